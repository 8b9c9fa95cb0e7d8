// The one list of steppers a user can name (scene key numerics.stepper, --stepper): each entry is
// a tableau that carries its name and, by its type, its family; one dispatch from name to type.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>
#include <type_traits>
#include <utility>

#include "kernels/lanes/host_device.hpp"
#include "kernels/steppers/dormand_prince.hpp"
#include "kernels/steppers/rosenbrock.hpp"

namespace rotorsweep::kernels {

/// The stepper family a tableau's type selects: linearly implicit or explicit. A family is one
/// type that takes its tableau (its Method) at run time.
template <LaneModel System>
RosenbrockStepper<System> stepper_family_of(const RosenbrockTableau&);
template <LaneModel System>
DormandPrince5<System> stepper_family_of(const ExplicitTableau&);

/// One entry of the list: `type<System>` is the stepper on a model, built with `tableau`.
/// `swing_error_factor` κ is how
/// many times rtol · max_t |R(t)| the error of a period's dissipation reaches with this stepper
/// (the channel dissipation_error, docs/numerics.md "The error of D", measured by
/// scripts/bench/error_calibration.py, with R held to rtol / 8): 1/8 for rodas4p2, 1/4 for rodas4,
/// 1 for rodas5p, whose error estimate is the least pessimistic; 1 for ros2 and dopri5.
template <const auto& Tableau, double SwingErrorFactor = 1.0>
struct StepperEntry {
  static constexpr std::string_view name = Tableau.name;
  static constexpr const auto& tableau = Tableau;
  static constexpr double swing_error_factor = SwingErrorFactor;
  template <class System>
  using type = decltype(stepper_family_of<System>(Tableau));
};

template <class... Entries>
struct StepperList {
  static constexpr std::size_t size = sizeof...(Entries);
  static constexpr std::array<std::string_view, size> names{Entries::name...};
  static constexpr std::array<double, size> swing_error_factors{Entries::swing_error_factor...};
};

// Adding a stepper: its tableau, and one entry here (the build makes a translation unit per family, the
// tableau its data).
using steppers = StepperList<StepperEntry<rodas4_tableau, 0.25>, StepperEntry<ros2_tableau>,
                             StepperEntry<dormand_prince5_tableau>, StepperEntry<rodas4p2_tableau, 0.125>,
                             StepperEntry<rodas5p_tableau>>;

inline constexpr auto stepper_names = steppers::names;
inline constexpr auto stepper_swing_error_factors = steppers::swing_error_factors;

/// Position of a stepper in the list (its identity in scenes and dispatch).
using StepperId = std::size_t;

constexpr std::optional<StepperId> parse_stepper(std::string_view name) {
  for (std::size_t i = 0; i < stepper_names.size(); ++i)
    if (stepper_names[i] == name) return i;
  return std::nullopt;
}

/// The stepper of a scene that names none: the cheapest at matched error of D on the benchmark
/// members, and at the default rtol both cheaper and more accurate than rodas4 (docs/performance.md).
inline constexpr std::string_view default_stepper_name = "rodas4p2";
inline StepperId default_stepper() { return *parse_stepper(default_stepper_name); }

/// The entry at position `id` of the list.
template <StepperId id, class List = steppers>
struct stepper_at;
template <StepperId id, class First, class... Rest>
struct stepper_at<id, StepperList<First, Rest...>> : stepper_at<id - 1, StepperList<Rest...>> {};
template <class First, class... Rest>
struct stepper_at<0, StepperList<First, Rest...>> {
  using type = First;
};

/// Calls f.template operator()<id>() with the run-time position `id` as a compile-time constant.
template <class F, std::size_t... ids>
decltype(auto) with_stepper_id(StepperId id, F&& f, std::index_sequence<ids...>) {
  using Result = decltype(f.template operator()<0>());
  if constexpr (std::is_void_v<Result>) {
    ((id == ids ? (f.template operator()<ids>(), true) : false) || ...);
  } else {
    Result result{};
    ((id == ids ? (result = f.template operator()<ids>(), true) : false) || ...);
    return result;
  }
}
template <class F>
decltype(auto) with_stepper_id(StepperId id, F&& f) {
  return with_stepper_id(id, std::forward<F>(f), std::make_index_sequence<steppers::size>());
}

/// The families of the list, by the type of their tableaus: one stepper type each.
enum class StepperFamily { rosenbrock, explicit_runge_kutta };
template <StepperFamily family, class System>
using family_stepper = std::conditional_t<family == StepperFamily::rosenbrock, RosenbrockStepper<System>,
                                          DormandPrince5<System>>;

/// The family of stepper `id`.
inline StepperFamily stepper_family(StepperId id) {
  StepperFamily family = StepperFamily::rosenbrock;
  with_stepper_id(id, [&]<StepperId i>() {
    if constexpr (std::is_same_v<std::remove_cvref_t<decltype(stepper_at<i>::type::tableau)>, ExplicitTableau>)
      family = StepperFamily::explicit_runge_kutta;
  });
  return family;
}

/// Calls f.template operator()<family>() with stepper `id`'s family as a compile-time constant.
template <class F>
decltype(auto) with_stepper_family(StepperId id, F&& f) {
  if (stepper_family(id) == StepperFamily::explicit_runge_kutta)
    return f.template operator()<StepperFamily::explicit_runge_kutta>();
  return f.template operator()<StepperFamily::rosenbrock>();
}

/// The tableau (Method) of stepper `id`, which belongs to a family whose tableaus are of type Method
/// (on the host: a device cannot read the list's constants and gets StepperMethods instead).
template <class Method, std::size_t... ids>
Method stepper_method(StepperId id, std::index_sequence<ids...>) {
  Method method{};
  const auto take = [&]<std::size_t i>() {
    if constexpr (std::is_same_v<std::remove_cvref_t<decltype(stepper_at<i>::type::tableau)>, Method>) {
      constexpr Method entry = stepper_at<i>::type::tableau;
      method = entry;
    }
  };
  ((id == ids ? (take.template operator()<ids>(), true) : false) || ...);
  return method;
}
template <class Method>
Method stepper_method(StepperId id) {
  return stepper_method<Method>(id, std::make_index_sequence<steppers::size>());
}

/// Stepper `id`'s tableau as data a device reads: the host fills the member of its family's type
/// (stepper_methods) and passes it in a kernel's arguments.
struct StepperMethods {
  RosenbrockTableau rosenbrock{};
  ExplicitTableau explicit_runge_kutta{};
  template <class Method>
  ROTORSWEEP_HD const Method& get() const {
    if constexpr (std::is_same_v<Method, RosenbrockTableau>)
      return rosenbrock;
    else
      return explicit_runge_kutta;
  }
};
inline StepperMethods stepper_methods(StepperId id) {
  StepperMethods methods;
  if (stepper_family(id) == StepperFamily::rosenbrock)
    methods.rosenbrock = stepper_method<RosenbrockTableau>(id);
  else
    methods.explicit_runge_kutta = stepper_method<ExplicitTableau>(id);
  return methods;
}

/// Calls f.template operator()<Stepper>(method) with the stepper type of `id` on `System` (its family's)
/// and the tableau it runs.
template <class System, class F>
decltype(auto) with_stepper(StepperId id, F&& f) {
  return with_stepper_family(id, [&]<StepperFamily family>() {
    using Stepper = family_stepper<family, System>;
    return f.template operator()<Stepper>(stepper_method<typename Stepper::Method>(id));
  });
}

}  // namespace rotorsweep::kernels
