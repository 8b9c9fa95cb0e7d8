// Member plans (ensemble/member_plan): the product in its documented order, noise and offset only for
// the kinds that use them, exact starts without replicas unless random; draws keyed by (seed, replica).
#include <catch2/catch.hpp>

#include "ensemble/rows/member_plan.hpp"

using namespace rotorsweep::ensemble;

TEST_CASE("members are A × g × kinds × replicas, replicas innermost", "[ensemble][plan]") {
  Scene scene;
  scene.A_values = {1, 2, 3};
  scene.g_values = {0.1, 0.2};
  scene.kinds = {InitialKind::fm, InitialKind::afm};
  scene.replicas = 2;
  const auto members = plan_members(scene);
  REQUIRE(members.size() == 24);
  for (std::size_t i = 0; i < members.size(); ++i) CHECK(members[i].index == i);
  CHECK(members[1].replica == 1);
  CHECK(members[2].kind == InitialKind::afm);
  CHECK(members[4].g == 0.2);
  CHECK(members[8].A == 2);
  CHECK(members[23].A == 3);
  CHECK(members[23].g == 0.2);
  CHECK(members[23].kind == InitialKind::afm);
}

TEST_CASE("a member's draw depends on its replica and the seed only", "[ensemble][plan]") {
  Scene scene;
  scene.row_counts = {6};
  scene.A_values = {1, 2};
  scene.g_values = {0.1};
  scene.kinds = {InitialKind::random};
  scene.replicas = 2;
  const auto members = plan_members(scene);
  const auto first = member_initial_angles(scene, members[1]);  // A = 1, replica 1
  CHECK(member_initial_angles(scene, members[3]) == first);     // A = 2, replica 1
  CHECK(member_initial_angles(scene, members[2]) != first);     // replica 0
  Scene larger = scene;
  larger.A_values = {7, 8, 9};
  CHECK(member_initial_angles(larger, plan_members(larger)[5]) == first);
  larger.seed = 2;
  CHECK(member_initial_angles(larger, plan_members(larger)[5]) != first);
}

TEST_CASE("the same member under another N or tolerance starts from the same draw", "[ensemble][plan]") {
  Scene scene;
  scene.row_counts = {4, 8};
  scene.rtol_values = {1e-4, 1e-8};
  scene.atol_values = {1e-7, 1e-11};
  scene.A_values = {1, 2, 3};
  scene.g_values = {0.1};
  scene.kinds = {InitialKind::random};
  const auto members = plan_members(scene);
  REQUIRE(members.size() == 12);
  CHECK(members[4].variant == 1);
  CHECK(members[4].stream == 0);
  CHECK(members[4].rtol == 1e-8);
  CHECK(members[7].rows == 8);
  const auto small = member_initial_angles(scene, members[1]);  // N = 4, rtol 1e-4, A = 2
  CHECK(member_initial_angles(scene, members[4]) == small);     // N = 4, rtol 1e-8, A = 2
  const auto large = member_initial_angles(scene, members[7]);  // N = 8, A = 2
  CHECK(std::vector<double>(large.begin(), large.begin() + 4) == small);
}

TEST_CASE("noise and offset are axes of the plan, and a noise scan rescales one draw", "[ensemble][plan]") {
  Scene scene;
  scene.row_counts = {8};
  scene.A_values = {1, 2};
  scene.g_values = {0.1};
  scene.noise_values = {1e-4, 0.1};
  scene.offset_values = {0.0, 3.0};
  scene.kinds = {InitialKind::fm, InitialKind::afm};
  scene.replicas = 3;
  const auto members = plan_members(scene);
  REQUIRE(members.size() == 2 * 2 * 2 * 2 * 3);
  // order: A × g × noise × offset × kind × replica
  CHECK(members[3].kind == InitialKind::afm);
  CHECK(members[6].offset == 3.0);
  CHECK(members[12].noise == 0.1);
  CHECK(members[24].A == 2);
  // member 1 (η = 1e-4, θ0 = 0, FM, replica 1) and member 13 (η = 0.1): the same draw scaled
  const auto small = member_initial_angles(scene, members[1]);
  const auto large = member_initial_angles(scene, members[13]);
  for (std::size_t j = 0; j < small.size(); ++j) CHECK(large[j] == Approx(small[j] * 1000).epsilon(1e-12));
  const auto shifted = member_initial_angles(scene, members[7]);  // θ0 = 3
  for (std::size_t j = 0; j < small.size(); ++j) CHECK(shifted[j] == Approx(small[j] + 3.0).epsilon(1e-12));
}

TEST_CASE("noise and offset do not multiply random and exact starts", "[ensemble][plan]") {
  Scene scene;
  scene.row_counts = {4};
  scene.A_values = {1, 2};
  scene.g_values = {0.1};
  scene.noise_values = {0.01, 0.3};
  scene.offset_values = {0.0, 1.0, 2.0};
  scene.kinds = {InitialKind::fm, InitialKind::random, InitialKind::afm, InitialKind::exact};
  scene.exact_angles = {0.5};
  scene.replicas = 2;
  // per A: (FM 2 + random 2 + AFM 2 + exact 1) at the first (η, θ0), then 5 × (FM 2 + AFM 2)
  const std::size_t block = 7 + 5 * 4;
  REQUIRE(scene.member_count() == 2 * block);
  const MemberPlan plan(scene);
  REQUIRE(plan.size() == 2 * block);
  REQUIRE(plan.point_count() == 2 * (4 + 5 * 2));
  std::size_t random = 0, exact = 0, point = 0;
  for (std::size_t i = 0; i < plan.size(); ++i) {
    const Member m = plan[i];
    CHECK(m.index == i);
    CHECK(m.A == (i < block ? 1 : 2));
    if (i > 0 && m.point != plan[i - 1].point) CHECK(m.point == ++point);
    CHECK(plan.point_first(m.point) == i - std::size_t(m.replica));
    const auto at = plan.axis_position(i);
    CHECK(scene.noise_values[at[4]] == m.noise);
    CHECK(scene.offset_values[at[5]] == m.offset);
    CHECK(scene.kinds[at[6]] == m.kind);
    CHECK(at[7] == std::size_t(m.replica));
    if (!kind_uses_noise(m.kind)) {
      CHECK(m.noise == 0.01);
      CHECK(m.offset == 0.0);
    }
    random += m.kind == InitialKind::random;
    exact += m.kind == InitialKind::exact;
  }
  CHECK(point + 1 == plan.point_count());
  CHECK(plan.point_first(plan.point_count()) == plan.size());
  CHECK(random == 2 * 2);
  CHECK(exact == 2);
  // the FM/AFM members of the full product keep their order: η = 0.3, θ0 = 2, AFM, replica 1 is last
  const Member last = plan[block - 1];
  CHECK(last.noise == 0.3);
  CHECK(last.offset == 2.0);
  CHECK(last.kind == InitialKind::afm);
  CHECK(last.replica == 1);
}

TEST_CASE("exact starts take replicas where disorder or temperature draws from them", "[ensemble][plan]") {
  Scene scene;
  scene.A_values = {1};
  scene.g_values = {0.1};
  scene.kinds = {InitialKind::exact};
  scene.exact_angles = {0.0};
  scene.replicas = 5;
  CHECK(scene.member_count() == 1);
  scene.disorder.A_rows = {1e-3};  // given rows: the same array for every replica
  CHECK(scene.member_count() == 1);
  scene.disorder.A = 1e-6;
  scene.disorder.A_rows.clear();
  CHECK(scene.member_count() == 5);
  scene.disorder.A = 0;
  scene.thermal.temperature = 0.1;
  CHECK(scene.member_count() == 5);
}
