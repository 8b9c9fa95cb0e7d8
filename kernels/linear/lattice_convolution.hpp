// Linear 2-D convolutions on a lattice with even kernels tabled per offset (docs/numerics.md "Pair sums by
// FFT"): out_k(p) = Σ_q kernel_k(p − q) in_k(q), by zero-padded FFTs (FFTW) or, on small lattices, directly.
#pragma once

#include <fftw3.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <mutex>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"

namespace rotorsweep::kernels {

/// The smallest 2^a 3^b 5^c 7^d at least `length`: a torus of 2n − 1 or more points holds every offset of n
/// lattice points either way, so a circular convolution there is the linear one on the lattice.
inline std::size_t smooth_length(std::size_t length) {
  for (std::size_t m = length > 1 ? length : 1;; ++m) {
    std::size_t rest = m;
    for (const std::size_t p : {2, 3, 5, 7})
      while (rest % p == 0) rest /= p;
    if (rest == 1) return m;
  }
}

/// FFTW plans of the batched 2-D real transforms of a rows × columns torus with `channels` transforms
/// interleaved (point p of channel c at p · channels + c), forward (real to half-complex) and inverse, made
/// once per process and shape (FFTW's planner is not thread-safe; executing a plan on new arrays is),
/// FFTW_ESTIMATE (every process plans alike, so the bits do not depend on timing), for 64-byte aligned arrays.
struct LatticeFftPlans {
  fftw_plan forward = nullptr, inverse = nullptr;
};
inline const LatticeFftPlans& lattice_fft_plans(std::size_t rows, std::size_t columns, std::size_t channels) {
  static std::mutex mutex;
  static std::map<std::tuple<std::size_t, std::size_t, std::size_t>, LatticeFftPlans> plans;
  const std::lock_guard<std::mutex> lock(mutex);
  LatticeFftPlans& found = plans[{rows, columns, channels}];
  if (found.forward) return found;
  const int n[2] = {int(rows), int(columns)};
  const std::size_t real = rows * columns * channels, complex = rows * (columns / 2 + 1) * channels;
  double* in = static_cast<double*>(fftw_malloc(sizeof(double) * real));
  fftw_complex* out = static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * complex));
  const int c = int(channels);
  found.forward = fftw_plan_many_dft_r2c(2, n, c, in, nullptr, c, 1, out, nullptr, c, 1, FFTW_ESTIMATE);
  found.inverse = fftw_plan_many_dft_c2r(2, n, c, out, nullptr, c, 1, in, nullptr, c, 1, FFTW_ESTIMATE);
  fftw_free(in);
  fftw_free(out);
  if (!found.forward || !found.inverse) throw std::runtime_error("FFTW could not plan a lattice transform");
  return found;
}

/// Up to `max_kernels` even kernels on a columns × rows lattice (point r = row · columns + column), each
/// tabled over the offsets (dx, dy), |dx| < columns, |dy| < rows, at (dy + rows − 1)(2 columns − 1) + dx +
/// columns − 1 (the value at offset 0 ignored), and the convolutions of lane fields with them.
///
/// On lattices of `direct_limit` points or fewer the sums run directly, each point's terms in ascending q;
/// above it by FFT on a padded torus (smooth_length(2n − 1) each way): the fields go in zero-padded, kernel k's
/// spectrum (real: the kernel is even) multiplies field k's, and the inverse transform gives every point's
/// sum at once, O(n log n) instead of O(n²), equal to the direct sums to rounding. Lanes are channels of one
/// batch of transforms (lane l of kernel k is channel k · width + l), so the lane block's fields transform
/// together. The spectra also bound the kernels' matrices on the lattice: each is a principal submatrix of
/// the torus's circulant, whose eigenvalues are the spectrum, so its eigenvalues lie in
/// [spectrum_min(k), spectrum_max(k)].
///
/// Host code (FFTW); storage from the arena, 64-byte aligned for FFTW's vector code.
template <class V>
class LatticeConvolution {
 public:
  static constexpr std::size_t max_kernels = 2;
  static constexpr std::size_t width = lane_width<V>;
  /// Lattices of this many points or fewer sum directly (docs/performance.md "The full array": the FFT's
  /// pair of transforms costs more than the n² terms below it).
  static constexpr std::size_t direct_limit = 36;

  struct Shape {
    std::size_t columns = 1, rows = 1, kernels = 1;
    std::size_t torus_columns = 1, torus_rows = 1;  ///< the padded torus (FFT only)
    bool fft = false;
    std::size_t points() const { return columns * rows; }
    std::size_t offsets() const { return (2 * columns - 1) * (2 * rows - 1); }
    std::size_t torus_points() const { return torus_columns * torus_rows; }
    std::size_t spectrum_points() const { return torus_rows * (torus_columns / 2 + 1); }
  };
  static Shape shape(std::size_t columns, std::size_t rows, std::size_t kernels) {
    Shape s{columns, rows, kernels, 1, 1, columns * rows > direct_limit};
    if (s.fft) {
      s.torus_columns = smooth_length(2 * columns - 1);
      s.torus_rows = smooth_length(2 * rows - 1);
    }
    return s;
  }

  static std::size_t storage_size(std::size_t columns, std::size_t rows, std::size_t kernels) {
    const Shape s = shape(columns, rows, kernels);
    std::size_t size = kernels * s.offsets();
    if (s.fft)
      size += aligned_count(s.torus_points() * kernels) + aligned_count(2 * s.spectrum_points() * kernels) +
              s.spectrum_points() * kernels;
    return size;
  }

  LatticeConvolution(std::size_t columns, std::size_t rows, std::size_t kernels, LaneArena<V>& arena)
      : shape_(shape(columns, rows, kernels)), tables_(arena.take(kernels * shape_.offsets())) {
    if (shape_.fft) {
      field_ = aligned_take(arena, shape_.torus_points() * kernels);
      spectrum_ = aligned_take(arena, 2 * shape_.spectrum_points() * kernels);
      symbols_ = arena.take(shape_.spectrum_points() * kernels);
      if (!arena.counting()) plans_ = &lattice_fft_plans(shape_.torus_rows, shape_.torus_columns, channels());
    }
  }

  const Shape& lattice() const { return shape_; }

  /// Kernel k from its offset table (the layout above; the value at offset 0 is taken as 0), and with an FFT
  /// its spectrum, the inverse transform's 1/(torus points) folded in.
  void set_kernel(std::size_t k, const std::vector<double>& table) {
    const std::size_t centre = (shape_.rows - 1) * (2 * shape_.columns - 1) + shape_.columns - 1;
    for (std::size_t i = 0; i < shape_.offsets(); ++i) tables_[k * shape_.offsets() + i] = V(i == centre ? 0.0 : table[i]);
    if (!shape_.fft) {
      torus_extremes(k);
      return;
    }
    clear_field();
    const std::size_t tc = shape_.torus_columns, tr = shape_.torus_rows;
    for (std::size_t j = 0; j < 2 * shape_.rows - 1; ++j)
      for (std::size_t i = 0; i < 2 * shape_.columns - 1; ++i) {
        const std::size_t y = (j + tr - (shape_.rows - 1)) % tr, x = (i + tc - (shape_.columns - 1)) % tc;
        for (std::size_t c = 0; c < shape_.kernels; ++c)
          field_[(y * tc + x) * shape_.kernels + c] = tables_[k * shape_.offsets() + j * (2 * shape_.columns - 1) + i];
      }
    fftw_execute_dft_r2c(plans_->forward, reinterpret_cast<double*>(field_),
                         reinterpret_cast<fftw_complex*>(spectrum_));
    const double scale = 1.0 / double(shape_.torus_points());
    double low = INFINITY, high = -INFINITY;
    for (std::size_t q = 0; q < shape_.spectrum_points(); ++q) {
      const double s = lane_get(spectrum_[2 * (q * shape_.kernels + k)], 0);  // the real part
      low = s < low ? s : low;
      high = s > high ? s : high;
      symbols_[k * shape_.spectrum_points() + q] = V(s * scale);
    }
    spectrum_min_[k] = low;
    spectrum_max_[k] = high;
  }
  /// Bounds of the eigenvalues of kernel k's matrix on the lattice: the extremes of its spectrum on the torus.
  double spectrum_min(std::size_t k) const { return spectrum_min_[k]; }
  double spectrum_max(std::size_t k) const { return spectrum_max_[k]; }

  /// Kernel k's offset table.
  ROTORSWEEP_HD const V* table(std::size_t k) const { return tables_ + k * shape_.offsets(); }

  /// out[k][p] = Σ_q kernel_k(p − q) in[k][q] at every lattice point p, for each kernel k.
  void apply(const V* const* in, V* const* out) const {
    if (!shape_.fft) {
      for (std::size_t k = 0; k < shape_.kernels; ++k) direct(table(k), in[k], out[k]);
      return;
    }
    clear_field();
    const std::size_t tc = shape_.torus_columns, nk = shape_.kernels;
    for (std::size_t j = 0, p = 0; j < shape_.rows; ++j)
      for (std::size_t i = 0; i < shape_.columns; ++i, ++p)
        for (std::size_t k = 0; k < nk; ++k) field_[(j * tc + i) * nk + k] = in[k][p];
    fftw_execute_dft_r2c(plans_->forward, reinterpret_cast<double*>(field_),
                         reinterpret_cast<fftw_complex*>(spectrum_));
    const std::size_t points = shape_.spectrum_points();
    for (std::size_t q = 0; q < points; ++q)
      for (std::size_t k = 0; k < nk; ++k) {
        const V s = symbols_[k * points + q];
        spectrum_[2 * (q * nk + k)] *= s;
        spectrum_[2 * (q * nk + k) + 1] *= s;
      }
    fftw_execute_dft_c2r(plans_->inverse, reinterpret_cast<fftw_complex*>(spectrum_),
                         reinterpret_cast<double*>(field_));
    for (std::size_t j = 0, p = 0; j < shape_.rows; ++j)
      for (std::size_t i = 0; i < shape_.columns; ++i, ++p)
        for (std::size_t k = 0; k < nk; ++k) out[k][p] = field_[(j * tc + i) * nk + k];
  }

  /// Σ_q kernel(p − q) x_q at lattice point p from the kernel's table, q in ascending order.
  ROTORSWEEP_HD V direct_at(const V* kernel, std::size_t p, const V* x) const {
    const std::size_t columns = shape_.columns, rows = shape_.rows, row_width = 2 * columns - 1;
    // the offset of q from p is (column(q) − column(p), row(q) − row(p)); the kernel is even
    const V* line = kernel + (rows - 1 - p / columns) * row_width + (columns - 1 - p % columns);
    V sum(0.0);
    for (std::size_t j = 0, q = 0; j < rows; ++j, line += row_width)
      for (std::size_t i = 0; i < columns; ++i, ++q) sum += line[i] * x[q];
    return sum;
  }

 private:
  std::size_t channels() const { return shape_.kernels * width; }
  static constexpr std::size_t alignment_values = 64 / sizeof(V) > 0 ? 64 / sizeof(V) : 1;
  static std::size_t aligned_count(std::size_t count) { return count + alignment_values; }
  /// `count` values from the arena, starting on a 64-byte boundary (the arena's storage is at least
  /// V-aligned).
  static V* aligned_take(LaneArena<V>& arena, std::size_t count) {
    V* piece = arena.take(aligned_count(count));
    if (!piece) return nullptr;
    const auto address = reinterpret_cast<std::uintptr_t>(piece);
    return piece + ((64 - address % 64) % 64) / sizeof(V);
  }
  void clear_field() const {
    for (std::size_t i = 0; i < shape_.torus_points() * shape_.kernels; ++i) field_[i] = V(0.0);
  }
  void direct(const V* kernel, const V* x, V* out) const {
    for (std::size_t p = 0; p < shape_.points(); ++p) out[p] = direct_at(kernel, p, x);
  }
  /// Without an FFT: kernel k's spectrum on the torus of smooth_length(2n − 1) points each way, summed
  /// directly (Σ_d kernel(d) cos(2π (u dx / columns' + v dy / rows')): an even kernel's is real).
  void torus_extremes(std::size_t k) {
    const std::size_t tc = smooth_length(2 * shape_.columns - 1), tr = smooth_length(2 * shape_.rows - 1);
    const double two_pi = 6.283185307179586;
    spectrum_min_[k] = INFINITY;
    spectrum_max_[k] = -INFINITY;
    for (std::size_t v = 0; v < tr; ++v)
      for (std::size_t u = 0; u < tc; ++u) {
        double s = 0;
        for (std::size_t j = 0; j < 2 * shape_.rows - 1; ++j)
          for (std::size_t i = 0; i < 2 * shape_.columns - 1; ++i) {
            const double dx = double(i) - double(shape_.columns - 1), dy = double(j) - double(shape_.rows - 1);
            s += lane_get(tables_[k * shape_.offsets() + j * (2 * shape_.columns - 1) + i], 0) *
                 std::cos(two_pi * (double(u) * dx / double(tc) + double(v) * dy / double(tr)));
          }
        spectrum_min_[k] = s < spectrum_min_[k] ? s : spectrum_min_[k];
        spectrum_max_[k] = s > spectrum_max_[k] ? s : spectrum_max_[k];
      }
  }

  Shape shape_;
  V* tables_;
  V* field_ = nullptr;     ///< the padded fields, kernels interleaved per point (then the sums)
  V* spectrum_ = nullptr;  ///< their transforms: per spectrum point and kernel, the real and imaginary parts
  V* symbols_ = nullptr;   ///< kernel k's spectrum / torus points at [k · spectrum points + q]
  const LatticeFftPlans* plans_ = nullptr;
  double spectrum_min_[max_kernels] = {}, spectrum_max_[max_kernels] = {};
};

}  // namespace rotorsweep::kernels
