// Realizations of quenched disorder: standard normal draws by Box–Muller from the counter-based
// stream of (disorder seed, replica), or the scene's explicit per-row lists repeated over N.
#include "ensemble/disorder.hpp"

#include <cmath>

#include "ensemble/random_stream.hpp"

namespace rotorsweep::ensemble {

namespace {

/// σ ξ_j for quantity q, or the explicit list repeated, or nothing.
std::vector<double> deviations(double sigma, const std::vector<double>& explicit_rows, std::size_t rows,
                               std::size_t quantity, const RandomStream& stream) {
  std::vector<double> out;
  if (!explicit_rows.empty()) {
    for (std::size_t j = 0; j < rows; ++j) out.push_back(explicit_rows[j % explicit_rows.size()]);
  } else if (sigma > 0) {
    for (std::size_t j = 0; j < rows; ++j) {
      const std::uint64_t k = 2 * (3 * j + quantity);
      const double u1 = stream.draw(k), u2 = stream.draw(k + 1);
      const double xi = std::sqrt(-2.0 * std::log1p(-u1)) * std::cos(2.0 * M_PI * u2);
      out.push_back(sigma * xi);
    }
  }
  return out;
}

}  // namespace

RowDeviations row_deviations(const Disorder& disorder, std::size_t rows, int replica) {
  const RandomStream stream(disorder.seed, std::uint64_t(replica));
  return {deviations(disorder.A, disorder.A_rows, rows, 0, stream),
          deviations(disorder.anisotropy, disorder.anisotropy_rows, rows, 1, stream),
          deviations(disorder.coupling, disorder.coupling_rows, rows, 2, stream)};
}

}  // namespace rotorsweep::ensemble
