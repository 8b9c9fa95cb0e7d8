// The steppers a user can name (scene key numerics.stepper, --stepper) and the dispatch from
// that run-time name to the compile-time stepper type.
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "kernels/dormand_prince.hpp"
#include "kernels/rosenbrock.hpp"

namespace rotorsweep::kernels {

enum class StepperKind { rodas4, ros2, dopri5 };

inline constexpr std::array<std::string_view, 3> stepper_names{"rodas4", "ros2", "dopri5"};

inline std::optional<StepperKind> parse_stepper(std::string_view name) {
  for (std::size_t i = 0; i < stepper_names.size(); ++i)
    if (stepper_names[i] == name) return StepperKind(i);
  return std::nullopt;
}

/// Calls f.template operator()<Stepper>() with the stepper type for `kind` on `System`.
template <class System, class F>
decltype(auto) with_stepper(StepperKind kind, F&& f) {
  switch (kind) {
    case StepperKind::ros2: return f.template operator()<Ros2<System>>();
    case StepperKind::dopri5: return f.template operator()<DormandPrince5<System>>();
    case StepperKind::rodas4: break;
  }
  return f.template operator()<Rodas4<System>>();
}

}  // namespace rotorsweep::kernels
