// One row's torque and stiffness in the nearest-neighbour rows (docs/model.md §1, paper Eq. EOMFULL), from
// its terms: the one place the formula is written for the lanes, the teams and the registers.
#pragma once

#include "kernels/lanes/host_device.hpp"

namespace rotorsweep::kernels {

/// f_j = (1/g)(−3 a_j sin 2θ_j + b_j sin(θ_j − θ_{j+1}) − b_{j−1} sin(θ_{j−1} − θ_j) + A_j sin(θ_j − t)),
/// from `anisotropy` = a_j sin 2θ_j, the weighted link sines after and before the row, and
/// `drive` = A_j sin(θ_j − t).
template <class V>
ROTORSWEEP_HD ROTORSWEEP_INLINE V row_torque(const V& inv_g, const V& anisotropy, const V& link_after,
                                             const V& link_before, const V& drive) {
  return inv_g * (V(-3.0) * anisotropy + link_after - link_before + drive);
}

/// ∂f_j/∂θ_j = (1/g)(−6 a_j cos 2θ_j + b_j cos(θ_j − θ_{j+1}) + b_{j−1} cos(θ_{j−1} − θ_j)
///              + A_j cos(θ_j − t)),
/// from `anisotropy` = a_j cos 2θ_j, the links' weighted cosines and `drive` = A_j cos(θ_j − t).
template <class V>
ROTORSWEEP_HD ROTORSWEEP_INLINE V row_stiffness(const V& inv_g, const V& anisotropy, const V& link_after,
                                                const V& link_before, const V& drive) {
  return inv_g * (V(-6.0) * anisotropy + link_after + link_before + drive);
}

}  // namespace rotorsweep::kernels
