// The finite substrate lattice's field at a table's nodes by box sums of running sums (docs/model.md §9
// "Substrate field"): exact lattice sums in O(nodes + moments) per node phase instead of O(nodes × moments).
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

#include "kernels/lanes/lane.hpp"
#include "kernels/models/slider/substrate_field.hpp"
#include "kernels/models/slider/substrate_table.hpp"

namespace rotorsweep::kernels {

/// The field of `lattice` (moments at (x_offset + k, y_offset + l, −depth), k < columns, l < rows) along
/// `tracks` unturned tracks at y = y_first + t, at the nodes x_begin + i/m, i ≤ intervals: nodes[t][i].
///
/// Nodes of one phase p (i ≡ p mod m) lie an integer apart, x = b + u with b = x_begin + p/m, and tracks an
/// integer apart, as the moments do, so the field at (u, t) is the sum of one moment's field g(a, c) =
/// G(b − x_offset + a, y_first − y_offset + c) over the box a ∈ [u − columns + 1, u], c ∈ [t − rows + 1,
/// t]. Per offset a the running sum of g over c gives each track's column sum H(a, t) as a difference of
/// two of them; per track the running sum of H over a gives each node's box the same way. Both running sums
/// are compensated (Kahan). So a phase evaluates one moment's field at (nodes + columns) × (tracks + rows)
/// offsets, lane_width<V> offsets a at once (every V gives the same bits), where the direct sum takes
/// columns × rows per node; the results are the direct sums' to rounding
/// (tests/kernels/models/slider/test_substrate_box_sums.cpp). `stopped`, where given, is asked before each
/// phase (SubstrateTableStopped).
template <class V = double>
std::vector<std::vector<TableNode>> box_sum_nodes(const SubstrateLattice& lattice, double y_first,
                                                  std::size_t tracks, double x_begin, std::size_t m,
                                                  std::size_t intervals,
                                                  const std::function<bool()>& stopped = {}) {
  constexpr std::size_t components = 6;  // B_x and B_z: value, slope, curvature
  constexpr std::size_t width_v = lane_width<V>;
  using Jets = std::array<double, components>;
  std::vector<std::vector<TableNode>> nodes(tracks, std::vector<TableNode>(intervals + 1));
  const std::size_t columns = lattice.columns, rows = lattice.rows;
  const bool turned = lattice.angle != 0.0;
  const std::size_t height = tracks + rows - 1;  // offsets c from −(rows − 1) to tracks − 1
  // compensated running sums: a sum and its carry per component
  struct Running {
    Jets sum{}, carry{};
    void add(const Jets& term) {
      for (std::size_t k = 0; k < components; ++k) {
        const double t = term[k] - carry[k], next = sum[k] + t;
        carry[k] = (next - sum[k]) - t;
        sum[k] = next;
      }
    }
  };
  std::vector<Running> column;        // per offset a: Σ over c so far
  std::vector<Jets> before, through;  // per (track, a): the column sums before c = t − rows + 1 and through t
  for (std::size_t p = 0; p < m && p <= intervals; ++p) {
    if (stopped && stopped()) throw SubstrateTableStopped{};
    const std::size_t count = (intervals - p) / m + 1;  // nodes u = 0 … count − 1 of this phase
    const std::size_t width = count + columns - 1;      // offsets a from −(columns − 1) to count − 1
    const double b = x_begin + double(p) / double(m) - lattice.x_offset;
    column.assign(width, Running{});
    before.assign(tracks * width, Jets{});
    through.assign(tracks * width, Jets{});
    for (std::size_t ic = 0; ic < height; ++ic) {
      const double Y = y_first - lattice.y_offset + (double(ic) - double(rows - 1));
      for (std::size_t ia = 0; ia < width; ia += width_v) {
        const V X = lane_from<V>(
            [&](std::size_t l) { return b + (double(std::min(ia + l, width - 1)) - double(columns - 1)); });
        SubstrateFieldAt<V> along_x, along_z;
        add_moment_field(X, Y, lattice.depth, turned, false, along_x, along_z);
        const SubstrateFieldAt<V> g = mixed_moment_field(lattice.angle, along_x, along_z);
        const std::array values{lane_values(g.x.value), lane_values(g.x.slope), lane_values(g.x.curvature),
                                lane_values(g.z.value), lane_values(g.z.slope), lane_values(g.z.curvature)};
        for (std::size_t l = 0; l < width_v && ia + l < width; ++l)
          column[ia + l].add(
              {values[0][l], values[1][l], values[2][l], values[3][l], values[4][l], values[5][l]});
      }
      // c = ic − (rows − 1): the sums through c close track c's column box, and open track c + rows's
      const std::ptrdiff_t c = std::ptrdiff_t(ic) - std::ptrdiff_t(rows - 1);
      if (c >= 0 && std::size_t(c) < tracks)
        for (std::size_t ia = 0; ia < width; ++ia) through[std::size_t(c) * width + ia] = column[ia].sum;
      if (c + std::ptrdiff_t(rows) < std::ptrdiff_t(tracks))
        for (std::size_t ia = 0; ia < width; ++ia)
          before[std::size_t(c + std::ptrdiff_t(rows)) * width + ia] = column[ia].sum;
    }
    for (std::size_t t = 0; t < tracks; ++t) {
      Running row;
      std::vector<Jets> upto(width);  // Σ over a' ≤ a of H(a', t)
      for (std::size_t ia = 0; ia < width; ++ia) {
        Jets h;
        for (std::size_t k = 0; k < components; ++k)
          h[k] = through[t * width + ia][k] - before[t * width + ia][k];
        row.add(h);
        upto[ia] = row.sum;
      }
      for (std::size_t u = 0; u < count; ++u) {
        Jets box;
        for (std::size_t k = 0; k < components; ++k)
          box[k] = upto[u + columns - 1][k] - (u > 0 ? upto[u - 1][k] : 0.0);
        nodes[t][p + u * m] = {{box[0], box[1], box[2]}, {box[3], box[4], box[5]}};
      }
    }
  }
  return nodes;
}

}  // namespace rotorsweep::kernels
