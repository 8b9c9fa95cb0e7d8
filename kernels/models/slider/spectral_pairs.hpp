// The slider's pair sums (P c)_r, (Q s)_r as lattice convolutions (FFT above a few dozen rotors) and its
// stiffness K without a matrix, solved by conjugate gradients (docs/numerics.md "The full array at any
// size").
#pragma once

#include <cstddef>
#include <stdexcept>
#include <vector>

#include "kernels/lanes/lane_arena.hpp"
#include "kernels/linear/lattice_convolution.hpp"
#include "kernels/linear/spectral_stiffness.hpp"
#include "kernels/models/slider/slider_pairs.hpp"

namespace rotorsweep::kernels {

/// O(n log n) per evaluation and O(n) storage (host code: FFTW). P and Q are the two kernels of one
/// LatticeConvolution, so a lane block's cos θ and sin θ transform together; K's products reuse them
/// (SpectralStiffness). The sums cover every rotor at once (no range of a team).
template <class V>
class SpectralPairs {
 public:
  using Stiffness = SpectralStiffness<V>;
  static constexpr bool matrix_free = true;
  static std::size_t storage_size(const SliderGrid& grid) {
    return LatticeConvolution<V>::storage_size(grid.columns, grid.rows, 2);
  }

  SpectralPairs(const SliderGrid& grid, LaneArena<V>& arena)
      : rotors_(grid.rotors()), convolution_(grid.columns, grid.rows, 2, arena) {
    if (arena.counting()) return;
    std::vector<double> p(grid.offsets(), 0.0), q(grid.offsets(), 0.0);
    for_each_pair_coupling(grid, [&](std::size_t at, double pa, double qa) {
      p[at] = pa;
      q[at] = qa;
    });
    convolution_.set_kernel(0, p);
    convolution_.set_kernel(1, q);
  }

  /// (P c)_r and (Q s)_r of every rotor ([begin, end) must be all of them).
  void sums(const V* cos, const V* sin, V* p_cos, V* q_sin, std::size_t begin, std::size_t end) const {
    if (begin != 0 || end != rotors_) throw std::logic_error("spectral pair sums cover every rotor at once");
    const V* in[2] = {cos, sin};
    V* out[2] = {p_cos, q_sin};
    convolution_.apply(in, out);
  }

  const LatticeConvolution<V>& convolution() const { return convolution_; }

 private:
  std::size_t rotors_;
  LatticeConvolution<V> convolution_;
};

}  // namespace rotorsweep::kernels
