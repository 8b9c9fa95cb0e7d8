// Linear 2-D convolutions on a lattice with even kernels tabled per offset (docs/numerics.md "Pair sums by
// FFT"): out_k(p) = Σ_q kernel_k(p − q) in_k(q), by zero-padded FFTs (FFTW) or, on small lattices, directly.
#pragma once

#include <fftw3.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <mutex>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"

namespace rotorsweep::kernels {

/// The torus length for a lattice line of n points: the power of two at least 2n − 1 (so a circular
/// convolution there is the linear one on the lattice: every offset either way fits), and at least 2 (a
/// half-complex transform of one point leaves its imaginary part unwritten). FFTW's estimated plans of
/// these lengths beat shorter 3 · 2^k ones (docs/performance.md "The full array at any size").
inline std::size_t torus_length(std::size_t n) {
  std::size_t power = 2;
  while (power < 2 * n - 1) power *= 2;
  return power;
}

/// FFTW plans (FFTW_ESTIMATE: every process plans alike, so the bits do not depend on timing) of the
/// separable transforms of `width` lane fields on a rows × columns torus whose first `lattice_rows` rows hold
/// the lattice (layout in LatticeConvolution), made once per process and shape: FFTW's planner is not
/// thread-safe, executing a plan on new arrays (of the planning arrays' 64-byte alignment) is.
struct LatticeFftPlans {
  fftw_plan rows_forward = nullptr;     ///< real to half-complex along x, the lattice's rows only
  fftw_plan columns_forward = nullptr;  ///< complex along y, in place, every column
  fftw_plan columns_inverse = nullptr;
  fftw_plan rows_inverse = nullptr;  ///< half-complex to real along x, the lattice's rows only
  fftw_plan full_forward = nullptr;  ///< a whole 2-D transform of one field (a kernel's spectrum)
};
inline const LatticeFftPlans& lattice_fft_plans(std::size_t rows, std::size_t columns,
                                                std::size_t lattice_rows, std::size_t width) {
  static std::mutex mutex;
  static std::map<std::tuple<std::size_t, std::size_t, std::size_t, std::size_t>, LatticeFftPlans> plans;
  const std::lock_guard<std::mutex> lock(mutex);
  LatticeFftPlans& found = plans[{rows, columns, lattice_rows, width}];
  if (found.rows_forward) return found;
  const int w = int(width), half = int(columns / 2 + 1), nc = int(columns);
  // planning arrays aligned as the arena's pieces are
  auto* in = static_cast<double*>(std::aligned_alloc(64, sizeof(double) * rows * columns * width + 64));
  auto* out = static_cast<fftw_complex*>(
      std::aligned_alloc(64, sizeof(fftw_complex) * rows * std::size_t(half) * width + 64));
  const fftw_iodim along_x{nc, w, w};
  const fftw_iodim along_y{int(rows), half * w, half * w};
  const fftw_iodim rows_forward[2] = {{int(lattice_rows), nc * w, half * w}, {w, 1, 1}};
  const fftw_iodim rows_inverse[2] = {{int(lattice_rows), half * w, nc * w}, {w, 1, 1}};
  const fftw_iodim columns_all{half * w, 1, 1};
  found.rows_forward = fftw_plan_guru_dft_r2c(1, &along_x, 2, rows_forward, in, out, FFTW_ESTIMATE);
  found.columns_forward =
      fftw_plan_guru_dft(1, &along_y, 1, &columns_all, out, out, FFTW_FORWARD, FFTW_ESTIMATE);
  found.columns_inverse =
      fftw_plan_guru_dft(1, &along_y, 1, &columns_all, out, out, FFTW_BACKWARD, FFTW_ESTIMATE);
  found.rows_inverse = fftw_plan_guru_dft_c2r(1, &along_x, 2, rows_inverse, out, in, FFTW_ESTIMATE);
  found.full_forward = fftw_plan_dft_r2c_2d(int(rows), nc, in, out, FFTW_ESTIMATE);
  std::free(in);
  std::free(out);
  if (!found.rows_forward || !found.columns_forward || !found.columns_inverse || !found.rows_inverse ||
      !found.full_forward)
    throw std::runtime_error("FFTW could not plan a lattice transform");
  return found;
}

/// Up to `max_kernels` even kernels on a columns × rows lattice (point p = row · columns + column), each
/// tabled over the offsets (dx, dy), |dx| < columns, |dy| < rows, at (dy + rows − 1)(2 columns − 1) + dx +
/// columns − 1 (the value at offset 0 taken as 0), and the convolutions of lane fields with them.
///
/// On lattices of `direct_limit` points or fewer the sums run directly, each point's terms in ascending q;
/// above it by FFT on a zero-padded torus (torus_length each way): the fields go in, kernel k's spectrum
/// (real: the kernel is even) multiplies field k's, and the inverse transform gives every point's sum at
/// once, O(n log n) instead of O(n²), equal to the direct sums to rounding. The 2-D transforms are
/// separable passes, pruned to the lattice: along x over the lattice's rows only (the others are zero on
/// the way in and not read on the way out), along y over every column. Each kernel's field has buffers of
/// its own, lane l at torus point (y, x) at double (y · torus columns + x) · width + l, so a lane block's
/// fields transform as one batch, and the kernels' convolutions can run on threads of their own (OpenMP
/// tasks: the same operations, so the same bits). The spectra also bound the kernels' matrices on
/// the lattice: each is a
/// principal submatrix of the torus's circulant, whose eigenvalues are the spectrum, so its eigenvalues
/// lie in [spectrum_min(k), spectrum_max(k)].
///
/// Host code (FFTW); storage from the arena, 64-byte aligned for FFTW's vector code.
template <class V>
class LatticeConvolution {
 public:
  static constexpr std::size_t max_kernels = 2;
  static constexpr std::size_t width = lane_width<V>;
  /// Lattices of this many points or fewer sum directly (docs/performance.md "The full array at any size":
  /// below it the n² terms cost less than the transforms).
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
      s.torus_columns = torus_length(columns);
      s.torus_rows = torus_length(rows);
    }
    return s;
  }

  static std::size_t storage_size(std::size_t columns, std::size_t rows, std::size_t kernels) {
    const Shape s = shape(columns, rows, kernels);
    std::size_t size = kernels * s.offsets();
    if (s.fft)
      size += kernels * (aligned_count(s.torus_points()) + aligned_count(2 * s.spectrum_points()) +
                         s.spectrum_points());
    return size;
  }

  LatticeConvolution(std::size_t columns, std::size_t rows, std::size_t kernels, LaneArena<V>& arena)
      : shape_(shape(columns, rows, kernels)), tables_(arena.take(kernels * shape_.offsets())) {
    if (!shape_.fft) return;
    for (std::size_t k = 0; k < kernels; ++k) {
      field_[k] = aligned_take(arena, shape_.torus_points());
      spectrum_[k] = aligned_take(arena, 2 * shape_.spectrum_points());
      symbols_[k] = arena.take(shape_.spectrum_points());
    }
    if (!arena.counting()) plans_ = &lattice_fft_plans(shape_.torus_rows, shape_.torus_columns, rows, width);
  }

  const Shape& lattice() const { return shape_; }

  /// Kernel k from its offset table (the layout above), and with an FFT its spectrum (the inverse
  /// transform's 1/(torus points) folded in); either way the bounds of its eigenvalues.
  void set_kernel(std::size_t k, const std::vector<double>& table) {
    const std::size_t centre = (shape_.rows - 1) * (2 * shape_.columns - 1) + shape_.columns - 1;
    for (std::size_t i = 0; i < shape_.offsets(); ++i)
      tables_[k * shape_.offsets() + i] = V(i == centre ? 0.0 : table[i]);
    const std::size_t tc = shape_.fft ? shape_.torus_columns : torus_length(shape_.columns);
    const std::size_t tr = shape_.fft ? shape_.torus_rows : torus_length(shape_.rows);
    const std::vector<double> spectrum = torus_spectrum(k, tr, tc);
    spectrum_min_[k] = INFINITY;
    spectrum_max_[k] = -INFINITY;
    for (const double s : spectrum) {
      spectrum_min_[k] = s < spectrum_min_[k] ? s : spectrum_min_[k];
      spectrum_max_[k] = s > spectrum_max_[k] ? s : spectrum_max_[k];
    }
    if (shape_.fft)
      for (std::size_t q = 0; q < shape_.spectrum_points(); ++q)
        symbols_[k][q] = V(spectrum[q] / double(shape_.torus_points()));
  }
  /// Bounds of the eigenvalues of kernel k's matrix on the lattice: the extremes of its spectrum on the
  /// torus.
  double spectrum_min(std::size_t k) const { return spectrum_min_[k]; }
  double spectrum_max(std::size_t k) const { return spectrum_max_[k]; }

  /// Kernel k's offset table.
  ROTORSWEEP_HD const V* table(std::size_t k) const { return tables_ + k * shape_.offsets(); }

  /// out[k][p] = Σ_q kernel_k(p − q) in[k][q] at every lattice point p, for each kernel k.
  void apply(const V* const* in, V* const* out) const {
    if (!shape_.fft) {
      for (std::size_t k = 0; k < shape_.kernels; ++k)
        for (std::size_t p = 0; p < shape_.points(); ++p) out[k][p] = direct_at(table(k), p, in[k]);
      return;
    }
    // every kernel but the first as an OpenMP task: a thread of the caller's team with no work of its own
    // (waiting at the team's end) takes it, else the caller runs it at the taskwait; the same bits either way
    for (std::size_t k = 1; k < shape_.kernels; ++k) {
#pragma omp task default(shared) firstprivate(k)
      convolve(k, in[k], out[k]);
    }
    convolve(0, in[0], out[0]);
#pragma omp taskwait
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
  static fftw_complex* complex(V* values) { return reinterpret_cast<fftw_complex*>(values); }

  /// Kernel k's convolution by FFT on its own buffers.
  void convolve(std::size_t k, const V* in, V* out) const {
    const std::size_t tc = shape_.torus_columns, half = tc / 2 + 1, sp = shape_.spectrum_points();
    V* field = field_[k];
    V* spectrum = spectrum_[k];
    // the lattice's rows, zero-padded along x (the other rows are not read)
    for (std::size_t j = 0, p = 0; j < shape_.rows; ++j) {
      V* row = field + j * tc;
      for (std::size_t i = 0; i < shape_.columns; ++i, ++p) row[i] = in[p];
      for (std::size_t i = shape_.columns; i < tc; ++i) row[i] = V(0.0);
    }
    fftw_execute_dft_r2c(plans_->rows_forward, reinterpret_cast<double*>(field), complex(spectrum));
    // the rows beyond the lattice's are zero before the transform along y
    for (std::size_t i = 2 * shape_.rows * half; i < 2 * sp; ++i) spectrum[i] = V(0.0);
    fftw_execute_dft(plans_->columns_forward, complex(spectrum), complex(spectrum));
    for (std::size_t q = 0; q < sp; ++q) {
      spectrum[2 * q] *= symbols_[k][q];
      spectrum[2 * q + 1] *= symbols_[k][q];
    }
    fftw_execute_dft(plans_->columns_inverse, complex(spectrum), complex(spectrum));
    fftw_execute_dft_c2r(plans_->rows_inverse, complex(spectrum), reinterpret_cast<double*>(field));
    for (std::size_t j = 0, p = 0; j < shape_.rows; ++j)
      for (std::size_t i = 0; i < shape_.columns; ++i, ++p) out[p] = field[j * tc + i];
  }

  /// Kernel k's spectrum on a tr × tc torus (its real half-spectrum, tr × (tc/2 + 1) values; an even
  /// kernel's is real): by FFT where this convolution has one, else summed directly.
  std::vector<double> torus_spectrum(std::size_t k, std::size_t tr, std::size_t tc) const {
    const std::size_t half = tc / 2 + 1, row_width = 2 * shape_.columns - 1;
    std::vector<double> spectrum(tr * half, 0.0);
    const auto value = [&](std::size_t j, std::size_t i) { return lane_get(table(k)[j * row_width + i], 0); };
    if (shape_.fft) {
      auto* in = static_cast<double*>(std::aligned_alloc(64, sizeof(double) * tr * tc + 64));
      auto* out = static_cast<fftw_complex*>(std::aligned_alloc(64, sizeof(fftw_complex) * tr * half + 64));
      for (std::size_t i = 0; i < tr * tc; ++i) in[i] = 0.0;
      for (std::size_t j = 0; j < 2 * shape_.rows - 1; ++j)
        for (std::size_t i = 0; i < row_width; ++i)
          in[((j + tr - (shape_.rows - 1)) % tr) * tc + (i + tc - (shape_.columns - 1)) % tc] = value(j, i);
      fftw_execute_dft_r2c(plans_->full_forward, in, out);
      for (std::size_t q = 0; q < tr * half; ++q) spectrum[q] = out[q][0];
      std::free(in);
      std::free(out);
      return spectrum;
    }
    const double two_pi = 6.283185307179586;
    for (std::size_t v = 0; v < tr; ++v)
      for (std::size_t u = 0; u < half; ++u)
        for (std::size_t j = 0; j < 2 * shape_.rows - 1; ++j)
          for (std::size_t i = 0; i < row_width; ++i) {
            const double dx = double(i) - double(shape_.columns - 1),
                         dy = double(j) - double(shape_.rows - 1);
            spectrum[v * half + u] +=
                value(j, i) * std::cos(two_pi * (double(u) * dx / double(tc) + double(v) * dy / double(tr)));
          }
    return spectrum;
  }

  Shape shape_;
  V* tables_;
  V* field_[max_kernels] = {};     ///< each kernel's padded field (then its sums)
  V* spectrum_[max_kernels] = {};  ///< its transform: per spectrum point, the real and imaginary parts
  V* symbols_[max_kernels] = {};   ///< each kernel's spectrum / torus points
  const LatticeFftPlans* plans_ = nullptr;
  double spectrum_min_[max_kernels] = {}, spectrum_max_[max_kernels] = {};
};

}  // namespace rotorsweep::kernels
