// Uses rotorsweep as a library: parses a scene from text, sweeps its members, prints D per member
// beside the paper's value, and J(A) of the quasi-static CP friction law (docs/model.md §3–5).
#include <cstdio>

#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/sweep.hpp"
#include "io/scene_parser.hpp"
#include "landscape/bifurcation_curves.hpp"
#include "landscape/jump_friction.hpp"

int main() {
  using namespace rotorsweep;
  const ensemble::Scene scene = io::parse_scene_text(R"(
[model]
rows = 20
[drive]
g = [0.0011]
[sweep]
A = [1.0, 11.0]
[initial]
kinds = ["FM"]
replicas = 1
[schedule]
relax_periods = 2
average_periods = 2
[numerics]
rtol = 1e-8
atol = 1e-11
)",
                                                     "example");
  const auto members = ensemble::plan_members(scene);
  const auto outcome = ensemble::run_sweep(scene, members, {.threads = 1});
  const double paper[] = {2.018948e-3, 1.654868e-1};  // the paper's table, FM starts
  for (std::size_t i = 0; i < members.size(); ++i)
    std::printf("A = %4.1f  D = %.6e  paper %.6e\n", members[i].A, outcome.results[i].dissipation(),
                paper[i]);
  std::printf("J(A_-) = %.12f at A_- = %.12f\n", landscape::jump_friction(landscape::A_minus()),
              landscape::A_minus());
  return 0;
}
