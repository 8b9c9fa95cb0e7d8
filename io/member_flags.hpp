// What a result file's members warn of (docs/cli.md "Running a sweep"): members that did not finish, and of
// those that did, whose D is not resolved for each reason apart: its error above 0.1 |D|, D decided
// by an asymmetry below the tolerance (symmetry_limited, symmetry_held), a shadow run that departed (shadow_departed); and CP
// members whose slips could not be told jumps or smooth (slip_jumps NaN).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "io/hdf5_file.hpp"

namespace rotorsweep::io {

struct MemberFlagCounts {
  std::map<std::string, std::size_t> failures;  ///< members that did not finish, by status
  /// finished members whose error is a bound but not below 0.1 |D| (neither of the two below)
  std::size_t unresolved = 0;
  std::size_t symmetry_limited = 0;  ///< finished members whose D an asymmetry below rtol decides
  std::size_t symmetry_held = 0;     ///< of those, members held on a symmetric set without slipping
  std::size_t shadow_departed = 0;   ///< finished members whose shadow run reached another attractor
  std::size_t untold = 0;  ///< finished CP members whose slips are not told jumps or smooth (slip_jumps NaN)
};

/// The counts over the rows of `members` (a /members group) marked in `done`, or over every row where
/// `done` is empty; read a block of rows at a time. Columns a file lacks count nothing.
inline MemberFlagCounts count_member_flags(const Hdf5Location& members, const std::vector<char>& done = {}) {
  const std::size_t rows = members.shape("status").first, block = 1 << 16;
  const auto column = [&](const char* name, std::size_t first, std::size_t count, std::int64_t absent) {
    return members.has(name) ? members.read_rows_integers(name, first, count)
                             : std::vector<std::int64_t>(count, absent);
  };
  MemberFlagCounts counts;
  for (std::size_t first = 0; first < rows; first += block) {
    const std::size_t count = std::min(block, rows - first);
    const auto status = members.read_rows_strings("status", first, count);
    const auto resolved = column("dissipation_resolved", first, count, 1);
    const auto limited = column("symmetry_limited", first, count, 0);
    const auto departed = column("shadow_departed", first, count, 0);
    const auto held = column("symmetry_held", first, count, 0);
    const bool kinds = members.has("slip_jumps");
    const auto regime = kinds ? members.read_rows_strings("regime", first, count) : std::vector<std::string>{};
    const auto jumps = kinds ? members.read_rows_doubles("slip_jumps", first, count) : std::vector<double>{};
    for (std::size_t i = 0; i < count; ++i) {
      if (!done.empty() && !done[first + i]) continue;
      if (status[i] != "ok") {
        ++counts.failures[status[i]];
        continue;
      }
      counts.symmetry_limited += limited[i] != 0;
      counts.symmetry_held += held[i] != 0;
      counts.shadow_departed += departed[i] != 0;
      counts.unresolved += resolved[i] == 0 && limited[i] == 0 && departed[i] == 0;
      counts.untold += kinds && regime[i] == "CP" && std::isnan(jumps[i]);
    }
  }
  return counts;
}

}  // namespace rotorsweep::io
