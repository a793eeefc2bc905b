#pragma once
// The semi-discrete linear viscoelastic problem of the marches in velocity (ch. 5 and 6) on the
// free dofs of a Dirichlet-reduced system:
//     M a + C v + K u + sum_m int_0^t exp(-beta_m (t - s)) K_m v(s) ds = f(t),
// K the stiffness (for a Kelvin-Voigt law, of its elastic part B), C the viscosity K_A, the K_m
// the stiffnesses of the memory kernel's exponential terms (material/kelvin_voigt.hpp) and M the
// mass. The stage layer builds it from the assembled system (stages/march_inputs.hpp).
#include "integrator/elastodynamics.hpp"

#include <Eigen/SparseCore>

#include <vector>

namespace sig {

/// One exponential term exp(-beta t) K of a memory kernel.
struct ExponentialStiffness {
  double beta = 0;
  Eigen::SparseMatrix<double> K;
};

struct ViscoelasticProblem {
  Eigen::SparseMatrix<double> K;            ///< stiffness, symmetric
  Eigen::SparseMatrix<double> C;            ///< viscosity, symmetric; 0 x 0 without one
  std::vector<ExponentialStiffness> memory; ///< the memory kernel's terms; none without memory
  Eigen::SparseMatrix<double> M;            ///< mass; 0 x 0 for the quasistatic march
  LoadHistory load;                         ///< f(t)
  /// K, C, M and the memory terms hold only this rank's rows of an mpirun job (the other rows
  /// empty; f(t) whole): the schemes sum their products over the ranks
  /// (solver/symmetric_product.hpp) and MUMPS factorizes their step matrix over them.
  bool rank_rows = false;

  int num_dofs() const { return static_cast<int>(K.rows()); }
};

} // namespace sig
