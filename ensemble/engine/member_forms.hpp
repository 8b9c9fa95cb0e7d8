// The forms a device holds a member in (docs/architecture.md "Teams", "Register kernels"): one thread,
// a team of a warp's threads, a warp's registers; as concepts the compiler checks each driver against.
#pragma once

#include <concepts>
#include <cstddef>

namespace rotorsweep::ensemble {

/// A member on one thread (DeviceMember): storage_size(s), the scratch values a member of schedule s
/// needs; run(s, slots, k, storage, capacity) integrates chunk member k to its retirement and writes its
/// slot. Schedule and Views: the problem's (rows: SlotSchedule, SlotViews).
template <class D, class Schedule, class Views>
concept ThreadMemberForm = requires(const Schedule& s, const Views& slots, std::size_t k, double* storage) {
  { D::storage_size(s) } -> std::convertible_to<std::size_t>;
  D::run(s, slots, k, storage, k);
};

/// A member on a team of `ranks` threads (TeamMember, SliderTeamMember): storage_size(s, ranks), the
/// scratch values the team shares; run(team, s, slots, k, storage, capacity).
template <class D, class Team, class Schedule, class Views>
concept TeamMemberForm =
    requires(Team& team, const Schedule& s, const Views& slots, std::size_t k, double* storage) {
      { D::storage_size(s, k) } -> std::convertible_to<std::size_t>;
      D::run(team, s, slots, k, storage, k);
    };

/// A member in a warp's registers (WarpMember): fits(s, carriable), whether the form holds schedule s
/// and the quadratures it carries; run(s, slots, k) on the lanes of one warp, no scratch.
template <class D, class Schedule, class Views, class Integrals>
concept RegisterMemberForm = requires(const Schedule& s, const Views& slots, std::size_t k, Integrals carriable) {
  { D::fits(s, carriable) } -> std::convertible_to<bool>;
  D::run(s, slots, k);
};

}  // namespace rotorsweep::ensemble
