// D converges as rtol → 1e-12 outside CP (N = 20, g = 0.0011, A = 1 AFM and A = 11 FM): each
// hundredfold tightening moves D by less, and rtol 1e-10 agrees with 1e-12 to 1e-9 with rodas4 and
// to 3e-9 with rodas4p2 (1.4e-9 measured); with both step controllers.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <utility>

#include "ensemble/rows/sweep.hpp"
#include "io/scene_parser.hpp"

using namespace rotorsweep::ensemble;

TEST_CASE("D converges as the tolerance tightens outside CP", "[ensemble][tolerance]") {
  const std::string controller = GENERATE(std::string("integral"), std::string("pi"));
  const auto [stepper, agreement] =
      GENERATE(std::make_pair(std::string("rodas4"), 1e-9), std::make_pair(std::string("rodas4p2"), 3e-9));
  INFO("controller " << controller << ", stepper " << stepper);
  const Scene scene = rotorsweep::io::parse_scene_text(
      "[model]\nrows = 20\n[drive]\ng = [0.0011]\n[sweep]\nA = [1.0, 11.0]\n[initial]\nkinds = [\"AFM\"]\n"
      "[numerics]\nstepper = \"" +
          stepper +
          "\"\nrtol = [1e-6, 1e-8, 1e-10, 1e-12]\natol = [1e-9, 1e-11, 1e-13, 1e-15]\ncontroller = \"" +
          controller + "\"\nglobal_error = \"local\"\n",  // no flags asked: no symmetry probes
      "tolerance.toml");
  const auto members = plan_members(scene);
  const auto outcome = run_sweep(scene, members, {.threads = 2});
  for (std::size_t a = 0; a < 2; ++a) {
    // members are variant-major: the same A (and noise draw) at rtol 1e-6, 1e-8, 1e-10, 1e-12
    const double reference = outcome.results[6 + a].dissipation();
    double previous = INFINITY;
    for (std::size_t v = 0; v < 3; ++v) {
      const double deviation = std::fabs(outcome.results[2 * v + a].dissipation() / reference - 1);
      INFO("A = " << members[a].A << " rtol " << members[2 * v + a].rtol << " deviation " << deviation);
      CHECK(deviation < previous);
      previous = deviation;
    }
    CHECK(previous < agreement);
  }
}
