// Which per-period integrals ride along with the integration as quadrature states
// (docs/model.md §3: work W, Stokes S, drive R, time integrals of alignment ρ̄ and energy H, and the
// first moments ∫ t q̇ dt of R, W, S for the paper's triangular window).
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"

namespace rotorsweep::kernels {

/// The quadratures a model can carry.
enum class Quadrature { drive, work, stokes, alignment, energy, drive_moment, work_moment, stokes_moment };

/// The quadrature states a row model carries, chosen at run time from the scene's observables:
/// what a scene does not ask for is not evaluated (the row models branch once per evaluation),
/// and the steppers' loops over quadratures run over the carried ones only.
struct Integrals {
  /// The most a model can carry: storage is sized for it, so one instantiation serves every set.
  static constexpr std::size_t max_count = 8;

  bool drive = true;       ///< R = A Σ ∫ sin(θ_j - t) dt        (dissipation, robust estimator)
  bool work = false;       ///< W = A Σ ∫ sin(θ_j - t) θ̇_j dt    (work done by the drive)
  bool stokes = false;     ///< S = g Σ ∫ θ̇_j² dt               (Stokes dissipation)
  bool alignment = false;  ///< ∫ ρ̄ dt, ρ̄ = (1/N) Σ cos²((θ_j - θ_{j+1})/2)
  bool energy = false;     ///< ∫ H dt
  /// ∫ t q̇ dt of R, W and S (t the model's time): carried only together with R, W and S.
  bool moments = false;

  /// The set with what it needs: the moments take R, W and S along.
  ROTORSWEEP_HD constexpr Integrals completed() const {
    Integrals q = *this;
    if (q.moments) q.drive = q.work = q.stokes = true;
    return q;
  }

  ROTORSWEEP_HD constexpr std::size_t count() const {
    return std::size_t(drive) + work + stokes + alignment + energy + 3 * std::size_t(moments);
  }
  // Position of each integral in the quadrature state vector (valid when it is carried).
  ROTORSWEEP_HD constexpr std::size_t drive_index() const { return 0; }
  ROTORSWEEP_HD constexpr std::size_t work_index() const { return std::size_t(drive); }
  ROTORSWEEP_HD constexpr std::size_t stokes_index() const { return work_index() + work; }
  ROTORSWEEP_HD constexpr std::size_t alignment_index() const { return stokes_index() + stokes; }
  ROTORSWEEP_HD constexpr std::size_t energy_index() const { return alignment_index() + alignment; }
  /// The moment of R, then those of W and S.
  ROTORSWEEP_HD constexpr std::size_t moment_index() const { return energy_index() + energy; }

  ROTORSWEEP_HD constexpr bool carries(Quadrature q) const {
    switch (q) {
      case Quadrature::drive: return drive;
      case Quadrature::work: return work;
      case Quadrature::stokes: return stokes;
      case Quadrature::alignment: return alignment;
      case Quadrature::energy: return energy;
      case Quadrature::drive_moment:
      case Quadrature::work_moment:
      case Quadrature::stokes_moment: return moments;
    }
    return false;
  }
  ROTORSWEEP_HD constexpr std::size_t index(Quadrature q) const {
    switch (q) {
      case Quadrature::drive: return drive_index();
      case Quadrature::work: return work_index();
      case Quadrature::stokes: return stokes_index();
      case Quadrature::alignment: return alignment_index();
      case Quadrature::energy: return energy_index();
      case Quadrature::drive_moment: return moment_index();
      case Quadrature::work_moment: return moment_index() + 1;
      case Quadrature::stokes_moment: return moment_index() + 2;
    }
    return 0;
  }
  constexpr Integrals operator|(const Integrals& o) const {
    return {drive || o.drive,         work || o.work,     stokes || o.stokes,
            alignment || o.alignment, energy || o.energy, moments || o.moments};
  }
  constexpr bool operator==(const Integrals&) const = default;
};

inline constexpr Integrals all_integrals{true, true, true, true, true, true};
inline constexpr Integrals dissipation_only{true, false, false, false, false, false};

// The enum, the flags and max_count describe one list: carrying all, quadrature q sits at q's place.
static_assert(all_integrals.count() == Integrals::max_count);
static_assert(all_integrals.index(Quadrature::drive) == 0 && all_integrals.index(Quadrature::work) == 1 &&
              all_integrals.index(Quadrature::stokes) == 2 &&
              all_integrals.index(Quadrature::alignment) == 3 &&
              all_integrals.index(Quadrature::energy) == 4 &&
              all_integrals.index(Quadrature::drive_moment) == 5 &&
              all_integrals.index(Quadrature::stokes_moment) == Integrals::max_count - 1);

}  // namespace rotorsweep::kernels
