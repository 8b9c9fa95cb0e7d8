// Dense references for the linear-algebra tests (dense_reference.hpp): Eigen's partial-pivot LU and
// self-adjoint eigenvalue solver, instantiated here once for every test that compares against them.
#include "support/dense_reference.hpp"

#include <Eigen/Dense>

namespace rotorsweep::testing {

Eigen::VectorXd dense_solve(const Eigen::MatrixXd& M, const Eigen::VectorXd& r) { return M.partialPivLu().solve(r); }

Eigen::VectorXd symmetric_eigenvalues(const Eigen::MatrixXd& M) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(M, Eigen::EigenvaluesOnly).eigenvalues();
}

}  // namespace rotorsweep::testing
