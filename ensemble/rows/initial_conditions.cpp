// Initial conditions of a member (model.md §2), drawn from its counter-based stream.
#include "ensemble/rows/initial_conditions.hpp"

#include <numbers>

#include "kernels/lanes/counter_random.hpp"

namespace rotorsweep::ensemble {

std::string_view kind_name(InitialKind kind) {
  switch (kind) {
    case InitialKind::fm: return "FM";
    case InitialKind::afm: return "AFM";
    case InitialKind::random: return "random";
    case InitialKind::exact: return "exact";
  }
  return "?";
}

std::optional<InitialKind> parse_kind(std::string_view name) {
  for (auto kind : {InitialKind::fm, InitialKind::afm, InitialKind::random, InitialKind::exact})
    if (kind_name(kind) == name) return kind;
  return std::nullopt;
}

std::vector<double> initial_angles(const InitialCondition& ic, std::size_t rows, std::uint64_t seed,
                                   std::uint64_t member) {
  const kernels::RandomStream stream(seed, member);
  constexpr double pi = std::numbers::pi;
  std::vector<double> theta(rows);
  for (std::size_t j = 0; j < rows; ++j) {
    const double u = stream.draw(j);
    switch (ic.kind) {
      case InitialKind::fm: theta[j] = ic.offset + ic.noise * (2 * u - 1); break;
      case InitialKind::afm: theta[j] = ic.offset + pi * double(j % 2) + ic.noise * (2 * u - 1); break;
      case InitialKind::random: theta[j] = 2 * pi * u; break;
      case InitialKind::exact: theta[j] = ic.exact_angles.at(j % ic.exact_angles.size()); break;
    }
  }
  return theta;
}

}  // namespace rotorsweep::ensemble
