// Initial conditions of a member (model.md §2): FM, AFM, random, exact, each from the
// member's own counter-based stream, so that every member can be rebuilt on its own.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace rotorsweep::ensemble {

enum class InitialKind { fm, afm, random, exact };

std::string_view kind_name(InitialKind kind);

/// Whether a kind's start uses η and θ0 (initial.noise, initial.offset): FM and AFM do; random and
/// exact starts do not, so those axes do not multiply their members (docs/model.md §2).
constexpr bool kind_uses_noise(InitialKind kind) { return kind == InitialKind::fm || kind == InitialKind::afm; }
std::optional<InitialKind> parse_kind(std::string_view name);

struct InitialCondition {
  InitialKind kind = InitialKind::afm;
  double noise = 0.01;               ///< η: θ_j gets η_j ~ U[-η, η] (FM, AFM)
  double offset = 0.0;               ///< θ0 (FM, AFM)
  std::vector<double> exact_angles;  ///< θ_j for kind exact (repeated cyclically over the rows)
};

/// θ_j(0) for rows j = 0 .. rows-1 of member `member` under `seed`:
///   FM: θ0 + η_j;  AFM: θ0 + π (j mod 2) + η_j;  random: U[0, 2π);  exact: the given angles.
std::vector<double> initial_angles(const InitialCondition& ic, std::size_t rows, std::uint64_t seed,
                                   std::uint64_t member);

}  // namespace rotorsweep::ensemble
