// A member's L lanes of a warp (docs/architecture.md "Register kernels"): what a register kernel asks
// of them — its lane, a value from the cyclic neighbour lanes, a lane's value to all, sums, maxima and
// votes in one fixed order, a write by one lane — on the host as a lane type of L doubles, on a device
// as L threads.
#pragma once

#include <cstddef>
#include <type_traits>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#if !defined(__CUDACC__)
#include "kernels/lanes/warp_lanes.hpp"
#endif

namespace rotorsweep::kernels {

/// Whether L lanes can hold a member: a power of two up to a warp.
constexpr bool warp_lanes_valid(std::size_t L) { return L >= 1 && L <= 32 && (L & (L - 1)) == 0; }

#if !defined(__CUDACC__)
/// The host's emulation: one value holds all L lanes (a double for L = 1), shuffles are permutations
/// and a sum adds lanes in the device's butterfly order (v_i + v_{i xor o} for o = L/2, …, 1), so the
/// host gives every bit the device's threads give. Its exchanges across lanes are never inlined:
/// GCC 12's AVX-512 vectoriser turned a two-lane sum inlined after a loop over slots into a wrong
/// value (one lane's part lost, -O3 -march=native only), and a call is a boundary it does not cross.
template <std::size_t L>
struct HostWarp {
  static_assert(warp_lanes_valid(L));
  static constexpr std::size_t lanes = L;
  using value = std::conditional_t<L == 1, double, WarpLanes<L>>;
  using mask = lane_mask<value>;

  /// Each lane's index 0 … L − 1.
  static value lane() {
    return lane_from<value>([](std::size_t l) { return double(l); });
  }
  /// The value of lane (l + 1) mod L in lane l.
  [[gnu::noinline]] static value from_next(const value& v) { return permuted(v, [](std::size_t l) { return (l + 1) % L; }); }
  /// The value of lane (l − 1) mod L in lane l.
  [[gnu::noinline]] static value from_previous(const value& v) {
    return permuted(v, [](std::size_t l) { return (l + L - 1) % L; });
  }
  /// The value of lane (l + s) mod L, and of lane (l − s) mod L, in lane l.
  [[gnu::noinline]] static value from_above(const value& v, std::size_t s) {
    return permuted(v, [&](std::size_t l) { return (l + s) % L; });
  }
  [[gnu::noinline]] static value from_below(const value& v, std::size_t s) {
    return permuted(v, [&](std::size_t l) { return (l + L - s % L) % L; });
  }
  /// Lane k's value in every lane.
  static double from_lane(const value& v, std::size_t k) {
    count_warp_operations(&WarpOperationCount::shuffle);
    return lane_get(v, k);
  }
  /// p[index] in each lane (index: a value holding each lane's own index).
  static value load(const double* p, const value& index) {
    return lane_from<value>([&](std::size_t l) { return p[std::size_t(lane_get(index, l))]; });
  }
  /// p[index] = v in each lane where `where` holds.
  static void store(double* p, const value& index, const value& v, const mask& where) {
    for (std::size_t l = 0; l < L; ++l)
      if (mask_get(where, l)) p[std::size_t(lane_get(index, l))] = lane_get(v, l);
  }
  /// Σ over the lanes, the same in every lane.
  [[gnu::noinline]] static double sum(const value& v) {
    return butterfly(v, [](double a, double b) { return a + b; });
  }
  /// max over the lanes.
  [[gnu::noinline]] static double max(const value& v) {
    return butterfly(v, [](double a, double b) { return b > a ? b : a; });
  }
  static bool all(const mask& m) {
    for (std::size_t l = 0; l < L; ++l)
      if (!mask_get(m, l)) return false;
    return true;
  }
  static bool any(const mask& m) { return lane_any(m); }
  /// f() once for the member (on a device: by its first lane).
  template <class F>
  static void one(F&& f) {
    f();
  }

 private:
  template <class Source>
  static value permuted(const value& v, Source&& source) {
    count_warp_operations(&WarpOperationCount::shuffle);
    return lane_from<value>([&](std::size_t l) { return lane_get(v, source(l)); });
  }
  template <class Combine>
  static double butterfly(const value& v, Combine&& combine) {
    double w[L];
    for (std::size_t l = 0; l < L; ++l) w[l] = lane_get(v, l);
    for (std::size_t o = L / 2; o >= 1; o /= 2) {
      count_warp_operations(&WarpOperationCount::shuffle);
      count_warp_operations(&WarpOperationCount::arithmetic);
      double next[L];
      for (std::size_t l = 0; l < L; ++l) next[l] = combine(w[l], w[l ^ o]);
      for (std::size_t l = 0; l < L; ++l) w[l] = next[l];
    }
    return w[0];
  }
};
#endif

#if defined(__CUDACC__)
/// L threads of a warp (threads L·k … L·k + L − 1): a value per thread, shuffles within the group, sums
/// and maxima by a butterfly of shuffles in HostWarp's order, votes of the group.
template <std::size_t L>
struct DeviceWarp {
  static_assert(warp_lanes_valid(L));
  static constexpr std::size_t lanes = L;
  using value = double;
  using mask = bool;

  __device__ static unsigned group() {
    return L == 32 ? 0xffffffffu : ((1u << L) - 1u) << (threadIdx.x % 32u / unsigned(L) * unsigned(L));
  }
  __device__ static unsigned rank() { return threadIdx.x % unsigned(L); }

  __device__ static double lane() { return double(rank()); }
  __device__ static double from_next(double v) { return __shfl_sync(group(), v, int((rank() + 1) % L), int(L)); }
  __device__ static double from_previous(double v) {
    return __shfl_sync(group(), v, int((rank() + L - 1) % L), int(L));
  }
  __device__ static double from_above(double v, std::size_t s) {
    return __shfl_sync(group(), v, int((rank() + s) % L), int(L));
  }
  __device__ static double from_below(double v, std::size_t s) {
    return __shfl_sync(group(), v, int((rank() + L - s % L) % L), int(L));
  }
  __device__ static double from_lane(double v, std::size_t k) { return __shfl_sync(group(), v, int(k), int(L)); }
  __device__ static double load(const double* p, double index) { return p[std::size_t(index)]; }
  __device__ static void store(double* p, double index, double v, bool where) {
    if (where) p[std::size_t(index)] = v;
  }
  __device__ static double sum(double v) {
    for (unsigned o = L / 2; o >= 1; o /= 2) v += __shfl_xor_sync(group(), v, int(o), int(L));
    return v;
  }
  __device__ static double max(double v) {
    for (unsigned o = L / 2; o >= 1; o /= 2) {
      const double other = __shfl_xor_sync(group(), v, int(o), int(L));
      v = other > v ? other : v;
    }
    return v;
  }
  __device__ static bool all(bool m) { return __all_sync(group(), m ? 1 : 0) != 0; }
  __device__ static bool any(bool m) { return __any_sync(group(), m ? 1 : 0) != 0; }
  template <class F>
  __device__ static void one(F&& f) {
    if (rank() == 0) f();
  }
};
#endif

}  // namespace rotorsweep::kernels
