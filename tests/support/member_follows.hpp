// Test support: whether one member run by two drivers whose sums differ only in order (one thread, a
// team, a warp's registers) agrees within the integration error: labels and counts equal, D and ρ̄ close.
#pragma once

#include <catch2/catch.hpp>
#include <cstddef>

#include "ensemble/rows/member_result.hpp"

namespace rotorsweep::testing {

/// b follows a: the same status, periods, regime, attractor and slips per period; D within 1e-8
/// relative (`outside_cp` outside CP), ρ̄ within 1e-9, W, S, H and the moments of R and S within 1e-8,
/// step attempts within 1 %.
inline void check_member_follows(const ensemble::MemberResult& a, const ensemble::MemberResult& b,
                                 double outside_cp) {
  using Catch::Detail::Approx;
  REQUIRE(b.status == a.status);
  CHECK(b.periods_run == a.periods_run);
  CHECK(b.regime == a.regime);
  CHECK(b.final_state.attractor == a.final_state.attractor);
  CHECK(b.slips_per_period() == a.slips_per_period());
  CHECK(b.dissipation() == Approx(a.dissipation()).epsilon(1e-8).margin(1e-12));
  if (a.regime != ensemble::Regime::cp)
    CHECK(b.dissipation() == Approx(a.dissipation()).epsilon(outside_cp).margin(1e-14));
  CHECK(b.alignment_mean() == Approx(a.alignment_mean()).epsilon(1e-9));
  for (const auto channel :
       {ensemble::Channel::work, ensemble::Channel::stokes, ensemble::Channel::energy_mean,
        ensemble::Channel::dissipation_moment, ensemble::Channel::stokes_moment}) {
    INFO("channel " << std::size_t(channel));
    CHECK(b.mean(channel) == Approx(a.mean(channel)).epsilon(1e-8).margin(1e-12));
  }
  CHECK(b.steps_accepted + b.steps_rejected == Approx(a.steps_accepted + a.steps_rejected).epsilon(0.01));
}

}  // namespace rotorsweep::testing
