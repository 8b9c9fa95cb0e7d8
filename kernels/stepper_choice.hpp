// The steppers a user can name (scene key numerics.stepper, --stepper) and the dispatch from
// that run-time name to the compile-time stepper type.
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "kernels/dormand_prince.hpp"
#include "kernels/rosenbrock.hpp"

namespace rotorsweep::kernels {

enum class StepperKind { rodas4, ros2, dopri5, rodas4p2 };

inline constexpr std::array<std::string_view, 4> stepper_names{"rodas4", "ros2", "dopri5", "rodas4p2"};

inline std::optional<StepperKind> parse_stepper(std::string_view name) {
  for (std::size_t i = 0; i < stepper_names.size(); ++i)
    if (stepper_names[i] == name) return StepperKind(i);
  return std::nullopt;
}

/// The stepper type of `kind` on `System`.
template <StepperKind kind, class System>
struct stepper_of {
  using type = Rodas4<System>;
};
template <class System>
struct stepper_of<StepperKind::ros2, System> {
  using type = Ros2<System>;
};
template <class System>
struct stepper_of<StepperKind::dopri5, System> {
  using type = DormandPrince5<System>;
};
template <class System>
struct stepper_of<StepperKind::rodas4p2, System> {
  using type = Rodas4P2<System>;
};

/// Calls f.template operator()<Stepper>() with the stepper type for `kind` on `System`.
template <class System, class F>
decltype(auto) with_stepper(StepperKind kind, F&& f) {
  switch (kind) {
    case StepperKind::ros2:
      return f.template operator()<typename stepper_of<StepperKind::ros2, System>::type>();
    case StepperKind::dopri5:
      return f.template operator()<typename stepper_of<StepperKind::dopri5, System>::type>();
    case StepperKind::rodas4p2:
      return f.template operator()<typename stepper_of<StepperKind::rodas4p2, System>::type>();
    case StepperKind::rodas4: break;
  }
  return f.template operator()<typename stepper_of<StepperKind::rodas4, System>::type>();
}

}  // namespace rotorsweep::kernels
