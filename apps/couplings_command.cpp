// `rotorsweep couplings --range M [--row-length L]`: prints (and writes as CSV) the point-dipole
// coupling table a, b_u, c_u of docs/model.md §8 and its two-angle coefficients a_M, b_M, c_M.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <optional>
#include <string_view>

#include "commands.hpp"
#include "csv_output.hpp"
#include "ensemble/rows/coupling_table.hpp"
#include "io/output_target.hpp"
#include "progress_line.hpp"

namespace rotorsweep::apps {

namespace {

/// The CSV file's first line starts so: an existing file that does is replaced without --force.
constexpr std::string_view csv_signature = "# point-dipole couplings";

}  // namespace

std::size_t row_length_value(const std::string& text) { return text == "infinite" ? 0 : std::stoul(text); }

int run_couplings(const CouplingsOptions& options) {
  const std::size_t row_length = row_length_value(options.row_length);
  RemoveOnSignal on_signal;  // long tables of long rows take minutes: a signal ends them at once
  std::optional<io::OutputTarget> target;
  std::optional<RemoveOnSignal> removing;
  if (!take_csv_output(options.output, csv_signature, options.force, target, removing)) return 2;
  ProgressLine progress(options.range, true, "row distances");
  const auto table =
      ensemble::dipolar_table(options.range, row_length, [&](std::size_t u) { progress.update(u); });
  progress.finish();
  const auto reduced = ensemble::two_angle_coefficients(table);
  std::printf("point dipoles, rows %s, range %zu rows\n",
              row_length == 0 ? "infinite" : (std::to_string(row_length) + " rotors long").c_str(),
              options.range);
  std::printf("a = %.10f\n%4s %16s %16s\n", table.a, "u", "b_u", "c_u");
  for (std::size_t u = 1; u <= table.range(); ++u)
    std::printf("%4zu %16.10f %16.10f\n", u, table.b[u - 1], table.c[u - 1]);
  std::printf("two-angle (periodic rows): a_M = %.10f, b_M = %.10f, c_M = %.10f\n", reduced.a, reduced.b,
              reduced.c);
  if (!target) return 0;

  std::ofstream csv(target->temporary());
  csv << csv_signature << ", range " << options.range << ", row length " << options.row_length
      << "; a = " << table.a << "\nu,b,c\n";
  csv.precision(17);
  for (std::size_t u = 1; u <= table.range(); ++u)
    csv << u << "," << table.b[u - 1] << "," << table.c[u - 1] << "\n";
  csv.close();
  if (!csv) {
    std::cerr << "error: writing " << options.output << " failed: " << std::strerror(errno) << "\n";
    return 1;
  }
  removing.reset();
  target->claim_temporary();
  target->commit();
  std::printf("table written to %s%s\n", options.output.c_str(), target->replaced() ? " (replaced)" : "");
  return 0;
}

}  // namespace rotorsweep::apps
