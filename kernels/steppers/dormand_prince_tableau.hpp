// Butcher tableau of the explicit Dormand–Prince 5(4) pair, the non-stiff reference stepper.
// Source: J. R. Dormand, P. J. Prince, J. Comput. Appl. Math. 6 (1980) 19–26, Table 2.
#pragma once

namespace rotorsweep::kernels {

struct ExplicitTableau {
  static constexpr int max_stages = 7;
  const char* name;
  int stages;
  int order;
  int embedded_order;
  double c[max_stages];
  double a[max_stages][max_stages];
  double b[max_stages];
  double e[max_stages];  ///< b - b̂: weights of the error estimate
};

inline constexpr ExplicitTableau dormand_prince5_tableau{
    "dopri5",
    7,
    5,
    4,
    {0.0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1.0, 1.0},
    {{0},
     {1.0 / 5},
     {3.0 / 40, 9.0 / 40},
     {44.0 / 45, -56.0 / 15, 32.0 / 9},
     {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
     {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
     {35.0 / 384, 0.0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84}},
    {35.0 / 384, 0.0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84, 0.0},
    {35.0 / 384 - 5179.0 / 57600, 0.0, 500.0 / 1113 - 7571.0 / 16695, 125.0 / 192 - 393.0 / 640,
     -2187.0 / 6784 + 92097.0 / 339200, 11.0 / 84 - 187.0 / 2100, -1.0 / 40}};

}  // namespace rotorsweep::kernels
