// Coefficient tables of the linearly implicit (Rosenbrock) steppers, in the transformed form
// of Hairer & Wanner (Solving ODEs II, §IV.7, Eq. 7.25): stage unknowns U_i = Σ_j γ_ij k_j.
#pragma once

#include <cmath>

namespace rotorsweep::kernels {

/// Stage i solves (1/(hγ) I - J) U_i = f(t + α_i h, y + Σ_{j<i} a_ij U_j)
///                                     + Σ_{j<i} (c_ij / h) U_j + γ_i h ∂f/∂t,
/// then y_new = y + Σ m_i U_i and the error estimate is Σ e_i U_i.
struct RosenbrockTableau {
  static constexpr int max_stages = 8;
  const char* name;
  int stages;
  int order;           ///< order of y_new
  int embedded_order;  ///< order of the embedded solution behind the error estimate
  double gamma;
  double alpha[max_stages];
  double gamma_sum[max_stages];  ///< γ_i = Σ_j γ_ij, the weight of h ∂f/∂t
  double a[max_stages][max_stages];
  double c[max_stages][max_stages];
  double m[max_stages];
  double e[max_stages];
};

/// RODAS (order 4, embedded 3, 6 stages, L-stable, stiffly accurate).
/// Source: E. Hairer, G. Wanner, Solving Ordinary Differential Equations II, 2nd ed.,
/// Springer 1996, §VI.4; coefficients as printed in the authors' code rodas.f (METH = 1).
inline constexpr RosenbrockTableau rodas4_tableau{
    "rodas4",
    6,
    4,
    3,
    0.25,
    {0.0, 0.386, 0.21, 0.63, 1.0, 1.0},
    {0.25, -0.1043, 0.1035, -0.3620000000000023e-01, 0.0, 0.0},
    {{0, 0, 0, 0, 0, 0},
     {0.1544000000000000e+01, 0, 0, 0, 0, 0},
     {0.9466785280815826e+00, 0.2557011698983284e+00, 0, 0, 0, 0},
     {0.3314825187068521e+01, 0.2896124015972201e+01, 0.9986419139977817e+00, 0, 0, 0},
     {0.1221224509226641e+01, 0.6019134481288629e+01, 0.1253708332932087e+02, -0.6878860361058950e+00, 0, 0},
     {0.1221224509226641e+01, 0.6019134481288629e+01, 0.1253708332932087e+02, -0.6878860361058950e+00, 1.0,
      0}},
    {{0, 0, 0, 0, 0, 0},
     {-0.5668800000000000e+01, 0, 0, 0, 0, 0},
     {-0.2430093356833875e+01, -0.2063599157091915e+00, 0, 0, 0, 0},
     {-0.1073529058151375e+00, -0.9594562251023355e+01, -0.2047028614809616e+02, 0, 0, 0},
     {0.7496443313967647e+01, -0.1024680431464352e+02, -0.3399990352819905e+02, 0.1170890893206160e+02, 0, 0},
     {0.8083246795921522e+01, -0.7981132988064893e+01, -0.3152159432874371e+02, 0.1631930543123136e+02,
      -0.6058818238834054e+01, 0}},
    {0.1221224509226641e+01, 0.6019134481288629e+01, 0.1253708332932087e+02, -0.6878860361058950e+00, 1.0,
     1.0},
    {0, 0, 0, 0, 0, 1.0}};

/// RODAS4P2 (order 4, embedded 3, 6 stages, L-stable, stiffly accurate, the RODAS structure):
/// extra conditions against the order reduction RODAS shows on stiff and Prothero–Robinson-type
/// problems at tight tolerances. Source: G. Steinebach, "Improvement of Rosenbrock-Wanner method
/// RODASP", in: Progress in Differential-Algebraic Equations II, Springer 2020, pp. 165–184.
inline constexpr RosenbrockTableau rodas4p2_tableau{
    "rodas4p2",
    6,
    4,
    3,
    0.25,
    {0.0, 0.75, 0.321448134013046, 0.519745732277726, 1.0, 1.0},
    {0.25, -0.5, -0.189532918363016, 0.085612108792769, 0.0, 0.0},
    {{0, 0, 0, 0, 0, 0},
     {3.0, 0, 0, 0, 0, 0},
     {0.906377755268814, -0.189707390391685, 0, 0, 0, 0},
     {3.758617027739064, 1.161741776019525, -0.849258085312803, 0, 0, 0},
     {7.089566927282776, 4.573591406461604, -8.423496976860259, -0.959280113459775, 0, 0},
     {7.089566927282776, 4.573591406461604, -8.423496976860259, -0.959280113459775, 1.0, 0}},
    {{0, 0, 0, 0, 0, 0},
     {-12.0, 0, 0, 0, 0, 0},
     {-6.354581592719008, 0.338972550544623, 0, 0, 0, 0},
     {-8.575016317114033, -7.606483992117508, 12.224997650124820, 0, 0, 0},
     {-5.888975457523102, -8.157396617841821, 24.805546872612922, 12.790401512796979, 0, 0},
     {-4.408651676063871, -6.692003137674639, 24.625568527593117, 16.627521966636085, -5.714285714285718, 0}},
    {7.089566927282776, 4.573591406461604, -8.423496976860259, -0.959280113459775, 1.0, 1.0},
    {0, 0, 0, 0, 0, 1.0}};

/// RODAS5P (order 5, embedded 4, 8 stages, L-stable, stiffly accurate): built against the order
/// reduction of Rosenbrock methods at tight tolerances and on Prothero–Robinson-type problems.
/// Source: G. Steinebach, "Construction of Rosenbrock–Wanner method Rodas5P and numerical
/// benchmarks within the Julia Differential Equations package", BIT Numer. Math. 63, 27 (2023);
/// coefficients as in OrdinaryDiffEq.jl (stages 7 and 8 add U_6 and U_7 to the stage-6 argument,
/// y_new is the stage-8 argument plus U_8, and U_8 is the error estimate).
inline constexpr RosenbrockTableau rodas5p_tableau{
    "rodas5p",
    8,
    5,
    4,
    0.21193756319429014,
    {0.0, 0.6358126895828704, 0.4095798393397535, 0.9769306725060716, 0.4288403609558664, 1.0, 1.0, 1.0},
    {0.21193756319429014, -0.42387512638858027, -0.3384627126235924, 1.8046452872882734, 2.325825639765069,
     0.0, 0.0, 0.0},
    {{0},
     {3.0},
     {2.849394379747939, 0.45842242204463923},
     {-6.954028509809101, 2.489845061869568, -10.358996098473584},
     {2.8029986275628964, 0.5072464736228206, -0.3988312541770524, -0.04721187230404641},
     {-7.502846399306121, 2.561846144803919, -11.627539656261098, -0.18268767659942256, 0.030198172008377946},
     {-7.502846399306121, 2.561846144803919, -11.627539656261098, -0.18268767659942256, 0.030198172008377946,
      1.0},
     {-7.502846399306121, 2.561846144803919, -11.627539656261098, -0.18268767659942256, 0.030198172008377946,
      1.0, 1.0}},
    {{0},
     {-14.155112264123755},
     {-17.97296035885952, -2.859693295451294},
     {147.12150275711716, -1.41221402718213, 71.68940251302358},
     {165.43517024871676, -0.4592823456491126, 42.90938336958603, -5.961986721573306},
     {24.854864614690072, -3.0009227002832186, 47.4931110020768, 5.5814197821558125, -0.6610691825249471},
     {30.91273214028599, -3.1208243349937974, 77.79954646070892, 34.28646028294783, -19.097331116725623,
      -28.087943162872662},
     {37.80277123390563, -3.2571969029072276, 112.26918849496327, 66.9347231244047, -40.06618937091002,
      -54.66780262877968, -9.48861652309627}},
    {-7.502846399306121, 2.561846144803919, -11.627539656261098, -0.18268767659942256, 0.030198172008377946,
     1.0, 1.0, 1.0},
    {0, 0, 0, 0, 0, 0, 0, 1.0}};

namespace detail {
inline constexpr double ros2_gamma = 1.0 + 0.70710678118654752440;  // 1 + 1/√2
}

/// ROS2 (order 2, embedded 1, 2 stages, L-stable): the cheap method for loose tolerances.
/// Source: J. G. Verwer, E. J. Spee, J. G. Blom, W. Hundsdorfer, "A second-order Rosenbrock
/// method applied to photochemical dispersion problems", SIAM J. Sci. Comput. 20 (1999)
/// 1456–1480, Eq. (2.5) with γ = 1 + 1/√2; embedded solution: the first stage alone
/// (linearly implicit Euler), y + U_1/γ.
inline constexpr RosenbrockTableau ros2_tableau{"ros2",
                                                2,
                                                2,
                                                1,
                                                detail::ros2_gamma,
                                                {0.0, 1.0},
                                                {detail::ros2_gamma, -detail::ros2_gamma},
                                                {{0}, {1.0 / detail::ros2_gamma}},
                                                {{0}, {-2.0 / detail::ros2_gamma}},
                                                {1.5 / detail::ros2_gamma, 0.5 / detail::ros2_gamma},
                                                {0.5 / detail::ros2_gamma, 0.5 / detail::ros2_gamma}};

}  // namespace rotorsweep::kernels
