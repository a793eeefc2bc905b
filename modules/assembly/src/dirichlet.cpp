#include "assembly/dirichlet.hpp"

#include "core/error.hpp"

#include <algorithm>

namespace sig {

Eigen::VectorXd ReducedSystem::expand(const Eigen::VectorXd& u_free) const {
  SIG_VERIFY(u_free.size() == num_free(),
             "expand: " << u_free.size() << " values for " << num_free() << " free dofs");
  Eigen::VectorXd full(num_full());
  for (int r = 0; r < num_free(); ++r)
    full(free_dofs[r]) = u_free(r);
  for (std::size_t k = 0; k < dirichlet_dofs.size(); ++k)
    full(dirichlet_dofs[k]) = dirichlet_values(static_cast<Eigen::Index>(k));
  return full;
}

int ReducedSystem::contact_node_first_dof(int node, int d) const {
  SIG_VERIFY(node >= 0 && d * node + d - 1 < num_full(),
             "contact node " << node + 1 << " is not a node of the system");
  for (int component = 0; component < d; ++component)
    SIG_VERIFY(reduced_index[d * node + component] >= 0,
               "contact node " << node + 1 << " has a Dirichlet condition on component "
                               << component + 1 << "; Gamma3 and Gamma1 must not share nodes");
  return reduced_index[d * node];
}

Eigen::VectorXd ReducedSystem::load_at(double t) const {
  if (time_loads.empty()) return f;
  return f + restrict(time_loads.change(t, num_full()));
}

Eigen::VectorXd ReducedSystem::restrict(const Eigen::VectorXd& full) const {
  SIG_VERIFY(full.size() == num_full(),
             "restrict: " << full.size() << " values for " << num_full() << " dofs");
  Eigen::VectorXd part(num_free());
  for (int r = 0; r < num_free(); ++r)
    part(r) = full(free_dofs[r]);
  return part;
}

Eigen::SparseMatrix<double>
ReducedSystem::restrict_matrix(const Eigen::SparseMatrix<double>& A) const {
  SIG_VERIFY(A.rows() == num_full() && A.cols() == num_full(),
             "restrict_matrix: " << A.rows() << " x " << A.cols() << " matrix for " << num_full()
                                 << " dofs");
  // The free dofs keep their order, so the kept entries stay sorted: fill the compressed
  // arrays directly, column by column.
  Eigen::SparseMatrix<double> R(num_free(), num_free());
  std::vector<int> outer(num_free() + 1, 0);
  std::vector<int> inner;
  std::vector<double> values;
  inner.reserve(A.nonZeros());
  values.reserve(A.nonZeros());
  for (int r = 0; r < num_free(); ++r) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, free_dofs[r]); it; ++it) {
      const int row = reduced_index[it.row()];
      if (row < 0) continue;
      inner.push_back(row);
      values.push_back(it.value());
    }
    outer[r + 1] = static_cast<int>(inner.size());
  }
  R.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
  std::copy(outer.begin(), outer.end(), R.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), R.innerIndexPtr());
  std::copy(values.begin(), values.end(), R.valuePtr());
  return R;
}

ReducedSystem reduce(const LinearSystem& system, const std::vector<int>& imposed_elsewhere) {
  const int n = system.num_dofs();
  SIG_VERIFY(system.K.rows() == n && system.K.cols() == n,
             "reduce: K is " << system.K.rows() << " x " << system.K.cols() << " for " << n
                             << " dofs");
  SIG_VERIFY(static_cast<Eigen::Index>(system.dirichlet_dofs.size()) ==
                 system.dirichlet_values.size(),
             "reduce: " << system.dirichlet_dofs.size() << " Dirichlet dofs but "
                        << system.dirichlet_values.size() << " values");
  ReducedSystem reduced;
  reduced.reduced_index.assign(n, 0);
  Eigen::VectorXd u_d = Eigen::VectorXd::Zero(n);
  std::vector<double> values;
  for (std::size_t k = 0; k < system.dirichlet_dofs.size(); ++k) {
    const int dof = system.dirichlet_dofs[k];
    SIG_VERIFY(dof >= 0 && dof < n && (k == 0 || dof > system.dirichlet_dofs[k - 1]),
               "reduce: Dirichlet dofs must be sorted, unique and < " << n);
    if (std::binary_search(imposed_elsewhere.begin(), imposed_elsewhere.end(), dof)) continue;
    reduced.reduced_index[dof] = -1;
    reduced.dirichlet_dofs.push_back(dof);
    values.push_back(u_d(dof) = system.dirichlet_values(static_cast<Eigen::Index>(k)));
  }
  reduced.dirichlet_values =
      Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
  for (int dof = 0; dof < n; ++dof) {
    if (reduced.reduced_index[dof] < 0) continue;
    reduced.reduced_index[dof] = reduced.num_free();
    reduced.free_dofs.push_back(dof);
  }
  reduced.K = reduced.restrict_matrix(system.K);
  reduced.f = reduced.restrict(system.f - system.K * u_d);
  reduced.time_loads = system.time_loads;
  return reduced;
}

} // namespace sig
