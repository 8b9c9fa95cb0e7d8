// Lattice sums of the point-dipole pair energy over the partners of a row (docs/model.md §8); an
// infinite row is summed to |k| = 10⁶ with the k⁻³ tails of b and c added in closed form, and rows
// u ≥ 7 apart take the sums' exact value 1/u² (Poisson summation).
#include "ensemble/rows/coupling_table.hpp"

#include <cmath>

namespace rotorsweep::ensemble {

namespace {

/// The terms of one pair offset by (k, u): its cos(θ1 − θ2) and cos(θ1 + θ2) coefficients.
struct PairTerms {
  double same, opposite;
};

PairTerms pair_terms(double k, double u) {
  const double r2 = k * k + u * u;
  const double inverse_cube = 1.0 / (r2 * std::sqrt(r2));
  const double axial = 1.5 * k * k / r2;
  return {inverse_cube * (1.0 - axial), inverse_cube * axial};
}

/// Offsets |k| summed directly for an infinite row; beyond, the terms are −1/(2k³) and 3/(2k³)
/// to O(u²/k⁵), summed as Σ_{k>K} k⁻³ ≈ 1/(2K²) − 1/(2K³) + 1/(4K⁴).
constexpr double direct_offsets = 1e6;

double cube_tail(double K) { return 1.0 / (2 * K * K) - 1.0 / (2 * K * K * K) + 1.0 / (4 * K * K * K * K); }

/// From this row distance on, an infinite row's b_u and c_u are 1/u²: by Poisson summation the sums
/// over k equal their integrals (∫ r⁻³ (1 − 3k²/2r²) dk = ∫ r⁻³ 3k²/2r² dk = 1/u²) up to terms of
/// relative size ~ u e^{−2πu}, below 1e-17 at u = 7; the direct sums agree to their rounding.
constexpr std::size_t line_limit_rows = 7;

}  // namespace

CouplingTable nearest_neighbour_table() { return {}; }

CouplingTable dipolar_table(std::size_t range, std::size_t row_length,
                            const std::function<void(std::size_t)>& progress) {
  CouplingTable table;
  table.b.assign(range, 0.0);
  table.c.assign(range, 0.0);
  const bool infinite = row_length == 0;
  const double L = double(row_length);
  const double last = infinite ? direct_offsets : L - 1;
  const auto weight = [&](double k) { return infinite ? 1.0 : (L - k) / L; };
  // a: the −(3/2) k⁻³ cos 2θ part of the intra-row pairs, one side (each pair once per rotor)
  table.a = 0;
  for (double k = last; k >= 1; --k) table.a += weight(k) * 1.5 / (k * k * k);
  if (infinite) table.a += 1.5 * cube_tail(direct_offsets);
  for (std::size_t u = 1; u <= range; ++u) {
    if (infinite && u >= line_limit_rows) {
      table.b[u - 1] = table.c[u - 1] = 1.0 / (double(u) * double(u));
      if (progress) progress(u);
      continue;
    }
    double same = 0, opposite = 0;
    for (double k = last; k >= 1; --k) {  // smallest terms first
      const auto t = pair_terms(k, double(u));
      same += 2 * weight(k) * t.same;
      opposite += 2 * weight(k) * t.opposite;
    }
    const auto centre = pair_terms(0, double(u));
    same += centre.same;
    if (infinite) {
      same -= 2 * 0.5 * cube_tail(direct_offsets);
      opposite += 2 * 1.5 * cube_tail(direct_offsets);
    }
    table.b[u - 1] = same;
    table.c[u - 1] = opposite;
    if (progress) progress(u);
  }
  return table;
}

CouplingTable RowCouplings::for_rows(std::size_t rows) const {
  CouplingTable out;
  switch (kind) {
    case Kind::nearest: out = nearest_neighbour_table(); break;
    case Kind::table: out = table; break;
    case Kind::dipolar: out = dipolar_table(all_rows ? largest_range(rows, open) : range, row_length); break;
  }
  if (kind != Kind::nearest && !open && 2 * out.range() == rows) {
    out.b.back() *= 0.5;
    out.c.back() *= 0.5;
  }
  return out;
}

TwoAngleCoefficients two_angle_coefficients(const CouplingTable& table) {
  TwoAngleCoefficients out{table.a, 0.0, 0.0};
  for (std::size_t u = 1; u <= table.range(); ++u) {
    if (u % 2 == 0) {
      out.a += table.c[u - 1];
    } else {
      out.b += 2 * table.b[u - 1];
      out.c += 2 * table.c[u - 1];
    }
  }
  return out;
}

double lattice_energy_per_moment(std::size_t half_width, bool antiferromagnetic) {
  const long M = long(half_width);
  double sum = 0;
  for (long u = -M; u <= M; ++u)
    for (long k = -M; k <= M; ++k) {
      if (k == 0 && u == 0) continue;
      // both moments along the rows (θ1 = θ2 = 0, or π apart for rows of odd distance)
      const auto t = pair_terms(double(k), double(u));
      const double sign = antiferromagnetic && (u % 2 != 0) ? -1.0 : 1.0;
      sum += sign * (t.same - t.opposite);
    }
  return sum;
}

}  // namespace rotorsweep::ensemble
