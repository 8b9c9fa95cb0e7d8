// Realizations of quenched disorder: standard normal draws (RandomStream::normal) from the counter-
// based stream of (disorder seed, replica), or the scene's explicit per-row lists repeated over N.
#include "ensemble/rows/disorder.hpp"

#include "kernels/lanes/counter_random.hpp"

namespace rotorsweep::ensemble {

namespace {

/// σ ξ_j for quantity q, or the explicit list repeated, or nothing.
std::vector<double> deviations(double sigma, const std::vector<double>& explicit_rows, std::size_t rows,
                               std::size_t quantity, const kernels::RandomStream& stream) {
  std::vector<double> out;
  if (!explicit_rows.empty()) {
    for (std::size_t j = 0; j < rows; ++j) out.push_back(explicit_rows[j % explicit_rows.size()]);
  } else if (sigma > 0) {
    for (std::size_t j = 0; j < rows; ++j) out.push_back(sigma * stream.normal(3 * j + quantity));
  }
  return out;
}

}  // namespace

RowDeviations row_deviations(const Disorder& disorder, std::size_t rows, int replica) {
  const kernels::RandomStream stream(disorder.seed, std::uint64_t(replica));
  return {deviations(disorder.A, disorder.A_rows, rows, 0, stream),
          deviations(disorder.anisotropy, disorder.anisotropy_rows, rows, 1, stream),
          deviations(disorder.coupling, disorder.coupling_rows, rows, 2, stream)};
}

}  // namespace rotorsweep::ensemble
