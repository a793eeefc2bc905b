#pragma once
// The semi-discrete linear elastodynamics problem without contact,
//     M a + K u = f(t),   u(0) = u0,   v(0) = v0,
// on the free dofs of a Dirichlet-reduced system (assembly/dirichlet.hpp): K = K_ff, M = M_ff and
// f(t) = f_f(t) - K_fd u_d with constant imposed values u_d (their velocity is zero). The mass is
// the consistent one, its row-sum lumping, or the Equivalent Mass Matrix (integrator/emm.hpp).
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <functional>
#include <string>

namespace sig {

/// f(t) on the free dofs.
using LoadHistory = std::function<Eigen::VectorXd(double)>;

/// A load that does not change in time.
LoadHistory constant_load(Eigen::VectorXd f);

struct Elastodynamics {
  Eigen::SparseMatrix<double> K; ///< stiffness on the free dofs, symmetric
  Eigen::SparseMatrix<double> M; ///< mass on the free dofs, symmetric positive (semi)definite
  LoadHistory load;              ///< f(t); empty = no load
  /// K and M hold only this rank's rows of an mpirun job (the other rows empty; f(t) whole):
  /// the schemes sum their products over the ranks and MUMPS factorizes their step operator
  /// over them (integrator/time_scheme.hpp).
  bool rank_rows = false;

  int num_dofs() const { return static_cast<int>(K.rows()); }
  /// f(t), or zero without a load.
  Eigen::VectorXd load_at(double t) const;
};

/// Card field `TIME ... mass=consistent|lumped|emm`.
enum class MassChoice { consistent, lumped, emm };
inline constexpr const char* mass_choice_names = "consistent|lumped|emm";
/// sig::Error listing the choices for an unknown name.
MassChoice mass_choice_from_string(const std::string& name);
std::string to_string(MassChoice choice);

/// The diagonal matrix of a lumped mass vector.
Eigen::SparseMatrix<double> diagonal_mass(const Eigen::VectorXd& lumped);

} // namespace sig
