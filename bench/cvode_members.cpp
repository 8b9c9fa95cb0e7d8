// Peer benchmark: SUNDIALS CVODE (BDF, dense direct solver, analytic Jacobian) on the row model
// of model.md §1 with the R quadrature q' = A Σ sin(θ_j − t) as an extra state, one member at a time.
//
// Input (stdin): one member per line "index A g θ_0 … θ_{N-1}". Output (stdout): CSV rows
// method,rtol,atol,member,A,g,D,seconds,rhs_evaluations with D the mean over periods 3 and 4.
// Usage: cvode_members RTOL[,RTOL…] [ATOL_RATIO = 1e-3] < members.txt > out.csv
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Member {
  int index = 0;
  double A = 0, g = 0;
  std::vector<double> theta;
};

int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* data) {
  const auto& m = *static_cast<const Member*>(data);
  const auto n = m.theta.size();
  const double* th = N_VGetArrayPointer(y);
  double* f = N_VGetArrayPointer(ydot);
  double drive = 0;
  for (std::size_t j = 0; j < n; ++j) {
    const double up = th[(j + 1) % n], down = th[(j + n - 1) % n], s = std::sin(th[j] - t);
    f[j] = (-3 * std::sin(2 * th[j]) + std::sin(th[j] - up) + std::sin(th[j] - down) + m.A * s) / m.g;
    drive += s;
  }
  f[n] = m.A * drive;
  return 0;
}

int jacobian(sunrealtype t, N_Vector y, N_Vector, SUNMatrix J, void* data, N_Vector, N_Vector, N_Vector) {
  const auto& m = *static_cast<const Member*>(data);
  const auto n = long(m.theta.size());
  const double* th = N_VGetArrayPointer(y);
  SUNMatZero(J);
  for (long j = 0; j < n; ++j) {
    const long up = (j + 1) % n, down = (j + n - 1) % n;
    const double cu = std::cos(th[j] - th[up]), cd = std::cos(th[j] - th[down]);
    SM_ELEMENT_D(J, j, j) = (-6 * std::cos(2 * th[j]) + cu + cd + m.A * std::cos(th[j] - t)) / m.g;
    SM_ELEMENT_D(J, j, up) -= cu / m.g;
    SM_ELEMENT_D(J, j, down) -= cd / m.g;
    SM_ELEMENT_D(J, n, j) = m.A * std::cos(th[j] - t);
  }
  return 0;
}

/// D over periods 3-4 (NaN on failure) and the RHS evaluations.
std::pair<double, long> dissipation(Member& m, double rtol, double atol, SUNContext context) {
  const auto n = sunindextype(m.theta.size());
  N_Vector y = N_VNew_Serial(n + 1, context);
  for (sunindextype j = 0; j < n; ++j) NV_Ith_S(y, j) = m.theta[std::size_t(j)];
  NV_Ith_S(y, n) = 0;
  void* cvode = CVodeCreate(CV_BDF, context);
  SUNMatrix J = SUNDenseMatrix(n + 1, n + 1, context);
  SUNLinearSolver solver = SUNLinSol_Dense(y, J, context);
  CVodeInit(cvode, rhs, 0.0, y);
  CVodeSStolerances(cvode, rtol, atol);
  CVodeSetUserData(cvode, &m);
  CVodeSetLinearSolver(cvode, solver, J);
  CVodeSetJacFn(cvode, jacobian);
  CVodeSetMaxNumSteps(cvode, 100000000);
  const double period = 2 * std::numbers::pi;
  double t = 0, D = std::nan("");
  if (CVode(cvode, 2 * period, y, &t, CV_NORMAL) >= 0) {
    const double q_mid = NV_Ith_S(y, n);
    if (CVode(cvode, 4 * period, y, &t, CV_NORMAL) >= 0) D = (NV_Ith_S(y, n) - q_mid) / 2;
  }
  long evaluations = 0;
  CVodeGetNumRhsEvals(cvode, &evaluations);
  CVodeFree(&cvode);
  SUNLinSolFree(solver);
  SUNMatDestroy(J);
  N_VDestroy(y);
  return {D, evaluations};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: cvode_members RTOL[,RTOL...] [ATOL_RATIO] < members.txt > out.csv\n");
    return 2;
  }
  std::vector<double> rtols;
  std::stringstream list(argv[1]);
  for (std::string item; std::getline(list, item, ',');) rtols.push_back(std::stod(item));
  const double atol_ratio = argc > 2 ? std::stod(argv[2]) : 1e-3;
  std::vector<Member> members;
  for (std::string line; std::getline(std::cin, line);) {
    std::istringstream in(line);
    Member m;
    if (!(in >> m.index >> m.A >> m.g)) continue;
    for (double x; in >> x;) m.theta.push_back(x);
    members.push_back(m);
  }
  SUNContext context;
  SUNContext_Create(nullptr, &context);
  std::printf("method,rtol,atol,member,A,g,D,seconds,rhs_evaluations\n");
  for (double rtol : rtols)
    for (auto& m : members) {
      const auto start = std::chrono::steady_clock::now();
      const auto [D, evaluations] = dissipation(m, rtol, rtol * atol_ratio, context);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::printf("CVODE,%g,%g,%d,%g,%g,%.17g,%.6g,%ld\n", rtol, rtol * atol_ratio, m.index, m.A, m.g, D,
                  seconds, evaluations);
      std::fflush(stdout);
    }
  SUNContext_Free(&context);
  return 0;
}
