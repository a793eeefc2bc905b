#include "solver/contact_problem.hpp"

#include "core/error.hpp"

#include <Eigen/Cholesky>

namespace sig {

Eigen::VectorXd ContactProblem::normal_part(const Eigen::VectorXd& u) const {
  Eigen::VectorXd un(contacts());
  for (int p = 0; p < contacts(); ++p)
    un[p] = u[normal_dof[p]];
  return un;
}

bool solve_linear_step(const ContactProblem& problem, const std::vector<char>& imposed,
                       const Eigen::VectorXd& normal_stiffness, const Eigen::VectorXd& normal_load,
                       const Eigen::VectorXd& u_previous, LinearStep& step) {
  const int n = problem.size();
  const int m = problem.contacts();
  SIG_ASSERT(static_cast<int>(imposed.size()) == m, "one flag per contact element");

  // Imposed normal unknowns leave the system (Dirichlet elimination); the rest is one dense
  // Cholesky of the free block.
  std::vector<int> free_index(n, 0);
  for (int p = 0; p < m; ++p)
    if (imposed[p]) free_index[problem.normal_dof[p]] = -1;
  std::vector<int> free;
  free.reserve(n);
  for (int i = 0; i < n; ++i)
    if (free_index[i] >= 0) {
      free_index[i] = static_cast<int>(free.size());
      free.push_back(i);
    }

  Eigen::VectorXd u_imposed = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd rhs = problem.f + problem.regularization * u_previous;
  for (int p = 0; p < m; ++p) {
    const int i = problem.normal_dof[p];
    rhs[i] += normal_load[p];
    if (imposed[p]) u_imposed[i] = problem.gap[p];
  }
  rhs -= problem.K * u_imposed;

  const int nf = static_cast<int>(free.size());
  Eigen::MatrixXd A(nf, nf);
  Eigen::VectorXd b(nf);
  for (int j = 0; j < nf; ++j) {
    for (int i = 0; i < nf; ++i)
      A(i, j) = problem.K(free[i], free[j]);
    A(j, j) += problem.regularization;
    b[j] = rhs[free[j]];
  }
  for (int p = 0; p < m; ++p)
    if (!imposed[p])
      A(free_index[problem.normal_dof[p]], free_index[problem.normal_dof[p]]) +=
          normal_stiffness[p];

  Eigen::LLT<Eigen::MatrixXd> cholesky(A);
  if (cholesky.info() != Eigen::Success) return false;
  const Eigen::VectorXd uf = cholesky.solve(b);

  step.u = u_imposed;
  for (int j = 0; j < nf; ++j)
    step.u[free[j]] = uf[j];

  // The multiplier of an imposed node is what equilibrium lacks at its normal unknown.
  const Eigen::VectorXd internal =
      problem.K * step.u + problem.regularization * (step.u - u_previous);
  step.reaction = Eigen::VectorXd::Zero(m);
  for (int p = 0; p < m; ++p)
    if (imposed[p]) {
      const int i = problem.normal_dof[p];
      step.reaction[p] = problem.f[i] + normal_load[p] - internal[i];
    }
  return true;
}

} // namespace sig
