// Which register kernel (docs/architecture.md "Register kernels") runs a row scene's members on the GPU:
// the shapes a build compiled (lanes × slots, uniform or disordered rows); gpu_plan.hpp chooses among them.
#pragma once

#include <cstddef>
#include <span>

#include "kernels/models/rows/integrals.hpp"
#include "kernels/steppers/rosenbrock_tableaus.hpp"

namespace rotorsweep::ensemble {

/// What a register kernel carries: R and ρ̄'s integral, the default observables' quadratures; a shape
/// with every_quadrature carries any of them (W, S, H, the moments too), in more registers.
inline constexpr kernels::Integrals register_quadratures{true, false, false, true, false, false};

/// A register kernel's shape: a member on `lanes` threads of a warp with `slots` rows apiece, its
/// rows uniform or disordered (each slot keeps three disorder factors), the stage vectors it holds
/// (tableaus of at most `stages` stages: 8 holds every Rosenbrock tableau, 6 rodas4 and rodas4p2 in
/// fewer registers), the occupancy it is compiled for (`blocks` > 0 makes ptxas keep blocks × 128
/// threads resident per multiprocessor: registers capped at 65 536 / (128 blocks), the rest spilled;
/// blocks of at most that many threads; 0 leaves the registers to ptxas), and the quadratures it can
/// carry (register_quadratures, or with `every_quadrature` all of them).
struct RegisterShape {
  std::size_t lanes = 0, slots = 0;
  bool disordered = false;
  std::size_t stages = kernels::RosenbrockTableau::max_stages;
  unsigned blocks = 0;
  bool every_quadrature = false;
  constexpr std::size_t capacity() const { return lanes * slots; }
  constexpr kernels::Integrals carriable() const {
    return every_quadrature ? kernels::all_integrals : register_quadratures;
  }
  /// Whether N rows fit: at least one per lane, at most `slots` (kernels::WarpRowSlots::fits).
  constexpr bool holds(std::size_t rows) const { return rows >= lanes && rows <= capacity(); }
  /// The most threads per block the kernel launches with (1024, a CUDA block's limit, unbounded).
  constexpr int max_threads_per_block() const { return blocks ? int(128 * blocks) : 1024; }
  friend constexpr bool operator==(const RegisterShape&, const RegisterShape&) = default;
};

/// The shapes this build compiled (CMake's ROTORSWEEP_GPU_REGISTER_SHAPES; none without CUDA).
std::span<const RegisterShape> gpu_register_shapes();

}  // namespace rotorsweep::ensemble
