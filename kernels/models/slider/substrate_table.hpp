// The substrate field along each slider row as piecewise quintic Hermite polynomials in x (docs/model.md
// §9 "Substrate field"): built once per separation from the direct sum, read per rotor and stage.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "kernels/lanes/host_device.hpp"
#include "kernels/models/slider/substrate_field.hpp"

namespace rotorsweep::kernels {

/// B_x and B_z with their first two x-derivatives at a point of a slider row.
struct RowField {
  double bx, bz;      ///< field
  double dbx, dbz;    ///< ∂/∂x
  double d2bx, d2bz;  ///< ∂²/∂x²
};

/// A read-only view of a table: for each row and each interval [x_begin + i·dx, x_begin + (i+1)·dx],
/// six polynomial coefficients in the local coordinate s ∈ [0, 1] for B_x, then six for B_z. Outside
/// [x_begin, x_end] the end intervals' polynomials extrapolate (the builder covers the whole path).
struct SubstrateTableView {
  const double* coefficients = nullptr;
  std::size_t rows = 0;
  std::size_t intervals = 0;
  double x_begin = 0.0;
  double inv_dx = 1.0;

  ROTORSWEEP_HD RowField at(std::size_t row, double x) const {
    const double u = (x - x_begin) * inv_dx;
    double cell = std::floor(u);
    cell = cell < 0.0 ? 0.0 : (cell > double(intervals - 1) ? double(intervals - 1) : cell);
    const double s = u - cell;
    const double* c = coefficients + (row * intervals + std::size_t(cell)) * 12;
    RowField f;
    horner(c, s, f.bx, f.dbx, f.d2bx);
    horner(c + 6, s, f.bz, f.dbz, f.d2bz);
    f.dbx *= inv_dx;
    f.dbz *= inv_dx;
    f.d2bx *= inv_dx * inv_dx;
    f.d2bz *= inv_dx * inv_dx;
    return f;
  }

 private:
  ROTORSWEEP_HD static void horner(const double* c, double s, double& p, double& dp, double& d2p) {
    p = c[5];
    dp = 0.0;
    d2p = 0.0;
    for (int i = 4; i >= 0; --i) {
      d2p = d2p * s + 2.0 * dp;
      dp = dp * s + p;
      p = p * s + c[i];
    }
  }
};

/// The table of one separation: rows at y = 0, 1, …, rows − 1 (the slider's rows, in units of a), x
/// over [x_begin, x_end] in intervals of at most `dx`. Each interval's quintic matches the direct sum's
/// value, slope and curvature at both ends, so the field is C² and its error falls as dx⁶.
class SubstrateTable {
 public:
  SubstrateTable(const SubstrateLattice& lattice, std::size_t rows, double x_begin, double x_end, double dx)
      : intervals_(std::size_t(std::ceil((x_end - x_begin) / dx - 1e-9))), rows_(rows), x_begin_(x_begin) {
    if (intervals_ == 0) intervals_ = 1;
    const double step = (x_end - x_begin) / double(intervals_);
    inv_dx_ = 1.0 / step;
    coefficients_.resize(rows * intervals_ * 12);
    std::vector<SubstrateFieldAt> nodes(intervals_ + 1);
    for (std::size_t row = 0; row < rows; ++row) {
      for (std::size_t i = 0; i <= intervals_; ++i)
        nodes[i] = substrate_field(lattice, x_begin + double(i) * step, double(row));
      for (std::size_t i = 0; i < intervals_; ++i) {
        double* c = coefficients_.data() + (row * intervals_ + i) * 12;
        fit(nodes[i].x, nodes[i + 1].x, step, c);
        fit(nodes[i].z, nodes[i + 1].z, step, c + 6);
      }
    }
  }

  SubstrateTableView view() const { return {coefficients_.data(), rows_, intervals_, x_begin_, inv_dx_}; }

 private:
  /// The quintic in s ∈ [0, 1] with the given value, slope and curvature (in x) at both ends.
  static void fit(const FieldJet& left, const FieldJet& right, double dx, double* c) {
    const double f0 = left.value, d0 = left.slope * dx, e0 = left.curvature * dx * dx;
    const double f1 = right.value, d1 = right.slope * dx, e1 = right.curvature * dx * dx;
    c[0] = f0;
    c[1] = d0;
    c[2] = 0.5 * e0;
    c[3] = -10.0 * f0 - 6.0 * d0 - 1.5 * e0 + 10.0 * f1 - 4.0 * d1 + 0.5 * e1;
    c[4] = 15.0 * f0 + 8.0 * d0 + 1.5 * e0 - 15.0 * f1 + 7.0 * d1 - e1;
    c[5] = -6.0 * f0 - 3.0 * d0 - 0.5 * e0 + 6.0 * f1 - 3.0 * d1 + 0.5 * e1;
  }

  std::vector<double> coefficients_;
  std::size_t intervals_;
  std::size_t rows_;
  double x_begin_;
  double inv_dx_ = 1.0;
};

}  // namespace rotorsweep::kernels
