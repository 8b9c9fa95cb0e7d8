// Aggregation of member results into curve points; std is the population spread over the
// replicas that finished (0 for one replica), NaN statistics only where count = 0.
#include "ensemble/rows/curves.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rotorsweep::ensemble {

std::vector<CurvePoint> aggregate_curves(const std::vector<Member>& members,
                                         const std::vector<MemberResult>& results, int replicas) {
  std::vector<CurvePoint> curves;
  const std::size_t group = std::size_t(replicas);
  for (std::size_t first = 0; first + group <= members.size(); first += group) {
    const Member& m = members[first];
    CurvePoint point;
    point.rows = m.rows;
    point.rtol = m.rtol;
    point.A = m.A;
    point.g = m.g;
    point.kind = m.kind;
    point.noise = m.noise;
    point.offset = m.offset;
    point.members = group;
    double sum = 0;
    point.dissipation_min = std::numeric_limits<double>::infinity();
    point.dissipation_max = -std::numeric_limits<double>::infinity();
    for (std::size_t i = first; i < first + group; ++i) {
      const MemberResult& r = results[i];
      ++point.attractor_count[r.final_state.attractor];
      if (r.status != kernels::LaneStatus::ok) {
        ++point.failed;
        continue;
      }
      ++point.regime_count[std::size_t(r.regime)];
      ++point.count;
      point.unresolved += !r.dissipation_resolved();
      sum += r.dissipation();
      point.dissipation_min = std::min(point.dissipation_min, r.dissipation());
      point.dissipation_max = std::max(point.dissipation_max, r.dissipation());
    }
    if (point.count == 0) {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      point.dissipation_mean = point.dissipation_std = point.dissipation_min = point.dissipation_max = nan;
      point.dissipation_sem = nan;
    } else {
      point.dissipation_mean = sum / double(point.count);
      double spread = 0;
      for (std::size_t i = first; i < first + group; ++i)
        if (results[i].status == kernels::LaneStatus::ok)
          spread += std::pow(results[i].dissipation() - point.dissipation_mean, 2) / double(point.count);
      point.dissipation_std = std::sqrt(spread);
      const double n = double(point.count);
      point.dissipation_sem =
          n > 1 ? point.dissipation_std / std::sqrt(n - 1) : std::numeric_limits<double>::quiet_NaN();
    }
    curves.push_back(point);
  }
  return curves;
}

}  // namespace rotorsweep::ensemble
