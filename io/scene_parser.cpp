// Scene parsing and validation with toml++: a table of allowed keys per section, typed
// readers that name the key and the allowed values in every message (docs/scenes.md "Scene files").
#include "io/scene_parser.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "ensemble/gpu/gpu_executor.hpp"
#include "ensemble/rows/row_models.hpp"
#include "io/toml_section.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::io {

namespace {

using ensemble::Scene;

const std::map<std::string, std::set<std::string>> allowed_keys{
    {"model", {"kind", "rows", "couplings", "range", "row_length", "coupling_table", "boundary"}},
    {"drive", {"g"}},
    {"sweep", {"A"}},
    {"initial", {"kinds", "noise", "offset", "angles", "replicas", "seed"}},
    {"disorder", {"A", "anisotropy", "coupling", "seed", "A_rows", "anisotropy_rows", "coupling_rows"}},
    {"thermal", {"temperature", "steps_per_period", "step_fraction", "seed"}},
    {"schedule", {"relax_periods", "average_periods", "steady_tol", "max_periods", "refill"}},
    {"observables",
     [] {
       std::set<std::string> keys{"period_series", "row_profiles", "slip_rate", "slip_kinds"};
       for (const auto& observable : ensemble::observables) keys.insert(std::string(observable.key));
       return keys;
     }()},
    {"numerics",
     {"stepper", "rtol", "atol", "h_max", "max_steps", "controller", "lanes", "wrap_angles", "device",
      "global_error"}},
    {"output", {"path"}},
};

/// [disorder]: σ of each quantity, or its deviations per row, and the realizations' seed.
void read_disorder(const Section& disorder, Scene& scene) {
  auto& d = scene.disorder;
  const auto sigma_what = "a number from 0 to 1 (relative standard deviation)";
  const auto sigma = [](double x) { return x >= 0 && x <= 1; };
  d.A = disorder.number("A", 0.0, sigma_what, sigma);
  d.anisotropy = disorder.number("anisotropy", 0.0, sigma_what, sigma);
  d.coupling = disorder.number("coupling", 0.0, sigma_what, sigma);
  d.seed = std::uint64_t(disorder.integer("seed", 1, "an integer >= 0", [](long long s) { return s >= 0; }));
  const auto rows_of = [&](const char* key, const char* sigma_key, double sigma_value) {
    const toml::node* node = disorder.find(key);
    if (!node) return std::vector<double>{};
    if (sigma_value > 0)
      fail(disorder.key(key), std::string("and ") + disorder.key(sigma_key) +
                                  " are both given; give the deviations either drawn (σ) or per row");
    const std::string what =
        "a list of relative deviations > -1 whose length divides every model.rows (repeated over the rows)";
    const auto* list = node->as_array();
    if (!list || list->empty()) fail(disorder.key(key), "must be " + what);
    for (std::size_t n : scene.row_counts)
      if (n % list->size() != 0)
        fail(disorder.key(key), "has " + std::to_string(list->size()) +
                                    " values, which does not divide N = " + std::to_string(n) +
                                    "; it must be " + what);
    std::vector<double> values;
    for (const auto& v : *list)
      values.push_back(
          Section::checked_number(v, disorder.key(key), "a number > -1", [](double x) { return x > -1; }));
    return values;
  };
  d.A_rows = rows_of("A_rows", "A", d.A);
  d.anisotropy_rows = rows_of("anisotropy_rows", "anisotropy", d.anisotropy);
  d.coupling_rows = rows_of("coupling_rows", "coupling", d.coupling);
}

/// numerics.device = "gpu" runs every row scene (any stepper or temperature, disorder, coupling
/// tables, open rows, row profiles) up to the rows one GPU thread's scratch holds.
void check_gpu_scene(const Scene& scene) {
  const std::size_t limit = ensemble::gpu_executor().max_rows(scene);
  if (scene.max_rows() <= limit) return;
  const std::string integrator =
      scene.thermal.on()
          ? std::string("the Langevin stepper (thermal.temperature > 0)")
          : "numerics.stepper = \"" + std::string(kernels::stepper_names[scene.stepper]) + "\"";
  const auto& traits = ensemble::row_model_traits(scene.model);
  const std::string model = traits.coupling_table ? std::string(", ") + traits.description : "";
  const std::string profiles = scene.row_profiles ? ", row profiles" : "";
  fail("model.rows", "at most " + std::to_string(limit) + " rows run on the GPU with " + integrator + model +
                         profiles + " (got " + std::to_string(scene.max_rows()) +
                         "); numerics.device = \"cpu\" has no limit");
}

constexpr std::size_t max_members = 100000000;

/// The plan is too large: names the axis with the most values, and every axis's size.
[[noreturn]] void fail_too_many_members(const Scene& scene) {
  static constexpr const char* axis_keys[] = {"model.rows",    "numerics.rtol",   "sweep.A",
                                              "drive.g",       "initial.noise",   "initial.offset",
                                              "initial.kinds", "initial.replicas"};
  const auto sizes = scene.axis_sizes();
  std::size_t largest = 0;
  std::string product;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    if (sizes[i] > sizes[largest]) largest = i;
    product += (i ? " × " : "") + std::string(axis_keys[i]) + " " + std::to_string(sizes[i]);
  }
  double count = 0;  // as Scene::member_count, in floating point
  for (auto kind : scene.kinds)
    count += double(scene.replicas_of(kind)) *
             (ensemble::kind_uses_noise(kind) ? double(sizes[4]) * double(sizes[5]) : 1);
  for (std::size_t i = 0; i < 4; ++i) count *= double(sizes[i]);
  char total[32];
  std::snprintf(total, sizeof total, "%.3g", count);
  fail(axis_keys[largest], "the plan has " + std::string(total) + " members (" + product + "); at most " +
                               std::to_string(max_members) + " are allowed");
}

/// "all", or an integer from 1 to `limit`, at key k; 0 stands for "all".
std::size_t range_or_all(const Section& model, std::string_view k, const char* what, std::size_t fallback) {
  const toml::node* node = model.find(k);
  if (!node) return fallback;
  if (node->value_exact<std::string>() == std::optional<std::string>("all") ||
      node->value_exact<std::string>() == std::optional<std::string>("infinite"))
    return 0;
  const auto v = node->value_exact<long long>();
  if (!node->is_integer() || !v || *v < 1 || *v > 100000)
    fail(model.key(k), std::string("must be ") + what + " (got " + describe(*node) + ")");
  return std::size_t(*v);
}

/// model.couplings, range, row_length, coupling_table, boundary (docs/model.md §1, §8).
/// Each of `keys` given in `section` is one error: the model of `traits` has no use for it.
void refuse_keys(const Section& section, const ensemble::RowModelTraits& traits,
                 const std::vector<std::string>& keys) {
  for (const std::string& k : keys)
    if (section.find(k))
      fail(section.key(k), std::string("does not apply to ") + traits.description + " (model.kind = \"" +
                               traits.scene_value + "\"" + (traits.fixed_rows ? ", N = " + std::to_string(traits.fixed_rows) : "") + ")");
}

/// model.kind: "rows" (nearest neighbours or a coupling table, as the couplings say) or a model of its own
/// (ensemble/rows/row_models.hpp), whose traits the other sections are read by.
const ensemble::RowModelTraits& read_model_kind(const Section& model, Scene& scene) {
  std::set<std::string> kinds;
  for (const auto& t : ensemble::row_model_table) kinds.insert(t.scene_value);
  const std::string kind = model.choice("kind", "rows", kinds);
  for (const auto& t : ensemble::row_model_table)
    if (kind == t.scene_value) {
      scene.model = t.kind;
      std::vector<std::string> keys;
      if (t.fixed_rows) keys.push_back("rows");
      if (!t.takes_couplings)
        keys.insert(keys.end(), {"couplings", "range", "row_length", "coupling_table", "boundary"});
      refuse_keys(model, t, keys);
      return t;
    }
  throw std::logic_error("model.kind: no model of that name");
}

void read_couplings(const Section& model, Scene& scene) {
  auto& couplings = scene.couplings;
  couplings.open = model.choice("boundary", "periodic", {"periodic", "open"}) == "open";
  const std::string kind = model.choice("couplings", "nearest", {"nearest", "dipolar"});
  const bool has_table = model.find("coupling_table") != nullptr;
  if (has_table && model.find("couplings"))
    fail(model.key("coupling_table"), "and model.couplings exclude each other: give one");
  for (const char* k : {"range", "row_length"})
    if (model.find(k) && kind != "dipolar") fail(model.key(k), "needs model.couplings = \"dipolar\"");
  if (has_table) {
    const auto* table = model.find("coupling_table")->as_table();
    if (!table) fail(model.key("coupling_table"), "must be a table { a = …, b = [b_1, …], c = [c_1, …] }");
    for (const auto& [name, value] : *table)
      if (name != "a" && name != "b" && name != "c")
        fail(model.key("coupling_table") + "." + std::string(name.str()),
             "unknown key; the table has a, b, c");
    const Section t(table, model.key("coupling_table"));
    const auto finite = [](double) { return true; };
    couplings.kind = ensemble::RowCouplings::Kind::table;
    couplings.table.a = Section::checked_number(t.require("a", "a number"), t.key("a"), "a number", finite);
    couplings.table.b = t.numbers("b", {}, "a number", finite);
    couplings.table.c = t.numbers("c", {}, "a number", finite);
    if (couplings.table.b.empty()) t.require("b", "a non-empty list of numbers b_1 … b_M");
    if (couplings.table.c.size() != couplings.table.b.size())
      fail(t.key("c"), "must be as long as " + t.key("b") + " (" + std::to_string(couplings.table.b.size()) +
                           " values, c_u for u = 1 .. M)");
  } else if (kind == "dipolar") {
    couplings.kind = ensemble::RowCouplings::Kind::dipolar;
    couplings.range = range_or_all(model, "range", "an integer from 1 to 100000, or \"all\"", 1);
    couplings.all_rows = couplings.range == 0;
    couplings.row_length =
        range_or_all(model, "row_length", "an integer from 1 to 100000 (rotors per row), or \"infinite\"", 0);
  }
  const std::size_t range = couplings.kind == ensemble::RowCouplings::Kind::table ? couplings.table.range()
                            : couplings.all_rows                                  ? 0
                                                                                  : couplings.range;
  for (std::size_t n : scene.row_counts) {
    const std::size_t largest = ensemble::RowCouplings::largest_range(n, couplings.open);
    if (range > largest)
      fail(model.key(couplings.kind == ensemble::RowCouplings::Kind::table ? "coupling_table" : "range"),
           "reaches " + std::to_string(range) + " rows, more than N = " + std::to_string(n) + " " +
               (couplings.open ? "open rows have (at most N - 1)"
                               : "periodic rows allow (at most N/2: each pair at its shortest distance)"));
  }
}

Scene read_scene(const toml::table& root) {
  for (const char* name : {"slider", "substrate"})
    if (root.contains(name))
      fail(name, "is a section of slider scenes (docs/model.md §9): run them with `rotorsweep slider FILE`");
  check_sections(root, allowed_keys);
  Scene scene;
  const Section model = section(root, "model");
  const ensemble::RowModelTraits& traits = read_model_kind(model, scene);
  scene.row_counts.clear();
  if (traits.fixed_rows) {
    scene.row_counts.push_back(traits.fixed_rows);
  } else {
    for (long long n : model.integers("rows", "an even integer from 2 to 100000",
                                      [](long long n) { return n >= 2 && n <= 100000 && n % 2 == 0; }))
      scene.row_counts.push_back(std::size_t(n));
  }
  if (traits.takes_couplings) {
    read_couplings(model, scene);
    scene.model = ensemble::row_model_for(scene.couplings);
  }

  scene.g_values = grid(section(root, "drive"), "g", "> 0", [](double g) { return g > 0; });
  scene.A_values = grid(section(root, "sweep"), "A", ">= 0", [](double A) { return A >= 0; });

  const Section initial = section(root, "initial");
  if (const toml::node* kinds = initial.find("kinds")) {
    const auto* list = kinds->as_array();
    const std::string allowed = "a non-empty list of distinct names from FM, AFM, random, exact";
    if (!list || list->empty())
      fail(initial.key("kinds"), "must be " + allowed + " (got " + describe(*kinds) + ")");
    scene.kinds.clear();
    for (const auto& element : *list) {
      const auto name = element.value_exact<std::string>();
      const auto kind = name ? ensemble::parse_kind(*name) : std::nullopt;
      if (!kind || std::count(scene.kinds.begin(), scene.kinds.end(), *kind))
        fail(initial.key("kinds"), "must be " + allowed + " (got " + describe(element) + ")");
      scene.kinds.push_back(*kind);
    }
  }
  scene.noise_values = grid(
      initial, "noise", "from 0 to 3.14159", [](double x) { return x >= 0 && x <= 3.1415926535897932; },
      scene.noise_values);
  // beyond 10^4 rad an angle's rounding (1.8e-12 there) starts to compete with atol
  const auto bounded_angle = [](double x) { return std::fabs(x) <= 1e4; };
  scene.offset_values = grid(initial, "offset", "from -1e4 to 1e4 (radians; give them modulo 2π)",
                             bounded_angle, scene.offset_values);
  scene.replicas = int(initial.integer("replicas", scene.replicas, "an integer from 1 to 1000000",
                                       [](long long r) { return r >= 1 && r <= 1000000; }));
  scene.seed =
      std::uint64_t(initial.integer("seed", 1, "an integer >= 0", [](long long s) { return s >= 0; }));
  const bool exact = std::count(scene.kinds.begin(), scene.kinds.end(), ensemble::InitialKind::exact) > 0;
  const std::string angles_what =
      "a list of numbers whose length divides every model.rows "
      "(repeated over the rows; one angle per row for a single N)";
  if (const toml::node* angles = initial.find("angles")) {
    const auto* list = angles->as_array();
    if (!list || list->empty()) fail(initial.key("angles"), "must be " + angles_what);
    for (std::size_t n : scene.row_counts)
      if (n % list->size() != 0)
        fail(initial.key("angles"), "has " + std::to_string(list->size()) +
                                        " values, which does not divide N = " + std::to_string(n) +
                                        "; it must be " + angles_what);
    for (const auto& a : *list)
      scene.exact_angles.push_back(Section::checked_number(
          a, initial.key("angles"), "a number from -1e4 to 1e4 (radians; give it modulo 2π)", bounded_angle));
    if (!exact) fail(initial.key("angles"), "is only used with kind \"exact\" in initial.kinds");
  } else if (exact) {
    initial.require("angles", angles_what + " when kinds has \"exact\"");
  }

  const Section disorder = section(root, "disorder");
  if (!traits.row_disorder)
    refuse_keys(disorder, traits, {"A", "anisotropy", "coupling", "A_rows", "anisotropy_rows", "coupling_rows", "seed"});
  read_disorder(disorder, scene);
  const Section thermal = section(root, "thermal");
  scene.thermal.temperature = thermal.number("temperature", 0.0, "a number from 0 to 1e6 (units of ε)",
                                             [](double T) { return T >= 0 && T <= 1e6; });
  if (scene.thermal.on() && !traits.langevin)
    fail(thermal.key("temperature"), std::string("must be 0 with ") + traits.description +
                                         " (model.kind = \"" + traits.scene_value + "\" has no Langevin stepper)");
  scene.thermal.steps_per_period = int(thermal.integer("steps_per_period", scene.thermal.steps_per_period,
                                                       "an integer from 16 to 10000000",
                                                       [](long long n) { return n >= 16 && n <= 10000000; }));
  scene.thermal.step_fraction = thermal.number("step_fraction", scene.thermal.step_fraction,
                                               "a number from 1e-6 to 1.5 (largest step × κ / g; the "
                                               "explicit step is unstable above 2)",
                                               [](double x) { return x >= 1e-6 && x <= 1.5; });
  scene.thermal.seed =
      std::uint64_t(thermal.integer("seed", 1, "an integer >= 0", [](long long s) { return s >= 0; }));

  const Section schedule = section(root, "schedule");
  const auto non_negative = [](long long n) { return n >= 0 && n <= 1000000; };
  const auto positive = [](long long n) { return n >= 1 && n <= 1000000; };
  scene.relax_periods = int(
      schedule.integer("relax_periods", scene.relax_periods, "an integer from 0 to 1000000", non_negative));
  scene.average_periods = int(
      schedule.integer("average_periods", scene.average_periods, "an integer from 1 to 1000000", positive));
  scene.steady_tol = schedule.number("steady_tol", scene.steady_tol, "a number >= 0 (0: fixed schedule)",
                                     [](double x) { return x >= 0; });
  const int minimum_periods = scene.relax_periods + scene.average_periods;
  scene.max_periods = std::max(scene.max_periods, minimum_periods);
  if (schedule.find("max_periods")) {
    scene.max_periods = int(schedule.integer("max_periods", 0, "an integer from 1 to 1000000", positive));
    if (scene.max_periods < minimum_periods)
      fail(schedule.key("max_periods"),
           "must be >= relax_periods + average_periods = " + std::to_string(minimum_periods));
  }
  scene.refill = schedule.boolean("refill", scene.refill);

  const Section observables = section(root, "observables");
  if (!traits.row_observables) {  // D alone
    for (std::size_t i = 0; i < ensemble::observable_count; ++i)
      if (ensemble::Observable(i) != ensemble::Observable::dissipation)
        scene.observables.set(ensemble::Observable(i), false);
    std::vector<std::string> row_keys{"row_profiles", "slip_kinds", "slip_rate"};
    for (std::size_t i = 0; i < ensemble::observable_count; ++i)
      if (ensemble::Observable(i) != ensemble::Observable::dissipation)
        row_keys.emplace_back(ensemble::declaration(ensemble::Observable(i)).key);
    refuse_keys(observables, traits, row_keys);
  }
  for (std::size_t i = 0; i < ensemble::observable_count; ++i) {
    const auto observable = ensemble::Observable(i);
    scene.observables.set(observable,
                          observables.boolean(ensemble::declaration(observable).key, scene.has(observable)));
  }
  scene.period_series = observables.boolean("period_series", scene.period_series);
  scene.row_profiles = observables.boolean("row_profiles", scene.couplings.open);
  scene.slip_rate = observables.number("slip_rate", scene.slip_rate, "a number > 0 (rows' angular velocity)",
                                       [](double x) { return x > 0; });
  scene.slip_kinds = observables.boolean("slip_kinds", scene.slip_kinds);
  if (scene.slip_kinds && !scene.classifies_regimes())
    fail(observables.key("slip_kinds"),
         "needs observables.slips and observables.alignment = true (it refines the regime rule)");
  if (scene.slip_kinds && scene.thermal.on())
    fail(observables.key("slip_kinds"),
         "must be false when thermal.temperature > 0 (with noise a slip's energy does not scale with g)");
  if (scene.steady_tol > 0 && !scene.has(ensemble::Observable::dissipation))
    fail(schedule.key("steady_tol"),
         "needs observables.dissipation = true (it compares D of successive periods)");
  for (const auto& [observable, also] : {std::pair{ensemble::Observable::estimators, ""},
                                         {ensemble::Observable::moments, " (the moments carry it along)"}})
    if (scene.thermal.on() && scene.has(observable))
      fail(observables.key(ensemble::declaration(observable).key),
           std::string("must be false when thermal.temperature > 0: with noise θ̇ does not exist, so the "
                       "Stokes estimator diverges") +
               also + " (D is the drive's work R; see docs/model.md §7)");

  const Section numerics = section(root, "numerics");
  scene.stepper = read_stepper(numerics);
  if (!traits.explicit_steppers && kernels::stepper_family(scene.stepper) != kernels::StepperFamily::rosenbrock)
    fail(numerics.key("stepper"), std::string("must be a linearly implicit stepper with ") + traits.description +
                                      " (model.kind = \"" + traits.scene_value + "\")");
  scene.rtol_values = numerics.numbers("rtol", scene.rtol_values, rtol_range, valid_rtol);
  scene.atol_values = numerics.numbers("atol", scene.atol_values, atol_range, valid_atol);
  if (scene.atol_values.size() == 1)
    scene.atol_values.assign(scene.rtol_values.size(), scene.atol_values.front());
  if (scene.atol_values.size() != scene.rtol_values.size())
    fail(numerics.key("atol"), "must be one number, or a list as long as numerics.rtol (" +
                                   std::to_string(scene.rtol_values.size()) + " values, paired with them)");
  scene.h_max = numerics.number("h_max", scene.h_max, "a number > 0 and <= 2π (the drive period)",
                                [](double x) { return x > 0 && x <= 6.283185307179586; });
  scene.max_steps = read_max_steps(numerics);
  scene.controller = numerics.choice("controller", "integral", {"integral", "pi"}) == "pi"
                         ? kernels::StepController::pi
                         : kernels::StepController::integral;
  if (scene.thermal.on() && scene.controller == kernels::StepController::pi)
    fail(numerics.key("controller"),
         "must be \"integral\" when thermal.temperature > 0 (the Langevin stepper takes fixed steps)");
  scene.lanes = numerics.choice("lanes", traits.simd_lanes ? "simd" : "scalar",
                                traits.simd_lanes ? std::set<std::string>{"simd", "scalar"}
                                                  : std::set<std::string>{"scalar"}) == "simd"
                    ? ensemble::LaneKind::simd
                    : ensemble::LaneKind::scalar;

  scene.wrap_angles = numerics.boolean("wrap_angles", scene.wrap_angles);
  scene.shadow_runs = numerics.choice("global_error", "shadow", {"shadow", "local"}) == "shadow";
  if (scene.thermal.on() && scene.shadow_runs && numerics.find("global_error"))
    fail(numerics.key("global_error"),
         "must be \"local\" (or left out) when thermal.temperature > 0: shadow runs need a deterministic "
         "member, and at T > 0 D's error is its standard error over the averaged periods");
  scene.device = numerics.choice("device", "cpu", {"cpu", "gpu"}) == "gpu" ? ensemble::Device::gpu
                                                                           : ensemble::Device::cpu;
  if (scene.device == ensemble::Device::gpu && !traits.device)
    fail(numerics.key("device"), std::string("must be \"cpu\" with ") + traits.description + " (model.kind = \"" +
                                     traits.scene_value + "\" runs on the CPU's lanes)");
  if (scene.slip_kinds && scene.device == ensemble::Device::gpu)
    fail(numerics.key("device"),
         "must be \"cpu\" with observables.slip_kinds (its reruns at g/10 run on the CPU backend)");

  const Section output = section(root, "output");
  scene.output_path = output.text("path", scene.output_path);
  if (!ensemble::row_model_traits(scene.model).bond_disorder &&
      (scene.disorder.coupling > 0 || !scene.disorder.coupling_rows.empty()))
    fail(scene.disorder.coupling > 0 ? "disorder.coupling" : "disorder.coupling_rows",
         "works with nearest-neighbour periodic rows only (model.couplings = \"nearest\", "
         "model.boundary = \"periodic\": a bond j, j + 1 has one coupling); a coupling table or open rows "
         "take disorder.A and disorder.anisotropy");
  if (scene.member_count() > max_members) fail_too_many_members(scene);
  check_device(scene);
  return scene;
}

}  // namespace

void check_device(const ensemble::Scene& scene) {
  if (scene.device == ensemble::Device::gpu) check_gpu_scene(scene);
}

ensemble::Scene parse_scene_text(std::string_view text, std::string_view source) {
  const toml::table root = parse_toml(text, source);
  Scene scene = read_scene(root);
  scene.text = std::string(text);
  return scene;
}

ensemble::Scene parse_scene_file(const std::string& path) {
  return parse_scene_text(read_scene_file(path), path);
}

}  // namespace rotorsweep::io
