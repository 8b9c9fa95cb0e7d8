// Run-time choices turned into compile-time ones (one instantiation per value): a flag, and the
// quadratures a scene's observables need (docs/architecture.md "Observables").
#pragma once

#include "kernels/integrals.hpp"

namespace rotorsweep::ensemble {

/// Calls f.template operator()<b>() with the run-time flag b as a compile-time constant.
template <class F>
decltype(auto) with_flag(bool b, F&& f) {
  return b ? f.template operator()<true>() : f.template operator()<false>();
}

/// Calls f.template operator()<Q>() with the quadratures `needed` as a compile-time Integrals,
/// one instantiation per combination of the observables that carry quadratures.
template <class F>
decltype(auto) with_integrals(kernels::Integrals needed, F&& f) {
  return with_flag(needed.drive, [&]<bool drive>() {
    return with_flag(needed.work, [&]<bool estimators>() {
      return with_flag(needed.alignment, [&]<bool alignment>() {
        return with_flag(needed.energy, [&]<bool energy>() {
          return f
              .template operator()<kernels::Integrals{drive, estimators, estimators, alignment, energy}>();
        });
      });
    });
  });
}

}  // namespace rotorsweep::ensemble
