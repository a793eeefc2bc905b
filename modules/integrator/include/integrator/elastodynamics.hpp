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
#include <vector>

namespace sig {

struct LinearSystem;
struct Mesh;
struct ReducedSystem;

/// f(t) on the free dofs.
using LoadHistory = std::function<Eigen::VectorXd(double)>;

/// A load that does not change in time.
LoadHistory constant_load(Eigen::VectorXd f);
/// The loads of a reduced system, f_f(t) - K_fd u_d (ReducedSystem::load_at).
LoadHistory reduced_load(const ReducedSystem& reduced);

struct Elastodynamics {
  Eigen::SparseMatrix<double> K; ///< stiffness on the free dofs, symmetric
  Eigen::SparseMatrix<double> M; ///< mass on the free dofs, symmetric positive (semi)definite
  LoadHistory load;              ///< f(t); empty = no load

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

/// The full-size mass of `choice`: system.M, diag(system.M_lumped), or the EMM built from the
/// consistent mass with the 0-based nodes of Gamma3 `contact_nodes` (ignored for the other
/// choices). sig::Error if the system has no mass (every density 0).
Eigen::SparseMatrix<double> mass_matrix(const LinearSystem& system, MassChoice choice,
                                        const Mesh& mesh,
                                        const std::vector<int>& contact_nodes = {});

/// The reduced problem: K_ff, M_ff of the full-size `mass`, the loads reduced_load(reduced).
Elastodynamics reduced_elastodynamics(const ReducedSystem& reduced,
                                      const Eigen::SparseMatrix<double>& mass);

} // namespace sig
