// Chamber raster: critical points per cell (OpenMP), then 4-neighbour connected components of equal
// Morse signature (zones) and of equal signature and alignment (chambers) by union-find.
#include "landscape/chamber_map.hpp"

#include <algorithm>
#include <numbers>
#include <numeric>

#include "landscape/critical_points.hpp"

namespace rotorsweep::landscape {

namespace {

struct UnionFind {
  std::vector<std::int32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::int32_t find(std::int32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void join(std::int32_t a, std::int32_t b) { parent[find(a)] = find(b); }
};

/// Labels 0… for the components of cells that `same` connects; −1 for degenerate cells.
template <class Same>
int label_components(const ChamberMap& map, Same same, std::vector<std::int32_t>& label) {
  const int rows = map.grid.A_cells, cols = map.grid.tau_cells;
  UnionFind sets(map.cells.size());
  const auto usable = [&](int k) { return map.cells[k].degenerate == 0; };
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      const int k = i * cols + j;
      if (!usable(k)) continue;
      if (j + 1 < cols && usable(k + 1) && same(map.cells[k], map.cells[k + 1])) sets.join(k, k + 1);
      if (i + 1 < rows && usable(k + cols) && same(map.cells[k], map.cells[k + cols])) sets.join(k, k + cols);
    }
  label.assign(map.cells.size(), -1);
  std::vector<std::int32_t> root_label(map.cells.size(), -1);
  int count = 0;
  for (std::size_t k = 0; k < map.cells.size(); ++k) {
    if (!usable(int(k))) continue;
    auto& root = root_label[sets.find(std::int32_t(k))];
    if (root < 0) root = count++;
    label[k] = root;
  }
  return count;
}

int count_at_least(const std::vector<std::int32_t>& label, int components, int min_cells) {
  std::vector<int> size(components, 0);
  for (auto l : label)
    if (l >= 0) ++size[l];
  return int(std::count_if(size.begin(), size.end(), [&](int s) { return s >= min_cells; }));
}

}  // namespace

ChamberCell chamber_cell(double A, double tau, const TwoAngleCoefficients& k) {
  const auto set = critical_points({A, tau, k});
  ChamberCell cell;
  cell.minima = std::int8_t(set.minima);
  cell.saddles = std::int8_t(set.saddles);
  cell.maxima = std::int8_t(set.maxima);
  cell.degenerate = std::int8_t(set.degenerate);
  for (const auto& p : set.points)
    if (p.type != MorseType::degenerate) ++cell.by_type_and_class[int(p.type)][int(p.alignment)];
  return cell;
}

ChamberMap chamber_map(const ChamberGrid& grid, const std::function<void(int)>& rows_done) {
  ChamberMap map;
  map.grid = grid;
  for (int i = 0; i < grid.A_cells; ++i)
    map.A.push_back(grid.A_min + (i + 0.5) * (grid.A_max - grid.A_min) / grid.A_cells);
  for (int j = 0; j < grid.tau_cells; ++j)
    map.tau.push_back((j + 0.5) * 0.5 * std::numbers::pi / grid.tau_cells);
  map.cells.resize(std::size_t(grid.A_cells) * grid.tau_cells);
  int finished = 0;
#pragma omp parallel for schedule(dynamic, 1)
  for (int i = 0; i < grid.A_cells; ++i) {
    for (int j = 0; j < grid.tau_cells; ++j)
      map.cells[std::size_t(i) * grid.tau_cells + j] = chamber_cell(map.A[i], map.tau[j], grid.k);
#pragma omp critical(chamber_map_progress)
    {
      ++finished;
      if (rows_done) rows_done(finished);
    }
  }
  map.zones = label_components(
      map, [](const ChamberCell& a, const ChamberCell& b) { return a.same_morse_signature(b); }, map.zone);
  map.chambers = label_components(
      map, [](const ChamberCell& a, const ChamberCell& b) { return a == b; }, map.chamber);
  return map;
}

int ChamberMap::zones_at_least(int min_cells) const { return count_at_least(zone, zones, min_cells); }
int ChamberMap::chambers_at_least(int min_cells) const {
  return count_at_least(chamber, chambers, min_cells);
}

}  // namespace rotorsweep::landscape
