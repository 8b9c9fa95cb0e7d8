// The lane arena (kernels/lanes/lane_arena.hpp): counting over null storage, and every kernel
// leaf's stated storage_size equal to what its constructor takes, for both lane types.
#include <catch2/catch.hpp>

#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/linear/cyclic_tridiagonal.hpp"
#include "kernels/linear/dense_symmetric.hpp"
#include "kernels/linear/diagonal_jacobian.hpp"
#include "kernels/linear/second_order_jacobian.hpp"
#include "kernels/models/rows/coupled_rows.hpp"
#include "kernels/models/rows/nearest_neighbour_rows.hpp"
#include "kernels/models/single_rotor.hpp"
#include "kernels/models/slider/slider_model.hpp"

using namespace rotorsweep::kernels;

namespace {

/// What `build(arena)` takes from an arena over real storage of `stated` values, which it must
/// fill exactly; and the same build counted over an arena without storage.
template <class V, class Build>
void check_takes(std::size_t stated, Build&& build) {
  lane_vector<V> storage(stated + 1);
  LaneArena<V> arena(storage.data(), stated);
  build(arena);
  CHECK(arena.used() == stated);
  CHECK(arena.fits());
  CHECK(counted_storage<V>(build) == stated);
}

template <class V>
void check_leaves() {
  for (std::size_t n : {2u, 3u, 20u, 64u}) {
    INFO("n = " << n);
    using Rows = NearestNeighbourRows<V>;
    check_takes<V>(Rows::storage_size(n), [&](LaneArena<V>& a) { const Rows m(n, a, all_integrals); });
    check_takes<V>(Rows::Workspace::storage_size(n),
                   [&](LaneArena<V>& a) { const typename Rows::Workspace w(n, a); });
    using Coupled = CoupledRows<V>;
    check_takes<V>(Coupled::storage_size(n), [&](LaneArena<V>& a) { const Coupled m(n, a, all_integrals); });
    check_takes<V>(Coupled::Workspace::storage_size(n),
                   [&](LaneArena<V>& a) { const typename Coupled::Workspace w(n, a); });
    check_takes<V>(CyclicTridiagonal<V>::storage_size(n),
                   [&](LaneArena<V>& a) { const CyclicTridiagonal<V> j(n, a); });
    check_takes<V>(DenseSymmetric<V>::storage_size(n),
                   [&](LaneArena<V>& a) { const DenseSymmetric<V> j(n, a); });
    check_takes<V>(DiagonalJacobian<V>::storage_size(n),
                   [&](LaneArena<V>& a) { const DiagonalJacobian<V> j(n, a); });
    check_takes<V>(SecondOrderJacobian<V, true>::storage_size(2 * n),
                   [&](LaneArena<V>& a) { const SecondOrderJacobian<V, true> j(2 * n, a); });
    check_takes<V>(SecondOrderJacobian<V, false>::storage_size(n),
                   [&](LaneArena<V>& a) { const SecondOrderJacobian<V, false> j(n, a); });
    check_takes<V>(SingleRotor<V>::storage_size(n), [&](LaneArena<V>& a) { const SingleRotor<V> m(n, a); });
  }
  for (const SliderGrid grid : {SliderGrid{3, 2}, SliderGrid{7, 7}}) {
    using Slider = SliderModel<V, true>;
    check_takes<V>(Slider::storage_size(grid),
                   [&](LaneArena<V>& a) { const Slider m(grid, SliderPlacement{}, a); });
    check_takes<V>(Slider::Workspace::storage_size(2 * grid.rotors()),
                   [&](LaneArena<V>& a) { const typename Slider::Workspace w(2 * grid.rotors(), a); });
  }
}

}  // namespace

TEST_CASE("an arena over null storage only counts", "[kernels][arena]") {
  LaneArena<double> counter(nullptr, 0);
  CHECK(counter.counting());
  CHECK(counter.take(5) == nullptr);
  CHECK(counter.take(7) == nullptr);
  CHECK(counter.used() == 12);
  CHECK_FALSE(counter.fits());
  double storage[4];
  LaneArena<double> small(storage, 4);
  CHECK_FALSE(small.counting());
  CHECK(small.take(3) == storage);
  CHECK(small.take(2) == nullptr);  // past the end
  CHECK_FALSE(small.fits());
}

TEST_CASE("every kernel leaf takes what its storage_size states", "[kernels][arena]") {
  check_leaves<double>();
  check_leaves<simd_lane>();
}
