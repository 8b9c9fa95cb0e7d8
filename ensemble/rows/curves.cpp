// Aggregation of member results into curve points: counts by regime and attractor, and D's replica
// statistics (ensemble/engine/replica_statistics.hpp), NaN only where no replica finished.
#include "ensemble/rows/curves.hpp"

#include "ensemble/engine/replica_statistics.hpp"

namespace rotorsweep::ensemble {

std::vector<CurvePoint> aggregate_curves(const std::vector<Member>& members,
                                         const std::vector<MemberResult>& results) {
  std::vector<CurvePoint> curves;
  for (std::size_t first = 0, group = 0; first < members.size(); first += group) {
    const Member& m = members[first];
    for (group = 1; first + group < members.size() && members[first + group].point == m.point;) ++group;
    CurvePoint point;
    point.index = m.point;
    point.rows = m.rows;
    point.rtol = m.rtol;
    point.A = m.A;
    point.g = m.g;
    point.kind = m.kind;
    point.noise = m.noise;
    point.offset = m.offset;
    point.members = group;
    for (std::size_t i = first; i < first + group; ++i) {
      const MemberResult& r = results[i];
      ++point.attractor_count[r.final_state.attractor];
      if (r.status != kernels::LaneStatus::ok) {
        ++point.failed;
        continue;
      }
      ++point.regime_count[std::size_t(r.regime)];
      point.unresolved += !r.dissipation_resolved();
      point.symmetry_limited += r.symmetry_limited;
      point.symmetry_held += r.symmetry_held;
      point.shadow_departed += r.shadow_departed;
    }
    const ReplicaStatistics d = replica_statistics(
        group, [&](std::size_t k) { return results[first + k].dissipation(); },
        [&](std::size_t k) { return results[first + k].status == kernels::LaneStatus::ok; });
    point.count = d.count;
    point.dissipation_mean = d.mean;
    point.dissipation_std = d.std;
    point.dissipation_sem = d.sem;
    point.dissipation_min = d.min;
    point.dissipation_max = d.max;
    point.dissipation_bias =
        replica_statistics(
            group, [&](std::size_t k) { return results[first + k].dissipation_error(); },
            [&](std::size_t k) { return results[first + k].status == kernels::LaneStatus::ok; })
            .mean;
    curves.push_back(point);
  }
  return curves;
}

}  // namespace rotorsweep::ensemble
