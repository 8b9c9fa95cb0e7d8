// Bisection to the last bit: the point of [a, b] where a predicate turns from true to false,
// shared by the closed-form roots of the bifurcation curves and the inversion of A_L(ζ).
#pragma once

namespace rotorsweep::landscape {

/// The point of [a, b] where `left` switches from true (at a) to false (at b), halving until the
/// midpoint no longer lies strictly inside. A root of f with a sign change on [a, b] is the switch
/// of left(x) = (f(x) < 0) == (f(a) < 0).
template <class Left>
double bisect(Left left, double a, double b) {
  for (int i = 0; i < 200; ++i) {
    const double m = 0.5 * (a + b);
    if (m <= a || m >= b) break;
    (left(m) ? a : b) = m;
  }
  return 0.5 * (a + b);
}

}  // namespace rotorsweep::landscape
