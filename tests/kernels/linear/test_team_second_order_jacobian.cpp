// The slider's stage solve on a host team (kernels/linear/team_second_order_jacobian.hpp) against
// SecondOrderJacobian itself: the same solution, J x and inertia test bit for bit, inertial and overdamped.
#include <catch2/catch.hpp>
#include <random>
#include <vector>

#include "kernels/lanes/team.hpp"
#include "kernels/linear/second_order_jacobian.hpp"
#include "kernels/linear/team_second_order_jacobian.hpp"
#include "support/built_matrix.hpp"

using namespace rotorsweep::kernels;
using rotorsweep::testing::BuiltMatrix;
using rotorsweep::testing::check_same_solve;

namespace {

template <bool Inertial>
void check_team_solve(std::mt19937_64& rng, std::size_t& indefinite, std::size_t& cases) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t rotors : {1u, 7u, 49u})
    for (std::size_t ranks : {1u, 2u, 3u, 8u, 32u})
      for (int draw = 0; draw < 4; ++draw) {
        const std::size_t dimension = Inertial ? 2 * rotors : rotors;
        BuiltMatrix<SecondOrderJacobian<double, Inertial>> one(dimension);
        BuiltMatrix<TeamSecondOrderJacobian<HostTeam, Inertial>, std::size_t> team(dimension, ranks);
        for (std::size_t j = 0; j < rotors; ++j)  // a symmetric stiffness K, its diagonal 1 + U(−1, 1)
          for (std::size_t k = j; k < rotors; ++k) {
            const double x = j == k ? 1.0 + u(rng) : u(rng) / double(rotors);
            one.matrix.stiffness().entry(j, k) = one.matrix.stiffness().entry(k, j) = x;
            team.matrix.stiffness().entry(j, k) = team.matrix.stiffness().entry(k, j) = x;
          }
        const double inertia = 0.3 + 0.5 * (u(rng) + 1.0), damping = 0.2 + 0.5 * (u(rng) + 1.0);
        one.matrix.set_dynamics(inertia, damping);
        team.matrix.set_dynamics(inertia, damping);
        const double shift = draw % 2 == 0 ? 6.0 : 0.05;  // definite, or likely not
        INFO((Inertial ? "inertial" : "overdamped") << ", " << rotors << " rotors, ranks " << ranks);
        indefinite += !check_same_solve(one.matrix, team.matrix, ranks, shift, dimension, rng);
        ++cases;
      }
}

}  // namespace

TEST_CASE("the slider's stage solve on a team gives SecondOrderJacobian's bits: solution, J x, inertia",
          "[kernels][team][slider]") {
  std::mt19937_64 rng(5);
  std::size_t indefinite = 0, cases = 0;
  check_team_solve<true>(rng, indefinite, cases);
  check_team_solve<false>(rng, indefinite, cases);
  CHECK(indefinite > cases / 8);  // both kinds were tested
}
