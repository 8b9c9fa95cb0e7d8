// Test support: whether two member results are the same bits (summaries, counts, final angles,
// period records, final state, the shadow's and the probe's D and flags, row profiles), for backend and lane-type
// agreement tests.
#pragma once

#include <cstring>
#include <string>
#include <vector>

#include "ensemble/rows/member_result.hpp"

namespace rotorsweep::testing {

inline bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// The first difference between two results, or "" when they have the same bits.
inline std::string result_difference(const ensemble::MemberResult& a, const ensemble::MemberResult& b) {
  if (a.index != b.index) return "index";
  if (a.status != b.status) return "status";
  if (a.settled != b.settled || a.periods_run != b.periods_run) return "settled or periods_run";
  if (!same_bits(a.steps_accepted, b.steps_accepted) || !same_bits(a.steps_rejected, b.steps_rejected))
    return "step counts " + std::to_string(a.steps_accepted) + " vs " + std::to_string(b.steps_accepted);
  if (a.regime != b.regime) return "regime";
  for (std::size_t c = 0; c < a.summaries.size(); ++c)
    for (std::size_t s = 0; s < a.summaries[c].size(); ++s)
      if (!same_bits(a.summaries[c][s], b.summaries[c][s]))
        return "summary of channel " + std::to_string(c) + ": " + std::to_string(a.summaries[c][s]) + " vs " +
               std::to_string(b.summaries[c][s]);
  if (a.theta_final.size() != b.theta_final.size()) return "theta_final size";
  for (std::size_t j = 0; j < a.theta_final.size(); ++j)
    if (!same_bits(a.theta_final[j], b.theta_final[j])) return "theta_final[" + std::to_string(j) + "]";
  if (a.periods.size() != b.periods.size()) return "period records";
  for (std::size_t p = 0; p < a.periods.size(); ++p)
    for (std::size_t c = 0; c < a.periods[p].values.size(); ++c)
      if (!same_bits(a.periods[p].values[c], b.periods[p].values[c]))
        return "period record " + std::to_string(p);
  if (a.final_state.attractor != b.final_state.attractor) return "attractor";
  if (!same_bits(a.dissipation_shadow, b.dissipation_shadow)) return "dissipation_shadow";
  if (!same_bits(a.dissipation_probe, b.dissipation_probe)) return "dissipation_probe";
  if (a.symmetry_limited != b.symmetry_limited || a.symmetry_held != b.symmetry_held ||
      a.shadow_departed != b.shadow_departed)
    return "symmetry_limited, symmetry_held or shadow_departed";
  for (const auto profile :
       {&ensemble::MemberResult::row_dissipation, &ensemble::MemberResult::link_alignment}) {
    if ((a.*profile).size() != (b.*profile).size()) return "row profile size";
    for (std::size_t j = 0; j < (a.*profile).size(); ++j)
      if (!same_bits((a.*profile)[j], (b.*profile)[j])) return "row profile entry " + std::to_string(j);
  }
  return "";
}

/// Checks every pair of results in order; returns how many differ, printing the first.
inline std::size_t count_differences(const std::vector<ensemble::MemberResult>& a,
                                     const std::vector<ensemble::MemberResult>& b, std::string& first) {
  std::size_t differ = a.size() == b.size() ? 0 : 1;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) {
    const std::string d = result_difference(a[i], b[i]);
    if (d.empty()) continue;
    if (differ++ == 0) first = "member " + std::to_string(a[i].index) + ": " + d;
  }
  return differ;
}

}  // namespace rotorsweep::testing
