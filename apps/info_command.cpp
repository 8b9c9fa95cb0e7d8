// `rotorsweep info OUT.h5`: a human summary of a result file (provenance, completeness, the grid,
// status and regime counts, the range of the dissipation), of a `landscape` file or of a slider scan.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <set>
#include <tuple>
#include <vector>

#include "commands.hpp"
#include "io/hdf5_file.hpp"
#include "io/result_reader.hpp"
#include "io/member_flags.hpp"
#include "progress_line.hpp"

namespace rotorsweep::apps {

namespace {

void print_counts(const char* title, const std::vector<std::string>& labels) {
  std::map<std::string, std::size_t> counts;
  for (const auto& l : labels) ++counts[l];
  std::printf("%-12s", title);
  for (const auto& [label, count] : counts) std::printf(" %s %zu", label.c_str(), count);
  std::printf("\n");
}

void print_range(const char* title, const std::vector<double>& values) {
  const std::set<double> distinct(values.begin(), values.end());
  if (distinct.empty()) return;
  if (distinct.size() == 1)
    std::printf("%-12s %g\n", title, *distinct.begin());
  else
    std::printf("%-12s %zu values from %g to %g\n", title, distinct.size(), *distinct.begin(),
                *distinct.rbegin());
}

/// A file of `rotorsweep landscape …`: its kind, closed forms and counts, and its datasets.
void print_landscape(const io::Hdf5Location& file) {
  std::printf("%-12s %s\n", "kind", file.attribute_string("kind").c_str());
  if (file.has_attribute("wall_seconds"))
    std::printf("%-12s %.2f s\n", "wall time", file.attribute_double("wall_seconds"));
  for (const char* name : {"A_minus", "A_star", "J_at_A_minus", "zones", "chambers"})
    if (file.has_attribute(name)) std::printf("%-12s %.16g\n", name, file.attribute_double(name));
  std::printf("%-12s", "datasets");
  for (const auto& name : file.members()) std::printf(" %s", name.c_str());
  std::printf("\n");
}

/// A file of `rotorsweep slider`: the scan, the status counts, the friction's range and peak; of a scan
/// that stopped early only the rows marked done (the others hold nothing yet), and how many they are.
void print_slider(const io::Hdf5Location& file, bool complete) {
  const auto members = file.open_group("members");
  const auto all = members.read_doubles("separation");
  std::vector<signed char> done(all.size(), 1);
  if (members.has("done")) done = members.read_flags("done");
  const auto kept = [&](auto values) {
    decltype(values) out;
    for (std::size_t i = 0; i < values.size(); ++i)
      if (done[i]) out.push_back(values[i]);
    return out;
  };
  const auto separation = kept(all);
  std::printf("%-12s %zu\n", "members", all.size());
  if (!complete)
    std::printf(
        "%-12s %zu of %zu members done by a scan that stopped early (continue it with slider --resume)\n",
        "partial", separation.size(), all.size());
  // the speed and damping axes (files before them have neither column)
  for (const auto& [column, label, scale] :
       {std::tuple{"speed", "v (mm/s)", 1e3}, std::tuple{"damping", "damping", 1.0}})
    if (members.has(column)) {
      std::vector<double> values = kept(members.read_doubles(column));
      for (double& v : values) v *= scale;
      print_range(label, values);
    }
  std::vector<double> millimetres;
  for (double h : separation) millimetres.push_back(h * 1e3);
  print_range("h (mm)", millimetres);
  print_counts("status", kept(members.read_strings("status")));
  const auto friction = kept(members.read_doubles("friction"));
  std::size_t peak = friction.size();
  for (std::size_t i = 0; i < friction.size(); ++i)
    if (std::isfinite(friction[i]) && (peak == friction.size() || friction[i] > friction[peak])) peak = i;
  if (peak < friction.size()) {
    const auto least = std::min_element(friction.begin(), friction.end(), [](double a, double b) {
      return std::isfinite(a) && (!std::isfinite(b) || a < b);
    });
    std::printf("%-12s from %.6g N to %.6g N (peak at h = %.4g mm)\n", "friction", *least, friction[peak],
                millimetres[peak]);
  }
}

}  // namespace

int run_info(const InfoOptions& options) {
  try {
    const auto file = io::Hdf5Location::open_file(options.file);
    if (!io::is_rotorsweep_file(file))
      throw std::runtime_error("'" + options.file + "' is not a rotorsweep file (" +
                               io::rotorsweep_file_shape + ")");
    const bool complete = file.has_attribute("complete") && file.attribute_flag("complete");
    std::printf("%-12s %s%s\n", "file", options.file.c_str(),
                complete ? "" : "  (INCOMPLETE: the run did not finish; do not trust it)");
    if (file.has_attribute("version"))
      std::printf("%-12s rotorsweep %s (revision %s)\n", "written by",
                  file.attribute_string("version").c_str(), file.attribute_string("revision").c_str());
    if (file.has_attribute("scene_path"))
      std::printf("%-12s %s\n", "scene", file.attribute_string("scene_path").c_str());
    if (file.has_attribute("device") && file.has_attribute("isa"))
      std::printf("%-12s %s, instruction set%s %s\n", "ran on", file.attribute_string("device").c_str(),
                  file.attribute_string("isa").find(", ") == std::string::npos ? "" : "s",
                  file.attribute_string("isa").c_str());
    if (file.has_attribute("kind")) {
      print_landscape(file);
      if (file.attribute_string("kind") == "slider") print_slider(file, complete);
      if (options.scene && file.has_attribute("scene"))  // slider files store their scene too
        std::printf("\n# scene\n%s\n", file.attribute_string("scene").c_str());
      return complete ? 0 : 1;
    }
    if (!file.has("members")) return complete ? 0 : 1;
    const auto members = file.open_group("members");
    // rows not marked done (an unfinished run's) hold nothing yet: leave them out of every count
    std::vector<char> done;
    if (members.has("done"))
      for (auto flag : members.read_flags("done")) done.push_back(char(flag));
    std::size_t done_count = 0;
    for (char d : done) done_count += d != 0;
    const auto kept = [&](auto values) {
      if (done.empty()) return values;
      decltype(values) out;
      for (std::size_t i = 0; i < values.size(); ++i)
        if (done[i]) out.push_back(values[i]);
      return out;
    };
    const auto A = kept(members.read_doubles("A"));
    std::printf("%-12s %zu\n", "members", done.empty() ? A.size() : done.size());
    if (!complete && !done.empty())
      std::printf(
          "%-12s %zu of %zu members done by a run that stopped early (continue it with run --resume)\n",
          "partial", done_count, done.size());
    if (file.has_attribute("shard_index"))
      std::printf("%-12s %lld/%lld of a plan of %lld members (join the shards with rotorsweep merge)\n",
                  "shard", (long long)file.attribute_double("shard_index"),
                  (long long)file.attribute_double("shard_count"),
                  (long long)file.attribute_double("plan_members"));
    if (file.has_attribute("wall_seconds"))
      std::printf("%-12s %.2f s on %lld threads × %lld lanes (%s, lane occupancy %.1f %%)\n", "wall time",
                  file.attribute_double("wall_seconds"), (long long)file.attribute_double("threads"),
                  (long long)file.attribute_double("lane_width"),
                  members_per_second(double(A.size()), file.attribute_double("wall_seconds")).c_str(),
                  100 * file.attribute_double("lane_occupancy"));
    const auto rows = kept(members.read_integers("rows"));
    print_range("rows N", std::vector<double>(rows.begin(), rows.end()));
    if (members.has("rtol")) print_range("rtol", kept(members.read_doubles("rtol")));
    print_range("A", A);
    print_range("g", kept(members.read_doubles("g")));
    print_counts("initial", kept(members.read_strings("ic")));
    print_counts("status", kept(members.read_strings("status")));
    if (members.has("regime")) print_counts("regime", kept(members.read_strings("regime")));
    if (members.has("attractor")) print_counts("attractor", kept(members.read_strings("attractor")));
    if (members.has("dissipation")) {
      const auto D = kept(members.read_doubles("dissipation"));
      std::vector<double> finite, per_row;
      for (std::size_t i = 0; i < D.size(); ++i)
        if (std::isfinite(D[i])) {
          finite.push_back(D[i]);
          per_row.push_back(D[i] / double(rows[i]));
        }
      if (!finite.empty())
        std::printf("%-12s from %.6g to %.6g (per row D/N: %.6g to %.6g)\n", "D per period",
                    *std::min_element(finite.begin(), finite.end()),
                    *std::max_element(finite.begin(), finite.end()),
                    *std::min_element(per_row.begin(), per_row.end()),
                    *std::max_element(per_row.begin(), per_row.end()));
    }
    if (members.has("dissipation_resolved")) {
      const auto counts = io::count_member_flags(members, done);
      if (counts.unresolved > 0)
        std::printf("%-12s %zu members whose D is not resolved (dissipation_error >= 0.1 |D|)\n", "warning",
                    counts.unresolved);
      if (counts.symmetry_limited > 0)
        std::printf(
            "%-12s %zu members whose D an asymmetry below rtol decides (symmetry_limited, %zu of them "
            "held on a symmetric set: symmetry_held; no error bounds it, not counted as resolved)\n",
            "warning", counts.symmetry_limited, counts.symmetry_held);
      if (counts.shadow_departed > 0)
        std::printf(
            "%-12s %zu members whose shadow run reached another attractor (shadow_departed; no "
            "error estimate)\n",
            "warning", counts.shadow_departed);
    }
    std::printf("%-12s /members:", "datasets");
    for (const auto& name : members.members()) std::printf(" %s", name.c_str());
    std::printf("\n");
    if (options.scene && file.has_attribute("scene"))
      std::printf("\n# scene\n%s\n", file.attribute_string("scene").c_str());
    return complete ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace rotorsweep::apps
