// The paper's table of dissipation integrals (docs/model.md §3; N = 20, g = 0.0011, two relaxation
// periods, two averaged), and agreement of the three estimators W, S, R outside the CP regime.
#include <catch2/catch.hpp>

#include "ensemble/rows/paper_table.hpp"
#include "support/kernel_scratch.hpp"
#include "support/member_run.hpp"

using rotorsweep::ensemble::Channel;
using rotorsweep::testing::run_member;
using rotorsweep::testing::Start;
namespace paper = rotorsweep::ensemble::paper_table;

namespace {

double dissipation(double A, Start start, double rtol) {
  return run_member(paper::rows, A, paper::g, start, paper::relax_periods, paper::average_periods, rtol,
                    rtol * 1e-3)
      .dissipation();
}

Start start_of(rotorsweep::ensemble::InitialKind kind) {
  return kind == rotorsweep::ensemble::InitialKind::fm ? Start::fm : Start::afm;
}

}  // namespace

TEST_CASE("paper table, FM and AFM regimes, to 1e-5 relative", "[kernels][paper]") {
  for (const auto& entry : paper::entries) {
    if (entry.cp || (entry.A == 4 && entry.kind == rotorsweep::ensemble::InitialKind::fm)) continue;
    INFO("A = " << entry.A);
    CHECK(dissipation(entry.A, start_of(entry.kind), 1e-9) == Approx(entry.paper_R).epsilon(1e-5));
  }
}

TEST_CASE("paper table, CP regime, within 3 percent", "[kernels][paper]") {
  CHECK(dissipation(6.0, Start::afm, 1e-9) == Approx(34.1).epsilon(0.03));
  CHECK(dissipation(8.0, Start::afm, 1e-9) == Approx(5.75).epsilon(0.03));
}

TEST_CASE("work, Stokes and drive estimators agree in the periodic steady state", "[kernels][paper]") {
  for (auto [A, start] :
       {std::pair{1.0, Start::fm}, {1.0, Start::afm}, {4.0, Start::afm}, {11.0, Start::afm}}) {
    const auto member = run_member(paper::rows, A, paper::g, start, 2, 2, 1e-11, 1e-14);
    const double R = member.dissipation();
    INFO("A = " << A);
    CHECK(member.mean(Channel::work) == Approx(R).epsilon(1e-6));
    CHECK(member.mean(Channel::stokes) == Approx(R).epsilon(1e-6));
  }
}
