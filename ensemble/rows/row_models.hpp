// The row models `rotorsweep run` sweeps, each declared once (docs/architecture.md "Worked example: adding
// a model"): its kind (the scene parser sets it), its model template, its traits (lanes, GPU forms, slots).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "ensemble/rows/coupling_table.hpp"
#include "kernels/models/rows/coupled_rows.hpp"
#include "kernels/models/rows/nearest_neighbour_rows.hpp"
#include "kernels/models/single_rotor.hpp"

namespace rotorsweep::ensemble {

/// Which model a scene's members run (Scene::model, declared in scene.hpp), in row_model_table's order.
enum class RowModelKind : unsigned char { nearest_neighbour, coupled, single_rotor };

/// What a model has, read by the parser, the sweeps, the GPU plan and the slot fill.
struct RowModelTraits {
  RowModelKind kind;
  const char* scene_value;  ///< model.kind that names it ("rows": the couplings pick nearest or coupled)
  const char* description;  ///< in messages: "a coupling table or open rows"
  bool simd_lanes = true;   ///< it runs on SIMD lanes too (else numerics.lanes is "scalar")
  bool explicit_steppers = true;  ///< the explicit family (dopri5) too, not only the linearly implicit one
  bool langevin = false;    ///< thermal.temperature > 0 (the Langevin stepper needs its curvature bound)
  bool device = false;      ///< on the GPU, a member per thread and per team of a warp's threads
  bool register_form = false;      ///< in the register kernels (kernels/models/rows/warp_rows.hpp)
  std::size_t team_max_rows = 0;   ///< the most rows of a member on a GPU team
  bool coupling_table = false;     ///< slot inputs: a coupling table (a, b, c, range, open)
  bool row_disorder = false;       ///< disorder.A and disorder.anisotropy (and the symmetry probes)
  bool bond_disorder = false;      ///< disorder.coupling
  std::size_t fixed_rows = 0;      ///< 0: model.rows gives N; else N is this and model.rows is refused
  bool takes_couplings = false;    ///< model.couplings, range, row_length, coupling_table, boundary
  bool row_observables = false;    ///< alignment, slips, energy, estimators, moments, row profiles (else R only)
  /// A_*, the end of the two-angle landscape's jumps, where the model has one (smooth_alternation_window.hpp)
  double (*A_star)() = nullptr;
};

/// A_* = √((1100 + 40√601)/27) of uniform nearest-neighbour rows (docs/model.md §4).
inline double nearest_neighbour_A_star() { return std::sqrt((1100 + 40 * std::sqrt(601.0)) / 27); }

/// Nearest-neighbour rows, periodic (docs/model.md §1).
struct NearestNeighbourModel {
  template <class V>
  using model = kernels::NearestNeighbourRows<V>;
  static constexpr RowModelTraits traits{.kind = RowModelKind::nearest_neighbour,
                                         .scene_value = "rows",
                                         .description = "nearest-neighbour rows",
                                         .langevin = true,
                                         .device = true,
                                         .register_form = true,
                                         .team_max_rows = std::size_t(1) << 16,
                                         .row_disorder = true,
                                         .bond_disorder = true,
                                         .takes_couplings = true,
                                         .row_observables = true,
                                         .A_star = &nearest_neighbour_A_star};
};

/// Rows coupled by a table (dipolar, or nearest neighbours with open ends; docs/model.md §8): two dense
/// N × N matrices on a GPU team, hence its smaller row cap.
struct CoupledModel {
  template <class V>
  using model = kernels::CoupledRows<V>;
  static constexpr RowModelTraits traits{.kind = RowModelKind::coupled,
                                         .scene_value = "rows",
                                         .description = "a coupling table or open rows",
                                         .langevin = true,
                                         .device = true,
                                         .team_max_rows = std::size_t(1) << 12,
                                         .coupling_table = true,
                                         .row_disorder = true,
                                         .takes_couplings = true,
                                         .row_observables = true};
};

/// One rotor in a rotating field (docs/model.md §1 "A second model"): R and D only, on the CPU's double lane.
struct SingleRotorModel {
  template <class V>
  using model = kernels::SingleRotor<V>;
  static constexpr RowModelTraits traits{.kind = RowModelKind::single_rotor,
                                         .scene_value = "single_rotor",
                                         .description = "a single rotor",
                                         .simd_lanes = false,
                                         .explicit_steppers = false,
                                         .fixed_rows = 1};
};

template <class... Entries>
struct RowModelList {};
/// Every model, in RowModelKind's order.
using RowModels = RowModelList<NearestNeighbourModel, CoupledModel, SingleRotorModel>;

inline constexpr std::array row_model_table{NearestNeighbourModel::traits, CoupledModel::traits,
                                            SingleRotorModel::traits};
static_assert([] {
  for (std::size_t i = 0; i < row_model_table.size(); ++i)
    if (std::size_t(row_model_table[i].kind) != i) return false;
  return true;
}());

constexpr const RowModelTraits& row_model_traits(RowModelKind kind) { return row_model_table[std::size_t(kind)]; }
/// The kind's description for an error's text; "(unknown)" for a value outside the enumeration.
constexpr const char* row_model_description(RowModelKind kind) {
  return std::size_t(kind) < row_model_table.size() ? row_model_table[std::size_t(kind)].description
                                                    : "(unknown)";
}

/// The rows' model for the couplings a scene gives: nearest neighbours on a ring, else a coupling table.
constexpr RowModelKind row_model_for(const RowCouplings& c) {
  return c.kind == RowCouplings::Kind::nearest && !c.open ? RowModelKind::nearest_neighbour
                                                          : RowModelKind::coupled;
}

/// The instantiations a dispatch may make: the CPU's lanes (the linearly implicit steppers, the explicit
/// ones, or only their storage), the Langevin stepper on them, the GPU's members (thread and team: a
/// model with the device form has both).
enum class RowModelForm { lanes, explicit_lanes, langevin, device, device_langevin };

constexpr bool has_form(const RowModelTraits& t, RowModelForm form) {
  switch (form) {
    case RowModelForm::lanes: return true;
    case RowModelForm::explicit_lanes: return t.explicit_steppers;
    case RowModelForm::langevin: return t.langevin;
    case RowModelForm::device: return t.device;
    case RowModelForm::device_langevin: return t.device && t.langevin;
  }
  return false;
}

namespace detail {

template <RowModelForm form, class Entry, class... Rest>
consteval auto first_entry_with(RowModelList<Entry, Rest...>) {
  if constexpr (has_form(Entry::traits, form))
    return std::type_identity<Entry>{};
  else
    return first_entry_with<form>(RowModelList<Rest...>{});
}

template <RowModelForm form, class R, class F, class Entry, class... Rest>
R dispatch_row_model(RowModelKind kind, F& f) {
  if constexpr (has_form(Entry::traits, form))
    if (kind == Entry::traits.kind) return f.template operator()<Entry>();
  if constexpr (sizeof...(Rest) > 0)
    return dispatch_row_model<form, R, F, Rest...>(kind, f);
  else
    throw std::logic_error(std::string("the row model of ") + row_model_description(kind) +
                           " has no such form; the scene parser refuses such scenes");
}

template <RowModelForm form, class F, class... Entries>
decltype(auto) dispatch_row_models(RowModelList<Entries...>, RowModelKind kind, F& f) {
  using First = typename decltype(first_entry_with<form>(RowModels{}))::type;
  using R = decltype(f.template operator()<First>());
  return dispatch_row_model<form, R, F, Entries...>(kind, f);
}

}  // namespace detail

/// f.template operator()<Entry>() with the kind's entry (NearestNeighbourModel, …) among the models that
/// have `form`.
template <RowModelForm form, class F>
decltype(auto) with_row_model_entry(RowModelKind kind, F&& f) {
  return detail::dispatch_row_models<form>(RowModels{}, kind, f);
}

/// f.template operator()<Model>() with the kind's model on the double lane (a GPU's thread, team or chunk).
template <RowModelForm form, class F>
decltype(auto) with_double_lane_model(RowModelKind kind, F&& f) {
  return with_row_model_entry<form>(kind, [&]<class Entry>() -> decltype(auto) {
    return f.template operator()<typename Entry::template model<double>>();
  });
}

// What the types tell is what the traits declare.
template <class Entry>
consteval bool traits_match_types() {
  using M = typename Entry::template model<double>;
  using P = typename M::Parameters;
  constexpr const RowModelTraits& t = Entry::traits;
  return t.langevin == requires(const M& m) { m.curvature_bound(std::size_t{}); } &&
         t.coupling_table == requires(P p) { p.range; } && t.row_disorder == requires(P p) { p.A_rows; } &&
         t.bond_disorder == requires(P p) { p.coupling_rows; };
}
static_assert(traits_match_types<NearestNeighbourModel>() && traits_match_types<CoupledModel>() &&
              traits_match_types<SingleRotorModel>());

}  // namespace rotorsweep::ensemble
