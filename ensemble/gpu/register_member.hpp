// The member a register kernel runs (docs/architecture.md "Register kernels"): WarpMember over the
// nearest-neighbour rows in registers (WarpRows, docs/model.md §1) with the Rosenbrock integrator, on
// a device's warp (kernels::DeviceWarp) or the host's emulation of one (kernels::HostWarp).
#pragma once

#include <cstddef>

#include "ensemble/gpu/gpu_registers.hpp"
#include "ensemble/rows/warp_member.hpp"
#include "kernels/models/rows/warp_rows.hpp"
#include "kernels/steppers/rosenbrock_tableaus.hpp"
#include "kernels/steppers/warp_member_form.hpp"
#include "kernels/steppers/warp_rosenbrock.hpp"

namespace rotorsweep::ensemble {

/// The rows of a member on the lanes of W with R slots apiece, disordered where PerRow, carrying
/// register_quadratures or, with Q, every quadrature (RegisterShape::carriable).
template <class W, std::size_t R, bool PerRow, bool Q = false>
using RegisterRows = kernels::WarpRows<W, R, PerRow, RegisterShape{.every_quadrature = Q}.carriable()>;

/// A member of RegisterRows from its start to its retirement, any Rosenbrock tableau of at most S
/// stages.
template <class W, std::size_t R, bool PerRow, std::size_t S = kernels::RosenbrockTableau::max_stages,
          bool Q = false>
using RegisterMember =
    WarpMember<RegisterRows<W, R, PerRow, Q>,
               kernels::WarpIntegrator<RegisterRows<W, R, PerRow, Q>,
                                       kernels::WarpRosenbrock<RegisterRows<W, R, PerRow, Q>, S>>>;

}  // namespace rotorsweep::ensemble
