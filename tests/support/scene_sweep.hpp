// Test support: a scene's text swept on the CPU's lanes as `rotorsweep run` sweeps it (parsed, every member
// planned, run_sweep on `threads` threads), its members' results in plan order.
#pragma once

#include <string>
#include <vector>

#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/sweep.hpp"
#include "io/scene_parser.hpp"

namespace rotorsweep::testing {

inline std::vector<ensemble::MemberResult> sweep(const std::string& text, int threads = 1) {
  const auto scene = io::parse_scene_text(text, "test-scene");
  return ensemble::run_sweep(scene, ensemble::plan_members(scene), {.threads = threads}).results;
}

}  // namespace rotorsweep::testing
