// The memory a row sweep works in besides its results: one lane block (an integration loop's
// arena) per OpenMP thread, at the scene's largest N, for the scene's stepper and row model.
#pragma once

#include "ensemble/rows/scene.hpp"

namespace rotorsweep::ensemble {

/// Bytes of one lane block's arena (model parameters, Jacobian and its factors, stage vectors,
/// state), counted by building the parts over an arena without storage; a dense coupling table
/// makes it grow as N².
double lane_block_bytes(const Scene& scene);

}  // namespace rotorsweep::ensemble
