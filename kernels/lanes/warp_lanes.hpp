// The lanes of one member's part of a warp as a host lane type (docs/architecture.md "Register
// kernels"): L doubles, every operation lane by lane and exactly rounded, so that the host runs a
// register kernel with the bits each of the device's L threads computes.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/warp_operation_count.hpp"

namespace rotorsweep::kernels {

template <std::size_t L>
struct WarpMask {
  std::array<bool, L> bits{};
  WarpMask operator&(const WarpMask& o) const { return combine(o, [](bool a, bool b) { return a && b; }); }
  WarpMask operator|(const WarpMask& o) const { return combine(o, [](bool a, bool b) { return a || b; }); }
  WarpMask operator!() const {
    WarpMask m;
    for (std::size_t l = 0; l < L; ++l) m.bits[l] = !bits[l];
    return m;
  }

 private:
  template <class F>
  WarpMask combine(const WarpMask& o, F&& f) const {
    WarpMask m;
    for (std::size_t l = 0; l < L; ++l) m.bits[l] = f(bits[l], o.bits[l]);
    return m;
  }
};

/// L lanes of doubles; arithmetic and comparisons lane by lane.
template <std::size_t L>
struct WarpLanes {
  std::array<double, L> v{};

  WarpLanes() = default;
  WarpLanes(double x) { v.fill(x); }  // NOLINT: a lane type converts from double as xsimd's batches do

  double& operator[](std::size_t l) { return v[l]; }
  const double& operator[](std::size_t l) const { return v[l]; }

  template <class F>
  static WarpLanes each(F&& f) {
    WarpLanes out;
    for (std::size_t l = 0; l < L; ++l) out.v[l] = f(l);
    return out;
  }
  template <class F>
  static WarpMask<L> test(F&& f) {
    count_warp_operations(&WarpOperationCount::other);
    WarpMask<L> m;
    for (std::size_t l = 0; l < L; ++l) m.bits[l] = f(l);
    return m;
  }

  friend WarpLanes operator+(const WarpLanes& a, const WarpLanes& b) {
    count_warp_operations(&WarpOperationCount::arithmetic);
    return each([&](std::size_t l) { return a.v[l] + b.v[l]; });
  }
  friend WarpLanes operator-(const WarpLanes& a, const WarpLanes& b) {
    count_warp_operations(&WarpOperationCount::arithmetic);
    return each([&](std::size_t l) { return a.v[l] - b.v[l]; });
  }
  friend WarpLanes operator*(const WarpLanes& a, const WarpLanes& b) {
    count_warp_operations(&WarpOperationCount::arithmetic);
    return each([&](std::size_t l) { return a.v[l] * b.v[l]; });
  }
  friend WarpLanes operator/(const WarpLanes& a, const WarpLanes& b) {
    count_warp_operations(&WarpOperationCount::division);
    return each([&](std::size_t l) { return a.v[l] / b.v[l]; });
  }
  WarpLanes& operator+=(const WarpLanes& b) { return *this = *this + b; }
  WarpLanes& operator-=(const WarpLanes& b) { return *this = *this - b; }
  WarpLanes& operator*=(const WarpLanes& b) { return *this = *this * b; }
  WarpLanes operator-() const {
    count_warp_operations(&WarpOperationCount::other);
    return each([&](std::size_t l) { return -v[l]; });
  }

  friend WarpMask<L> operator<(const WarpLanes& a, const WarpLanes& b) {
    return test([&](std::size_t l) { return a.v[l] < b.v[l]; });
  }
  friend WarpMask<L> operator<=(const WarpLanes& a, const WarpLanes& b) {
    return test([&](std::size_t l) { return a.v[l] <= b.v[l]; });
  }
  friend WarpMask<L> operator>(const WarpLanes& a, const WarpLanes& b) {
    return test([&](std::size_t l) { return a.v[l] > b.v[l]; });
  }
  friend WarpMask<L> operator>=(const WarpLanes& a, const WarpLanes& b) {
    return test([&](std::size_t l) { return a.v[l] >= b.v[l]; });
  }
  friend WarpMask<L> operator==(const WarpLanes& a, const WarpLanes& b) {
    return test([&](std::size_t l) { return a.v[l] == b.v[l]; });
  }
  friend WarpMask<L> operator!=(const WarpLanes& a, const WarpLanes& b) {
    return test([&](std::size_t l) { return a.v[l] != b.v[l]; });
  }
};

template <std::size_t L>
struct lane_traits<WarpLanes<L>> {
  using mask = WarpMask<L>;
  static constexpr std::size_t width = L;
};

template <std::size_t L>
WarpLanes<L> lane_select(const WarpMask<L>& m, const WarpLanes<L>& a, const WarpLanes<L>& b) {
  count_warp_operations(&WarpOperationCount::other);
  return WarpLanes<L>::each([&](std::size_t l) { return m.bits[l] ? a.v[l] : b.v[l]; });
}
/// A member's decision, alike in every lane (a device thread's select).
template <std::size_t L>
WarpLanes<L> lane_select(bool m, const WarpLanes<L>& a, const WarpLanes<L>& b) {
  return m ? a : b;
}
template <std::size_t L, class F>
WarpLanes<L> lanewise(const WarpLanes<L>& x, F&& f) {
  count_warp_operations(&WarpOperationCount::other);
  return WarpLanes<L>::each([&](std::size_t l) { return f(x.v[l]); });
}
template <std::size_t L>
WarpLanes<L> lane_abs(const WarpLanes<L>& x) {
  return lanewise(x, [](double a) { return lane_abs(a); });
}
template <std::size_t L>
WarpLanes<L> lane_neg(const WarpLanes<L>& x) {
  return lanewise(x, [](double a) { return lane_neg(a); });
}
template <std::size_t L>
WarpLanes<L> lane_min(const WarpLanes<L>& a, const WarpLanes<L>& b) {
  count_warp_operations(&WarpOperationCount::other);
  return WarpLanes<L>::each([&](std::size_t l) { return lane_min(a.v[l], b.v[l]); });
}
template <std::size_t L>
WarpLanes<L> lane_max(const WarpLanes<L>& a, const WarpLanes<L>& b) {
  count_warp_operations(&WarpOperationCount::other);
  return WarpLanes<L>::each([&](std::size_t l) { return lane_max(a.v[l], b.v[l]); });
}
template <std::size_t L>
WarpLanes<L> lane_sqrt(const WarpLanes<L>& x) {
  count_warp_operations(&WarpOperationCount::square_root);
  return WarpLanes<L>::each([&](std::size_t l) { return lane_sqrt(x.v[l]); });
}
template <std::size_t L>
WarpLanes<L> lane_floor(const WarpLanes<L>& x) {
  return lanewise(x, [](double a) { return lane_floor(a); });
}
template <std::size_t L>
WarpLanes<L> lane_round(const WarpLanes<L>& x) {
  return lanewise(x, [](double a) { return lane_round(a); });
}
template <std::size_t L>
WarpMask<L> lane_isfinite(const WarpLanes<L>& x) {
  return WarpLanes<L>::test([&](std::size_t l) { return lane_isfinite(x.v[l]); });
}
template <std::size_t L>
WarpMask<L> lane_signbit(const WarpLanes<L>& x) {
  return WarpLanes<L>::test([&](std::size_t l) { return lane_signbit(x.v[l]); });
}
template <std::size_t L>
WarpLanes<L> lane_frexp(const WarpLanes<L>& x, WarpLanes<L>& e) {
  count_warp_operations(&WarpOperationCount::other);
  return WarpLanes<L>::each([&](std::size_t l) { return lane_frexp(x.v[l], e.v[l]); });
}
template <std::size_t L>
WarpLanes<L> lane_ldexp(const WarpLanes<L>& x, const WarpLanes<L>& e) {
  count_warp_operations(&WarpOperationCount::other);
  return WarpLanes<L>::each([&](std::size_t l) { return lane_ldexp(x.v[l], e.v[l]); });
}
template <std::size_t L>
bool lane_any(const WarpMask<L>& m) {
  for (bool b : m.bits)
    if (b) return true;
  return false;
}
template <std::size_t L>
double lane_get(const WarpLanes<L>& x, std::size_t l) {
  return x.v[l];
}
template <std::size_t L>
void lane_set(WarpLanes<L>& x, std::size_t l, double value) {
  x.v[l] = value;
}
template <std::size_t L>
bool mask_get(const WarpMask<L>& m, std::size_t l) {
  return m.bits[l];
}

}  // namespace rotorsweep::kernels
