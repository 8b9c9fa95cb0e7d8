// How the GPU backend lays members on threads (ensemble/gpu/gpu_plan.hpp, gpu_launch.hpp), on the host:
// which scenes run in registers or on teams, the team's size by N (and the slider's by its rotors), a
// team's scratch and the chunk's size, the environment's settings and their errors, the file's label.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "ensemble/gpu/gpu_backend.hpp"
#include "ensemble/gpu/gpu_executor.hpp"
#include "ensemble/gpu/gpu_launch.hpp"
#include "ensemble/gpu/gpu_plan.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/sweep.hpp"
#include "io/scene_parser.hpp"
#include "io/slider_scene_parser.hpp"
#include "support/scoped_variable.hpp"

using namespace rotorsweep;

namespace {

using testing::ScopedVariable;

ensemble::Scene scene_of(const std::string& model, const std::string& rest = "") {
  return io::parse_scene_text("[model]\n" + model + "\n[drive]\ng = [0.01]\n[sweep]\nA = [1, 8]\n" + rest,
                              "launch");
}

/// An executor of the environment's launch as it is now (gpu_executor() reads it once per process).
ensemble::GpuExecutor from_environment() { return ensemble::GpuExecutor(ensemble::gpu_launch()); }

std::string launch_error() {
  try {
    ensemble::gpu_launch();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("teams run rows at T > 0 or with a linearly implicit stepper, coupling tables too",
          "[gpu_launch]") {
  CHECK(ensemble::gpu_teams_fit(scene_of("rows = 20")));
  CHECK(ensemble::gpu_teams_fit(scene_of("rows = 20", "[disorder]\nA = 1e-3\n")));
  CHECK(ensemble::gpu_teams_fit(scene_of("rows = 20", "[observables]\nestimators = true\nmoments = true\n")));
  for (const char* stepper : {"rodas4", "ros2", "rodas4p2", "rodas5p"})
    CHECK(ensemble::gpu_teams_fit(
        scene_of("rows = 20", std::string("[numerics]\nstepper = \"") + stepper + "\"\n")));
  CHECK_FALSE(ensemble::gpu_teams_fit(scene_of("rows = 20", "[numerics]\nstepper = \"dopri5\"\n")));
  CHECK(ensemble::gpu_teams_fit(scene_of("rows = 20\ncouplings = \"dipolar\"\nrange = 2")));
  CHECK(ensemble::gpu_teams_fit(scene_of("rows = 20\nboundary = \"open\"")));
  CHECK_FALSE(ensemble::gpu_teams_fit(
      scene_of("rows = 20\ncouplings = \"dipolar\"\nrange = 2", "[numerics]\nstepper = \"dopri5\"\n")));
  CHECK(ensemble::gpu_teams_fit(scene_of("rows = 20", "[thermal]\ntemperature = 0.01\n")));
  CHECK(ensemble::gpu_teams_fit(scene_of(
      "rows = 20", "[thermal]\ntemperature = 0.01\n[numerics]\nstepper = \"dopri5\"\n")));  // Langevin
  CHECK(ensemble::gpu_teams_fit(
      scene_of("rows = 20\ncouplings = \"dipolar\"\nrange = 2", "[thermal]\ntemperature = 0.01\n")));
  CHECK(ensemble::gpu_teams_fit(scene_of("rows = 20", "[observables]\nrow_profiles = true\n")));
}

TEST_CASE("a team has two or three rows per thread, up to a warp; N up to 4 runs a member per thread",
          "[gpu_launch]") {
  const auto scene = scene_of("rows = 20");
  const ensemble::GpuLaunch launch;
  for (const auto& [rows, team] :
       {std::pair{2u, 1u}, std::pair{4u, 1u}, std::pair{6u, 2u}, std::pair{8u, 4u}, std::pair{20u, 8u},
        std::pair{48u, 16u}, std::pair{96u, 32u}, std::pair{1024u, 32u}})
    CHECK(ensemble::gpu_team_size(scene, rows, launch) == team);
  for (std::size_t rows = 6; rows <= 96; rows += 2) {
    const unsigned team = ensemble::gpu_team_size(scene, rows, launch);
    INFO("N = " << rows << ", team " << team);
    CHECK((team & (team - 1)) == 0);
    CHECK((rows + team - 1) / team <= 3);                 // at most three rows per thread
    CHECK((team == 2 || (rows + team - 1) / team >= 2));  // and no smaller team would do
  }
  CHECK(ensemble::gpu_team_size(scene_of("rows = 20\nboundary = \"open\""), 1024, launch) == 32);
  CHECK(ensemble::gpu_team_size(
            scene_of("rows = 20\nboundary = \"open\"", "[numerics]\nstepper = \"dopri5\"\n"), 1024, launch) ==
        1);
  CHECK(ensemble::gpu_team_size(scene_of("rows = 20", "[thermal]\ntemperature = 0.01\n"), 64, launch) == 32);
  CHECK(ensemble::gpu_team_size(scene_of("rows = 20", "[observables]\nrow_profiles = true\n"), 64, launch) ==
        32);
}

TEST_CASE("the environment sets the launch; a bad value is one error naming it", "[gpu_launch]") {
  const auto plain = ensemble::gpu_launch();
  CHECK(plain.threads_per_block == 128);
  CHECK(plain.blocks == 0);
  CHECK(plain.team == 0);
  CHECK(plain.scratch == ensemble::GpuScratch::automatic);
  {
    const ScopedVariable team("ROTORSWEEP_GPU_TEAM", "16");
    const ScopedVariable scratch("ROTORSWEEP_GPU_SCRATCH", "global");
    const auto launch = ensemble::gpu_launch();
    CHECK(launch.team == 16);
    CHECK(launch.scratch == ensemble::GpuScratch::global);
    CHECK(ensemble::gpu_team_size(scene_of("rows = 2"), 2, launch) == 16);  // asked for, even at N = 2
    CHECK(ensemble::gpu_team_size(scene_of("rows = 20\ncouplings = \"dipolar\"\nrange = 2"), 20, launch) ==
          16);
    CHECK(ensemble::gpu_team_size(scene_of("rows = 20", "[numerics]\nstepper = \"dopri5\"\n"), 20, launch) ==
          1);  // no team form: a member per thread whatever is asked
  }
  for (const char* bad : {"3", "64", "2048", "eight", "0", "96"}) {  // 64 … 1024: no block teams
    const ScopedVariable team("ROTORSWEEP_GPU_TEAM", bad);
    INFO(bad);
    CHECK_THAT(launch_error(), Catch::Contains("ROTORSWEEP_GPU_TEAM"));
  }
  {
    const ScopedVariable team("ROTORSWEEP_GPU_TEAM", "12");
    CHECK_THAT(launch_error(), Catch::Contains("allowed: 1, 2, 4, 8, 16 or 32"));
  }
  {
    const ScopedVariable scratch("ROTORSWEEP_GPU_SCRATCH", "local");
    CHECK_THAT(launch_error(),
               Catch::Contains("ROTORSWEEP_GPU_SCRATCH") && Catch::Contains("shared, global"));
  }
  {
    const ScopedVariable block("ROTORSWEEP_GPU_BLOCK", "48");
    CHECK_THAT(launch_error(), Catch::Contains("ROTORSWEEP_GPU_BLOCK") && Catch::Contains("multiple of 32"));
  }
}

TEST_CASE("a member on a team has no per-thread row limit; on one thread it has", "[gpu_launch]") {
  const auto scene = scene_of("rows = 20");
  CHECK(from_environment().max_rows(scene) == 65536);
  const ScopedVariable team("ROTORSWEEP_GPU_TEAM", "1");
  const std::size_t per_thread = from_environment().max_rows(scene);
  CHECK(per_thread >= 100);
  CHECK(per_thread < 65536);
}

TEST_CASE("a coupling table on a team holds up to 4096 rows, on one thread what its dense matrices leave",
          "[gpu_launch]") {
  const auto scene = scene_of("rows = 20\ncouplings = \"dipolar\"\nrange = \"all\"\nboundary = \"open\"");
  CHECK(from_environment().max_rows(scene) == 4096);
  const ScopedVariable team("ROTORSWEEP_GPU_TEAM", "1");
  const std::size_t per_thread = from_environment().max_rows(scene);
  CHECK(per_thread >= 49);  // the experiment's slider, as rows
  CHECK(per_thread < 91);   // N² values of 8192
}

TEST_CASE("the result file's device says how many threads run a member", "[gpu_launch]") {
  // N = 20 runs in registers where the build compiled a shape that holds it (ROTORSWEEP_GPU_REGISTER_SHAPES)
  const auto teams_of_8 = [](const ensemble::Scene& s) {
    return ensemble::choose_register_shape(ensemble::gpu_register_shapes(), s, 20, {})
               ? std::string("8 threads per member, rows in registers")
               : std::string("8 threads per member");
  };
  auto scene = scene_of("rows = 20");
  scene.device = ensemble::Device::gpu;
  CHECK_THAT(from_environment().label(scene),
             Catch::StartsWith("gpu (") && Catch::EndsWith("; " + teams_of_8(scene) + ")"));
  auto pair = scene_of("rows = [2, 20]");
  pair.device = ensemble::Device::gpu;
  CHECK_THAT(from_environment().label(pair),
             Catch::EndsWith("; 1 thread per member at N = 2; " + teams_of_8(pair) + " at N = 20)"));
  const ScopedVariable eight("ROTORSWEEP_GPU_TEAM", "8");  // a team, whatever the build compiled
  CHECK_THAT(from_environment().label(scene), Catch::EndsWith("; 8 threads per member)"));
  auto coupled = scene_of("rows = 20\ncouplings = \"dipolar\"\nrange = 2");
  coupled.device = ensemble::Device::gpu;
  CHECK_THAT(from_environment().label(coupled), Catch::EndsWith("; 8 threads per member)"));
  auto explicit_stepper = scene_of("rows = 20", "[numerics]\nstepper = \"dopri5\"\n");
  explicit_stepper.device = ensemble::Device::gpu;
  CHECK_THAT(from_environment().label(explicit_stepper), Catch::EndsWith("; 1 thread per member)"));
}

TEST_CASE("a register kernel runs the T = 0 nearest-neighbour scenes whose N a compiled shape holds",
          "[gpu_launch]") {
  using ensemble::RegisterShape;
  const std::vector<RegisterShape> shapes{{1, 2, false}, {4, 2, false},  {8, 3, false},
                                          {8, 3, true},  {16, 4, false}, {32, 4, false}};
  const auto chosen = [&](const ensemble::Scene& scene, std::size_t rows) {
    return ensemble::choose_register_shape(shapes, scene, rows, {});
  };
  const auto uniform = scene_of("rows = 20", "[numerics]\nglobal_error = \"local\"\n");
  CHECK(chosen(uniform, 2) == RegisterShape{1, 2, false});
  CHECK(chosen(uniform, 4) == RegisterShape{4, 2, false});  // fewest slots in all, then most lanes
  CHECK(chosen(uniform, 8) == RegisterShape{4, 2, false});
  CHECK(chosen(uniform, 10) == RegisterShape{8, 3, false});
  CHECK(chosen(uniform, 24) == RegisterShape{8, 3, false});
  CHECK(chosen(uniform, 26) == RegisterShape{16, 4, false});
  CHECK(chosen(uniform, 128) == RegisterShape{32, 4, false});
  CHECK_FALSE(chosen(uniform, 130));  // beyond every shape: teams
  const auto disordered = scene_of("rows = 20", "[disorder]\nA = 1e-3\n");
  CHECK(chosen(disordered, 20) == RegisterShape{8, 3, true});
  CHECK_FALSE(chosen(disordered, 2));  // no disordered shape of one lane
  // uniform rows with shadow runs may run symmetry probes, whose rerun chunks carry A's deviations
  const auto probed = scene_of("rows = 20");
  CHECK(chosen(probed, 20) == RegisterShape{8, 3, true});
  CHECK_FALSE(chosen(probed, 2));
  CHECK(chosen(scene_of("rows = 20", "[disorder]\nA = 1e-5\n"), 20) == RegisterShape{8, 3, true});
  // what a register kernel does not hold runs on teams or threads
  CHECK_FALSE(chosen(scene_of("rows = 20", "[thermal]\ntemperature = 0.01\n"), 20));
  CHECK_FALSE(chosen(scene_of("rows = 20\ncouplings = \"dipolar\"\nrange = 2"), 20));
  CHECK_FALSE(chosen(scene_of("rows = 20", "[observables]\nrow_profiles = true\n"), 20));
  CHECK_FALSE(chosen(scene_of("rows = 20", "[observables]\nenergy = true\n"), 20));
  CHECK_FALSE(chosen(scene_of("rows = 20", "[numerics]\nstepper = \"dopri5\"\n"), 20));
  CHECK(chosen(scene_of("rows = 20", "[observables]\nslips = false\n"), 20));
  ensemble::GpuLaunch team;
  team.team = 8;  // ROTORSWEEP_GPU_TEAM asks for a team
  CHECK_FALSE(ensemble::choose_register_shape(shapes, uniform, 20, team));
}

TEST_CASE("a register shape with every quadrature runs the scenes asking for W, S, H or the moments",
          "[gpu_launch]") {
  using ensemble::RegisterShape;
  const std::vector<RegisterShape> shapes{{8, 3, false, 6, 3, true}, {8, 3, false, 6, 3, false}};
  // no shadow runs, so no symmetry probes (which would ask for a disordered shape)
  const auto uniform = [](const char* observables) {
    return scene_of("rows = 20", std::string(observables) + "[numerics]\nglobal_error = \"local\"\n");
  };
  const auto chosen = [&](const char* observables) {
    return ensemble::choose_register_shape(shapes, uniform(observables), 20, {});
  };
  // R and ρ̄ alone: the shape that carries no more (fewer registers)
  CHECK(chosen("") == RegisterShape{8, 3, false, 6, 3, false});
  for (const char* asks : {"[observables]\nenergy = true\n", "[observables]\nestimators = true\n",
                           "[observables]\nmoments = true\n"}) {
    INFO(asks);
    CHECK(chosen(asks) == RegisterShape{8, 3, false, 6, 3, true});
    CHECK_FALSE(ensemble::choose_register_shape(std::vector<RegisterShape>{{8, 3, false, 6, 3, false}},
                                                uniform(asks), 20, {}));
  }
  CHECK(RegisterShape{.every_quadrature = true}.carriable() == kernels::all_integrals);
}

TEST_CASE("a register shape with six stage vectors runs the six-stage tableaus, eight the rest",
          "[gpu_launch]") {
  using ensemble::RegisterShape;
  const std::vector<RegisterShape> shapes{{8, 3, false, 8}, {8, 3, false, 6}, {32, 4, false, 8}};
  const auto chosen = [&](const char* stepper, std::size_t rows) {
    const auto scene = scene_of("rows = 20", std::string("[numerics]\nstepper = \"") + stepper +
                                                 "\"\nglobal_error = \"local\"\n");
    return ensemble::choose_register_shape(shapes, scene, rows, {});
  };
  CHECK(chosen("rodas4", 20) == RegisterShape{8, 3, false, 6});
  CHECK(chosen("rodas4p2", 20) == RegisterShape{8, 3, false, 6});
  CHECK(chosen("ros2", 20) == RegisterShape{8, 3, false, 6});
  CHECK(chosen("rodas5p", 20) == RegisterShape{8, 3, false, 8});
  CHECK(chosen("rodas4p2", 100) == RegisterShape{32, 4, false, 8});  // no six-stage shape holds N = 100
  CHECK_FALSE(ensemble::choose_register_shape(std::vector<RegisterShape>{{8, 3, false, 6}},
                                              scene_of("rows = 20", "[numerics]\nstepper = \"rodas5p\"\n"),
                                              20, {}));
}

TEST_CASE("a slider member's team: two or three rotors a thread, at most a warp; the file's label",
          "[ensemble][gpu][slider]") {
  const ensemble::GpuLaunch automatic;
  CHECK(ensemble::gpu_slider_team_size({7, 7}, automatic) == 32);
  CHECK(ensemble::gpu_slider_team_size({3, 2}, automatic) == 2);
  CHECK(ensemble::gpu_slider_team_size({4, 4}, automatic) == 8);
  CHECK(ensemble::gpu_slider_team_size({20, 20}, automatic) == 32);
  ensemble::GpuLaunch asked;
  asked.team = 8;
  CHECK(ensemble::gpu_slider_team_size({7, 7}, asked) == 8);
  for (const unsigned team : {1u, 64u}) {
    asked.team = team;
    CHECK_THROWS_WITH(ensemble::gpu_slider_team_size({7, 7}, asked),
                      Catch::Contains("ROTORSWEEP_GPU_TEAM = " + std::to_string(team)) &&
                          Catch::Contains("2, 4, 8, 16 or 32"));
  }
  const auto scene = io::parse_slider_scene_text(
      "[slider]\ncolumns = [7, 3]\nrows = [7, 2]\n[sweep]\nseparation = [8e-3]\n[numerics]\ndevice = "
      "\"gpu\"\n",
      "label");
  CHECK_THAT(from_environment().label(scene),
             Catch::Contains("threads per member: 32 at 7 × 7, 2 at 3 × 2"));
  const ScopedVariable team("ROTORSWEEP_GPU_TEAM", "16");
  CHECK_THAT(from_environment().label(scene), Catch::Contains("16 at 7 × 7, 16 at 3 × 2"));
}

TEST_CASE("under mpirun or srun each rank of a node takes the GPU of its local rank", "[gpu_launch]") {
  {
    const ScopedVariable open_mpi("OMPI_COMM_WORLD_LOCAL_RANK", "");
    const ScopedVariable slurm("SLURM_LOCALID", "");
    CHECK(ensemble::gpu_device_index(4) == 0);  // one process: the first device
  }
  {
    const ScopedVariable open_mpi("OMPI_COMM_WORLD_LOCAL_RANK", "3");
    const ScopedVariable slurm("SLURM_LOCALID", "6");  // mpirun's rank counts where both are set
    CHECK(ensemble::gpu_device_index(4) == 3);
    CHECK(ensemble::gpu_device_index(2) == 1);  // more ranks than GPUs: they share them in turn
    CHECK(ensemble::gpu_device_index(1) == 0);
  }
  {
    const ScopedVariable open_mpi("OMPI_COMM_WORLD_LOCAL_RANK", "");
    const ScopedVariable slurm("SLURM_LOCALID", "6");
    CHECK(ensemble::gpu_device_index(4) == 2);
  }
  for (const char* bad : {"-1", "two", "1.5"}) {
    const ScopedVariable open_mpi("OMPI_COMM_WORLD_LOCAL_RANK", bad);
    INFO(bad);
    CHECK_THROWS_WITH(ensemble::gpu_device_index(4), Catch::Contains("OMPI_COMM_WORLD_LOCAL_RANK") &&
                                                         Catch::Contains("non-negative integer"));
  }
}

TEST_CASE(
    "a register shape bounded to B blocks of 128 threads runs ahead of the unbounded one where the "
    "launch's blocks fit",
    "[gpu_launch]") {
  using ensemble::RegisterShape;
  const std::vector<RegisterShape> shapes{{8, 3, false, 6, 3}, {8, 3, false, 6, 0}};
  const auto scene = scene_of("rows = 20", "[numerics]\nglobal_error = \"local\"\n");  // no probes
  ensemble::GpuLaunch launch;  // 128 threads per block
  CHECK(ensemble::choose_register_shape(shapes, scene, 20, launch) == RegisterShape{8, 3, false, 6, 3});
  launch.threads_per_block = 384;  // 3 × 128: still the bounded kernel's
  CHECK(ensemble::choose_register_shape(shapes, scene, 20, launch) == RegisterShape{8, 3, false, 6, 3});
  launch.threads_per_block = 512;  // beyond its bound: the unbounded kernel
  CHECK(ensemble::choose_register_shape(shapes, scene, 20, launch) == RegisterShape{8, 3, false, 6, 0});
  CHECK_FALSE(
      ensemble::choose_register_shape(std::vector<RegisterShape>{{8, 3, false, 6, 3}}, scene, 20, launch));
  CHECK(RegisterShape{8, 3, false, 6, 3}.max_threads_per_block() == 384);
  CHECK(RegisterShape{8, 3, false, 6, 0}.max_threads_per_block() == 1024);
  // the gpu preset's four 8 × 3 six-stage kernels: a scene with symmetry probes takes the bounded
  // disordered one (8x3ds6b3), the unbounded 8x3ds6 beyond its blocks
  const std::vector<RegisterShape> preset{
      {8, 3, false, 6, 3}, {8, 3, false, 6, 0}, {8, 3, true, 6, 0}, {8, 3, true, 6, 3}};
  const auto probed = scene_of("rows = 20");
  launch.threads_per_block = 128;
  CHECK(ensemble::choose_register_shape(preset, probed, 20, launch) == RegisterShape{8, 3, true, 6, 3});
  CHECK(ensemble::choose_register_shape(preset, scene, 20, launch) == RegisterShape{8, 3, false, 6, 3});
  launch.threads_per_block = 512;
  CHECK(ensemble::choose_register_shape(preset, probed, 20, launch) == RegisterShape{8, 3, true, 6, 0});
}

TEST_CASE("the plan: a variant's mapping, a team's scratch and the chunk's size, for rows and the slider",
          "[gpu_launch]") {
  ensemble::GpuLaunch launch;
  const auto thermal = scene_of("rows = 20", "[thermal]\ntemperature = 0.01\n");
  auto plan = ensemble::plan_row_variant(thermal, 20, launch);
  CHECK(plan.mapping == ensemble::GpuMapping::team);
  CHECK(plan.team == 8);
  CHECK(plan.scratch == ensemble::GpuScratch::shared);  // where a block's teams fit
  CHECK_FALSE(plan.scratch_asked);
  CHECK(plan.chunk_members(1000, 1'000'000) == 65536);  // at least 65 536
  CHECK(plan.chunk_members(10'000, 1'000'000) == 80'000);  // 8 × the resident members
  CHECK(plan.chunk_members(10'000, 5'000) == 5'000);  // the group's members at most
  CHECK(plan.threads_per_member() == "8 threads per member");
  plan = ensemble::plan_row_variant(scene_of("rows = 2"), 2, launch);
  CHECK(plan.mapping == ensemble::GpuMapping::thread);
  CHECK(plan.threads_per_member() == "1 thread per member");
  const std::vector<ensemble::RegisterShape> shapes{{8, 3, false}};
  plan = ensemble::plan_row_variant(scene_of("rows = 20", "[numerics]\nglobal_error = \"local\"\n"), 20,
                                    launch, shapes);
  CHECK(plan.mapping == ensemble::GpuMapping::registers);
  CHECK(plan.shape == shapes.front());
  CHECK(plan.team == 8);
  CHECK(plan.threads_per_member() == "8 threads per member, rows in registers");
  launch.scratch = ensemble::GpuScratch::global;
  launch.threads_per_block = 256;
  launch.blocks = 7;
  plan = ensemble::plan_row_variant(thermal, 20, launch);
  CHECK(plan.scratch == ensemble::GpuScratch::global);
  CHECK(plan.scratch_asked);
  CHECK(plan.threads_per_block == 256);
  CHECK(plan.blocks == 7);

  const auto slider = ensemble::plan_slider_size({7, 7}, ensemble::GpuLaunch{});
  CHECK(slider.mapping == ensemble::GpuMapping::team);
  CHECK(slider.team == 32);
  CHECK(slider.scratch == ensemble::GpuScratch::global);  // unless asked otherwise
  CHECK_FALSE(slider.scratch_asked);
  CHECK(slider.chunk_members(100, 1'000'000) == 1024);  // at least 1 024
  CHECK(slider.chunk_members(1000, 1'000'000) == 4000);  // 4 × the resident members
  ensemble::GpuLaunch shared;
  shared.scratch = ensemble::GpuScratch::shared;
  CHECK(ensemble::plan_slider_size({7, 7}, shared).scratch == ensemble::GpuScratch::shared);
}

TEST_CASE("a GPU scene runs on the executor its caller gives, and without one is an error", "[gpu_launch]") {
  auto scene = scene_of("rows = 4");
  scene.device = ensemble::Device::gpu;
  const auto members = ensemble::plan_members(scene);
  CHECK_THROWS_WITH(ensemble::run_sweep(scene, members), Catch::Contains("no GPU executor"));
  CHECK(ensemble::device_for(ensemble::Device::cpu) == nullptr);
  CHECK(ensemble::device_for(ensemble::Device::gpu) == &ensemble::gpu_executor());
  if (!ensemble::gpu_info().available) {  // the executor says why it cannot run
    const ensemble::GpuExecutor executor;
    CHECK_THROWS_WITH(ensemble::run_sweep(scene, members, {}, &executor), Catch::Contains("numerics.device"));
  }
}
