// The substrate field along each slider row (or each rotor's path) as piecewise quintic Hermite polynomials
// in x (docs/model.md §9 "Substrate field"): built once per separation from the direct sum, read per rotor.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <type_traits>
#include <vector>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/models/slider/substrate_field.hpp"

namespace rotorsweep::kernels {

/// B_∥ (B_x unless the slider is turned) and B_z with their first two x-derivatives at a point of a
/// track (per lane).
template <class V = double>
struct TrackField {
  V bx, bz;      ///< field
  V dbx, dbz;    ///< ∂/∂x
  V d2bx, d2bz;  ///< ∂²/∂x²
};

/// A read-only view of a table: for each track and each interval [x_begin + i·dx, x_begin + (i+1)·dx],
/// six polynomial coefficients in the local coordinate s ∈ [0, 1] for B_∥, then six for B_z; track t's
/// start `track_stride` coefficients after track t − 1's (0: one track serves every track). Outside
/// [x_begin, x_end] the end intervals' polynomials extrapolate (the builder covers the whole path).
struct SubstrateTableView {
  const double* coefficients = nullptr;
  std::size_t tracks = 0;
  std::size_t intervals = 0;
  double x_begin = 0.0;
  double inv_dx = 1.0;
  std::size_t track_stride = 0;

  /// How many coefficients the table holds (twelve per interval and stored track).
  ROTORSWEEP_HD std::size_t coefficient_count() const { return (track_stride ? tracks : 1) * intervals * 12; }

  /// The coefficients of the interval holding x on `track`, and x's local coordinate s there.
  ROTORSWEEP_HD const double* interval(std::size_t track, double x, double& s) const {
    const double u = (x - x_begin) * inv_dx;
    double cell = std::floor(u);
    cell = cell < 0.0 ? 0.0 : (cell > double(intervals - 1) ? double(intervals - 1) : cell);
    s = u - cell;
    return coefficients + track * track_stride + std::size_t(cell) * 12;
  }
};

/// The field on `track` at x, lane l read from tables[l] at its own x: the coefficients gathered into
/// lanes once, the quintics evaluated in lanes (every lane holds the bits of a scalar evaluation). Without
/// `curvatures` the second derivatives are left 0 (the others' bits are the same either way).
template <class V>
ROTORSWEEP_HD TrackField<V> field_in_lanes(const SubstrateTableView* tables, std::size_t track, const V& x,
                                           bool curvatures = true) {
  constexpr std::size_t width = lane_width<V>;
  const auto xs = lane_values(x);
  std::array<const double*, width> c;
  std::array<double, width> s, inv_dx;
  for (std::size_t l = 0; l < width; ++l) {
    c[l] = tables[l].interval(track, xs[l], s[l]);
    inv_dx[l] = tables[l].inv_dx;
  }
  const V local = lane_from<V>([&](std::size_t l) { return s[l]; });
  const V scale = lane_from<V>([&](std::size_t l) { return inv_dx[l]; });
  // Horner's rule for p, p' and p'' of the quintic whose coefficients start at `first`
  const auto horner = [&](std::size_t first, V& p, V& dp, V& d2p) {
    p = lane_from<V>([&](std::size_t l) { return c[l][first + 5]; });
    dp = V(0.0);
    d2p = V(0.0);
    for (std::size_t i = 5; i-- > 0;) {
      if (curvatures) d2p = d2p * local + V(2.0) * dp;
      dp = dp * local + p;
      p = p * local + lane_from<V>([&](std::size_t l) { return c[l][first + i]; });
    }
  };
  TrackField<V> f;
  horner(0, f.bx, f.dbx, f.d2bx);
  horner(6, f.bz, f.dbz, f.d2bz);
  f.dbx *= scale;
  f.dbz *= scale;
  if (curvatures) {
    f.d2bx *= scale * scale;
    f.d2bz *= scale * scale;
  }
  return f;
}

/// Thrown by a SubstrateTable whose build was asked to stop (its `stopped` returned true).
struct SubstrateTableStopped {};

/// A track's field at a table node: B_∥ (along the rotors' in-plane axis) and B_z with their first two
/// x-derivatives.
struct TableNode {
  FieldJet<> along, z;
};

/// The table of one separation: B_∥, the field along the rotors' in-plane axis (cos τ, sin τ, 0) for a
/// slider turned by τ = tilt (B_x at τ = 0), and B_z along tracks at y = track_y[t] (units of a; a slider's
/// rows, or each rotor's path when the slider is turned), x over [x_begin, x_end] in intervals of at most
/// `dx`. Each interval's quintic matches the nodes' value, slope and curvature at both ends, so the field
/// is C² and its error falls as dx⁶. The nodes come from the direct sum over the lattice's moments here,
/// lane_width<V> nodes at once (V of the type_identity argument; every V gives the same table), or from
/// elsewhere (box sums, the infinite lattice's series: the node constructor); `stopped`, where given, is
/// asked before each block of nodes, and the build ends with SubstrateTableStopped once it says true.
class SubstrateTable {
 public:
  template <class V = double>
  SubstrateTable(const SubstrateLattice& lattice, const std::vector<double>& track_y, double x_begin,
                 double x_end, double dx, double tilt = 0.0, std::type_identity<V> = {},
                 const std::function<bool()>& stopped = {})
      : SubstrateTable(track_y.size(), intervals_over(x_begin, x_end, dx), x_begin,
                       (x_end - x_begin) / double(intervals_over(x_begin, x_end, dx)),
                       [&](std::size_t track, std::vector<TableNode>& nodes) {
                         direct_nodes<V>(lattice, track_y[track], x_begin,
                                         (x_end - x_begin) / double(intervals_over(x_begin, x_end, dx)), tilt,
                                         stopped, nodes);
                       }) {}

  /// From nodes at x_begin + i·step, i ≤ intervals: `track_nodes(track, nodes)` fills a track's (nodes has
  /// intervals + 1 places). With `shared`, one track (track 0's nodes) serves `tracks` tracks.
  template <class TrackNodes>
  SubstrateTable(std::size_t tracks, std::size_t intervals, double x_begin, double step,
                 TrackNodes&& track_nodes, bool shared = false)
      : intervals_(intervals), tracks_(tracks), shared_(shared), x_begin_(x_begin), inv_dx_(1.0 / step) {
    const std::size_t stored = shared ? 1 : tracks;
    coefficients_.resize(stored * intervals_ * 12);
    std::vector<TableNode> nodes(intervals_ + 1);
    for (std::size_t track = 0; track < stored; ++track) {
      track_nodes(track, nodes);
      for (std::size_t i = 0; i < intervals_; ++i) {
        double* coefficients = coefficients_.data() + (track * intervals_ + i) * 12;
        fit(nodes[i].along, nodes[i + 1].along, step, coefficients);
        fit(nodes[i].z, nodes[i + 1].z, step, coefficients + 6);
      }
    }
  }

  /// The intervals of at most dx over [x_begin, x_end].
  static std::size_t intervals_over(double x_begin, double x_end, double dx) {
    const auto intervals = std::size_t(std::ceil((x_end - x_begin) / dx - 1e-9));
    return intervals == 0 ? 1 : intervals;
  }

  SubstrateTableView view() const {
    return {coefficients_.data(), tracks_, intervals_, x_begin_, inv_dx_, shared_ ? 0 : intervals_ * 12};
  }

 private:
  /// A track's nodes by the direct sum, lane_width<V> at once.
  template <class V>
  static void direct_nodes(const SubstrateLattice& lattice, double track_y, double x_begin, double step,
                           double tilt, const std::function<bool()>& stopped, std::vector<TableNode>& nodes) {
    constexpr std::size_t width = lane_width<V>;
    const std::size_t last = nodes.size() - 1;
    const V c(std::cos(tilt)), s(std::sin(tilt));
    const auto along_axis = [&](const FieldJet<V>& x, const FieldJet<V>& y) {
      if (tilt == 0.0) return x;
      return FieldJet<V>{c * x.value + s * y.value, c * x.slope + s * y.slope,
                         c * x.curvature + s * y.curvature};
    };
    for (std::size_t first = 0; first <= last; first += width) {
      if (stopped && stopped()) throw SubstrateTableStopped{};
      const auto node = [&](std::size_t l) { return std::min(first + l, last); };
      const auto field = substrate_field(
          lattice, lane_from<V>([&](std::size_t l) { return x_begin + double(node(l)) * step; }), track_y,
          tilt != 0.0);
      const auto jet = [](const FieldJet<V>& f) {
        return std::array{lane_values(f.value), lane_values(f.slope), lane_values(f.curvature)};
      };
      const auto x = jet(along_axis(field.x, field.y)), z = jet(field.z);
      for (std::size_t l = 0; l < width && first + l <= last; ++l)
        nodes[first + l] = {{x[0][l], x[1][l], x[2][l]}, {z[0][l], z[1][l], z[2][l]}};
    }
  }

  /// The quintic in s ∈ [0, 1] with the given value, slope and curvature (in x) at both ends. Every
  /// combination is a sum of products (a − b·c as a + (−b)·c, the same bits): GCC 12's vectoriser fuses an
  /// adjacent pair p + q, p − q of products into one vfmsubadd even under -ffp-contract=off.
  static void fit(const FieldJet<>& left, const FieldJet<>& right, double dx, double* c) {
    const double f0 = left.value, d0 = left.slope * dx, e0 = left.curvature * dx * dx;
    const double f1 = right.value, d1 = right.slope * dx, e1 = right.curvature * dx * dx;
    c[0] = f0;
    c[1] = d0;
    c[2] = 0.5 * e0;
    c[3] = -10.0 * f0 + -6.0 * d0 + -1.5 * e0 + 10.0 * f1 + -4.0 * d1 + 0.5 * e1;
    c[4] = 15.0 * f0 + 8.0 * d0 + 1.5 * e0 + -15.0 * f1 + 7.0 * d1 + -1.0 * e1;
    c[5] = -6.0 * f0 + -3.0 * d0 + -0.5 * e0 + 6.0 * f1 + -3.0 * d1 + 0.5 * e1;
  }

  std::vector<double> coefficients_;
  std::size_t intervals_;
  std::size_t tracks_;
  bool shared_ = false;  ///< one stored track serves every track
  double x_begin_;
  double inv_dx_ = 1.0;
};

}  // namespace rotorsweep::kernels
