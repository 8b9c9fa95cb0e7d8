// Slider scene parsing with the shared section readers (io/toml_section.hpp): SI values with their
// allowed ranges, the separation scan as a grid, and the limits that keep a run meaningful
// (docs/scenes.md "The slider's scene").
#include "io/slider_scene_parser.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <set>

#include "io/toml_section.hpp"

namespace rotorsweep::io {

namespace {

using ensemble::SliderScene;

const std::map<std::string, std::set<std::string>> slider_keys{
    {"slider",
     {"columns", "rows", "spacing", "moment", "inertia", "damping", "dynamics", "tilt", "shift_x",
      "shift_y"}},
    {"substrate", {"columns", "rows", "moment", "nodes_per_depth", "angle", "extent"}},
    {"drive", {"speed", "rest", "end", "periods", "relax_periods"}},
    {"sweep", {"separation"}},
    {"initial", {"kind", "noise", "replicas", "seed", "angles"}},
    {"observables",
     {"samples_per_period", "series", "angles", "energies", "field", "sublattices", "torques", "forces"}},
    {"numerics", {"stepper", "rtol", "atol", "max_steps", "device", "linear_solver", "global_error"}},
    {"output", {"path"}},
};

/// The most members a slider plan may have, and the most sample points of its series over the speeds.
constexpr std::size_t max_slider_members = 10000000;
constexpr double max_sample_points = 1e7;

bool positive(double x) { return x > 0; }
bool within_pi(double x) { return std::fabs(x) <= 3.141592653589793; }

bool up_to_100(long long v) { return v >= 1 && v <= 100; }
bool up_to_1024(long long v) { return v >= 1 && v <= 1024; }
bool up_to_100000(long long v) { return v >= 1 && v <= 100000; }

/// A count from 1 to 100 (small) or to 100000.
std::size_t count(const Section& s, std::string_view k, std::size_t fallback, bool small) {
  return std::size_t(s.integer(k, (long long)fallback,
                               small ? "an integer from 1 to 100" : "an integer from 1 to 100000",
                               small ? up_to_100 : up_to_100000));
}

/// slider.columns and slider.rows: integers from 1 to 1024, or lists of them paired one to one (a single
/// value goes with every value of the other list); each size has at least two rotors (the memory a size
/// needs is checked before a run: dense stage solves take O(n²) per lane block, matrix-free ones O(n)).
std::vector<ensemble::SliderSize> read_sizes(const Section& slider) {
  const auto read = [&](std::string_view k) {
    std::vector<std::size_t> values;
    const toml::node* node = slider.find(k);
    if (!node) return std::vector<std::size_t>{7};
    const std::string what = "an integer from 1 to 1024, or a non-empty list of them";
    const auto take = [&](const toml::node& n) {
      const auto v = n.value_exact<long long>();
      if (!n.is_integer() || !v || !up_to_1024(*v))
        fail(slider.key(k), "must be " + what + " (got " + describe(n) + ")");
      values.push_back(std::size_t(*v));
    };
    if (const auto* list = node->as_array()) {
      if (list->empty()) fail(slider.key(k), "must be " + what);
      for (const auto& element : *list) take(element);
    } else {
      take(*node);
    }
    return values;
  };
  const auto columns = read("columns"), rows = read("rows");
  if (columns.size() > 1 && rows.size() > 1 && columns.size() != rows.size())
    fail(slider.key("rows"), "must be one integer or a list as long as slider.columns (" +
                                 std::to_string(columns.size()) + " values, paired with them)");
  std::vector<ensemble::SliderSize> sizes;
  for (std::size_t i = 0; i < std::max(columns.size(), rows.size()); ++i) {
    const ensemble::SliderSize size{columns[columns.size() > 1 ? i : 0], rows[rows.size() > 1 ? i : 0]};
    if (size.rotors() < 2) fail(slider.key("columns"), "and slider.rows must give at least 2 rotors");
    if (std::find(sizes.begin(), sizes.end(), size) != sizes.end())
      fail(slider.key("columns"), "and slider.rows give the size " + std::to_string(size.columns) + " × " +
                                      std::to_string(size.rows) + " twice");
    sizes.push_back(size);
  }
  return sizes;
}

/// initial.angles with kind "given": rows × columns angles of the scene's single size, row-major
/// from the row with the smallest y; one replica (every replica would start alike).
void read_given_angles(const Section& initial, const toml::node* angles, SliderScene& scene) {
  if (angles && scene.start != ensemble::SliderStart::given)
    fail(initial.key("angles"), "is only used with initial.kind = \"given\"");
  if (scene.start != ensemble::SliderStart::given) return;
  if (scene.sizes.size() > 1)
    fail(initial.key("angles"), "needs a single slider size (each size has its own number of rotors)");
  const ensemble::SliderSize size = scene.sizes.front();
  const std::string what = "a list of slider.rows × slider.columns = " + std::to_string(size.rotors()) +
                           " angles (rad), row by row from the row with the smallest y, each row from the "
                           "smallest x";
  const toml::node& node =
      angles ? *angles : initial.require("angles", what + " with initial.kind = \"given\"");
  const auto* list = node.as_array();
  if (!list || list->size() != size.rotors())
    fail(initial.key("angles"),
         "must be " + what + (list ? " (got " + std::to_string(list->size()) + ")" : std::string()));
  for (const auto& a : *list)
    scene.given_angles.push_back(Section::checked_number(a, initial.key("angles"),
                                                         "a number from -1e4 to 1e4 (rad)",
                                                         [](double x) { return std::fabs(x) <= 1e4; }));
  if (scene.replicas != 1)
    fail(initial.key("replicas"),
         "must be 1 with initial.kind = \"given\" (every replica would start alike)");
}

/// drive.end (s, one speed) or drive.periods (whole substrate periods slid after the rest, at every
/// speed); several speeds need drive.periods.
void read_run_length(const Section& drive, SliderScene& scene) {
  const bool several = scene.speeds.size() > 1;
  if (drive.find("periods")) {
    if (drive.find("end")) fail(drive.key("periods"), "and drive.end both give the run's length: give one");
    scene.periods = std::size_t(drive.integer("periods", 1,
                                              "an integer from 1 to 10000 (substrate periods slid after "
                                              "drive.rest, at every speed)",
                                              [](long long p) { return p >= 1 && p <= 10000; }));
    scene.end = scene.rest + double(scene.periods) * scene.spacing / scene.speed;
    return;
  }
  if (several && drive.find("end"))
    fail(drive.key("end"),
         "gives each of several drive.speed values a different number of substrate periods: give "
         "drive.periods (whole periods slid after drive.rest, at every speed) instead");
  if (several)
    fail(drive.key("periods"),
         "is needed with several drive.speed values: an integer from 1 to 10000 (whole substrate periods "
         "slid after drive.rest, at every speed)");
  scene.end = drive.number("end", scene.end, "a number > 0 (s)", positive);
  const double period = scene.spacing / scene.speed;
  if (scene.end - scene.rest < period * (1 - 1e-9))
    fail(drive.key("end"), "must leave at least one substrate period a/v = " + number_text(period) +
                               " s of sliding after drive.rest (the friction is a mean over whole periods)");
  if (scene.end - scene.rest > 1e4 * scene.spacing / scene.speed)
    fail(drive.key("end"), "gives more than 10000 substrate periods of sliding");
}

/// drive.relax_periods: whole periods of sliding before the friction is averaged, fewer than the run
/// slides (after read_run_length).
void read_relax_periods(const Section& drive, SliderScene& scene) {
  if (!drive.find("relax_periods")) return;
  const double period = scene.spacing / scene.speed;
  const auto sliding = scene.periods > 0 ? scene.periods
                                         : std::size_t(std::floor((scene.end - scene.rest) / period + 1e-9));
  const std::string what = "an integer from 0 to " + std::to_string(sliding - 1) +
                           ": whole substrate periods of sliding before the friction is averaged, fewer "
                           "than the " + std::to_string(sliding) + " the run slides";
  const long long relax =
      drive.integer("relax_periods", 1, what, [](long long p) { return p >= 0 && p < 10000; });
  if (std::size_t(relax) >= sliding) fail(drive.key("relax_periods"), "must be " + what);
  scene.relax_periods = std::size_t(relax);
}

/// The rest and the sample points a member's series hold: at most 10⁴ substrate periods of rest at the
/// fastest speed (as of sliding), and at most 10⁷ points over the speeds (the series' columns × speeds).
void check_samples(const SliderScene& scene) {
  const double fastest = *std::max_element(scene.speeds.begin(), scene.speeds.end());
  const double rest_periods = scene.rest * fastest / scene.spacing;
  if (rest_periods > 1e4)
    fail("drive.rest", "is " + number_text(rest_periods) + " substrate periods a/v at drive.speed " +
                           number_text(fastest) + " m/s (slider.spacing " + number_text(scene.spacing) +
                           " m); at most 10000 are allowed");
  double points = 0;  // stops per member: the rest's and the sliding's, and the start
  for (const double v : scene.speeds) {
    const double period = scene.spacing / v;
    const double sliding = scene.periods > 0 ? double(scene.periods) : (scene.end - scene.rest) / period;
    points = std::max(points, (scene.rest / period + sliding) * double(scene.samples_per_period) + 2);
  }
  if (points * double(scene.speeds.size()) > max_sample_points)
    fail("observables.samples_per_period",
         "gives " + number_text(points) + " sample points per member" +
             (scene.speeds.size() > 1 ? " at each of " + std::to_string(scene.speeds.size()) + " speeds"
                                      : "") +
             " (drive.rest and the periods slid, at " + std::to_string(scene.samples_per_period) +
             " per period); at most " + number_text(max_sample_points) + " are allowed");
}

/// The plan is too large: names the axis with the most values, and every axis's size.
[[noreturn]] void fail_too_many_members(const SliderScene& scene) {
  const std::pair<const char*, std::size_t> axes[] = {{"slider.columns", scene.sizes.size()},
                                                      {"drive.speed", scene.speeds.size()},
                                                      {"slider.damping", scene.dampings.size()},
                                                      {"sweep.separation", scene.separations.size()},
                                                      {"initial.replicas", scene.replicas}};
  std::size_t largest = 0;
  double count = 1;
  std::string product;
  for (std::size_t i = 0; i < std::size(axes); ++i) {
    if (axes[i].second > axes[largest].second) largest = i;
    count *= double(axes[i].second);
    product += (i ? " × " : "") + std::string(axes[i].first) + " " + std::to_string(axes[i].second);
  }
  fail(axes[largest].first, "the plan has " + number_text(count) + " members (" + product + "); at most " +
                                std::to_string(max_slider_members) + " are allowed");
}

SliderScene read_slider_scene(const toml::table& root) {
  check_sections(root, slider_keys);
  SliderScene scene;
  const Section slider = section(root, "slider");
  scene.sizes = read_sizes(slider);
  scene.spacing = slider.number("spacing", scene.spacing, "a number > 0 (lattice constant a, m)", positive);
  scene.moment = slider.number("moment", scene.moment, "a number > 0 (A m²)", positive);
  scene.inertia = slider.number("inertia", scene.inertia, "a number > 0 (kg m²)", positive);
  scene.dampings = grid(slider, "damping", "> 0 (kg m²/s)", positive, scene.dampings);
  scene.damping = scene.dampings.front();
  scene.overdamped = slider.choice("dynamics", "inertial", {"inertial", "overdamped"}) == "overdamped";
  scene.tilt =
      slider.number("tilt", scene.tilt, "a number from -π to π (rad; the grid turned about z)", within_pi);
  const auto shift = [&](std::string_view k) {
    return slider.number(k, 0.0, "a number from -1 to 1 (m)", [](double x) { return std::fabs(x) <= 1.0; });
  };
  scene.shift_x = shift("shift_x");
  scene.shift_y = shift("shift_y");

  const Section substrate = section(root, "substrate");
  scene.substrate_infinite = substrate.choice("extent", "finite", {"finite", "infinite"}) == "infinite";
  if (scene.substrate_infinite) {
    for (const char* key : {"columns", "rows"})
      if (substrate.find(key))
        fail(substrate.key(key),
             "has no meaning with substrate.extent = \"infinite\" (a moment at every lattice "
             "point); leave it out, or take substrate.extent = \"finite\"");
  } else {
    scene.substrate_columns = count(substrate, "columns", scene.substrate_columns, false);
    scene.substrate_rows = count(substrate, "rows", scene.substrate_rows, false);
    // box sums make a large lattice cheap; a turned slider's tracks take direct sums over every moment
    const double magnets = double(scene.substrate_columns) * double(scene.substrate_rows);
    const double most = scene.tilt != 0.0 ? 1e6 : 1e8;
    if (magnets > most)
      fail(substrate.key("columns"),
           "and substrate.rows give " + number_text(magnets) + " magnets; at most " + number_text(most) +
               " are allowed" +
               (scene.tilt != 0.0 ? " under a turned slider (every node of its tables sums over all of them)"
                                  : "") +
               " (substrate.extent = \"infinite\" has no edges at all)");
  }
  scene.substrate_moment =
      substrate.number("moment", scene.substrate_moment, "a number > 0 (A m²)", positive);
  scene.nodes_per_depth = substrate.number("nodes_per_depth", scene.nodes_per_depth,
                                           "a number from 2 to 1000 (table nodes per separation h)",
                                           [](double x) { return x >= 2 && x <= 1000; });
  scene.substrate_angle =
      substrate.number("angle", scene.substrate_angle,
                       "a number from -π to π (rad; the moments (cos φ, 0, −sin φ))", within_pi);

  const Section drive = section(root, "drive");
  scene.speeds = grid(drive, "speed", "> 0 (m/s)", positive, scene.speeds);
  scene.speed = scene.speeds.front();
  scene.rest = drive.number("rest", scene.rest, "a number >= 0 (s)", [](double x) { return x >= 0; });
  read_run_length(drive, scene);
  read_relax_periods(drive, scene);

  scene.separations = grid(section(root, "sweep"), "separation", "> 0 (layer separation h, m)", positive);
  for (const double h : scene.separations)
    if (h < 0.05 * scene.spacing)
      fail("sweep.separation", "must be at least 0.05 a = " + number_text(0.05 * scene.spacing) +
                                   " m (closer, the point dipoles are no model of magnets)");

  const Section initial = section(root, "initial");
  const toml::node* angles = initial.find("angles");
  const std::string kind = initial.choice("kind", angles ? "given" : "alternating_rows",
                                          {"alternating_rows", "aligned", "random", "given"});
  scene.start = kind == "aligned"  ? ensemble::SliderStart::aligned
                : kind == "random" ? ensemble::SliderStart::random
                : kind == "given"  ? ensemble::SliderStart::given
                                   : ensemble::SliderStart::alternating_rows;
  scene.noise = initial.number("noise", scene.noise, "a number from 0 to 2π (full width, rad)",
                               [](double x) { return x >= 0 && x <= 6.283185307179586; });
  scene.replicas = count(initial, "replicas", scene.replicas, false);
  scene.seed =
      std::uint64_t(initial.integer("seed", 1, "an integer >= 0", [](long long s) { return s >= 0; }));
  read_given_angles(initial, angles, scene);

  const Section observables = section(root, "observables");
  scene.samples_per_period = count(observables, "samples_per_period", scene.samples_per_period, false);
  scene.series = observables.boolean("series", scene.series);
  scene.angles = observables.boolean("angles", scene.angles);
  scene.energies = observables.boolean("energies", scene.energies);
  scene.field = observables.boolean("field", scene.field);
  scene.sublattices = observables.boolean("sublattices", scene.sublattices);
  scene.torques = observables.boolean("torques", scene.torques);
  scene.forces = observables.boolean("forces", scene.forces);
  for (const auto& [key, asked] : scene.optional_series())
    if (asked && !scene.series)
      fail(observables.key(key), "is a time series: it needs observables.series = true");
  for (const auto& [key, asked] : {std::pair{"angles", scene.angles}, {"torques", scene.torques}})
    if (asked && scene.sizes.size() > 1)
      fail(observables.key(key), "needs a single slider size (each size has its own number of rotors)");

  const Section numerics = section(root, "numerics");
  scene.stepper = read_stepper(numerics, ensemble::default_slider_stepper_name);
  scene.rtol = numerics.number("rtol", scene.rtol, rtol_range, valid_rtol);
  scene.atol = numerics.number("atol", scene.atol, atol_range, valid_atol);
  scene.max_steps = read_max_steps(numerics);
  scene.device = numerics.choice("device", "cpu", {"cpu", "gpu"}) == "gpu" ? ensemble::Device::gpu
                                                                           : ensemble::Device::cpu;
  const std::string solver = numerics.choice("linear_solver", "auto", {"auto", "dense", "krylov"});
  scene.linear_solver = solver == "dense"    ? ensemble::SliderSolver::dense
                        : solver == "krylov" ? ensemble::SliderSolver::krylov
                                             : ensemble::SliderSolver::automatic;
  scene.shadow_runs = numerics.choice("global_error", "shadow", {"shadow", "local"}) == "shadow";

  const Section output = section(root, "output");
  scene.output_path = output.text("path", scene.output_path);
  if (double(scene.sizes.size()) * double(scene.speeds.size()) * double(scene.dampings.size()) *
          double(scene.separations.size()) * double(scene.replicas) >
      double(max_slider_members))
    fail_too_many_members(scene);
  check_samples(scene);
  check_slider_device(scene);
  return scene;
}

}  // namespace

void check_slider_device(const ensemble::SliderScene& scene) {
  if (scene.device != ensemble::Device::gpu) return;
  if (scene.linear_solver == ensemble::SliderSolver::krylov)
    fail("numerics.linear_solver",
         "\"krylov\" runs on the CPU (conjugate gradients with FFTs); with numerics.device = \"gpu\" it must "
         "be \"dense\" or \"auto\" (which is dense there)");
  if (kernels::stepper_family(scene.stepper) == kernels::StepperFamily::rosenbrock) return;
  std::string allowed;
  for (kernels::StepperId id = 0; id < kernels::stepper_names.size(); ++id)
    if (kernels::stepper_family(id) == kernels::StepperFamily::rosenbrock)
      allowed += (allowed.empty() ? "" : ", ") + std::string(kernels::stepper_names[id]);
  fail("numerics.stepper", "must be a linearly implicit stepper (" + allowed +
                               ") with numerics.device = \"gpu\" (the slider's GPU kernels); \"" +
                               std::string(kernels::stepper_names[scene.stepper]) +
                               "\" runs with numerics.device = \"cpu\"");
}

ensemble::SliderScene parse_slider_scene_text(std::string_view text, std::string_view source) {
  SliderScene scene = read_slider_scene(parse_toml(text, source));
  scene.text = std::string(text);
  return scene;
}

ensemble::SliderScene parse_slider_scene_file(const std::string& path) {
  return parse_slider_scene_text(read_scene_file(path), path);
}

}  // namespace rotorsweep::io
