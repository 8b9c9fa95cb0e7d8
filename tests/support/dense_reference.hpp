// Dense references for the linear-algebra tests: Eigen's partial-pivot LU solve and a symmetric
// matrix's eigenvalues, compiled once in dense_reference.cpp (the tests see only Eigen's matrix type).
#pragma once

#include <Eigen/Core>

namespace rotorsweep::testing {

/// x with M x = r, by LU with partial pivoting.
Eigen::VectorXd dense_solve(const Eigen::MatrixXd& M, const Eigen::VectorXd& r);

/// The eigenvalues of the symmetric M, ascending.
Eigen::VectorXd symmetric_eigenvalues(const Eigen::MatrixXd& M);

}  // namespace rotorsweep::testing
