#pragma once
// The dynamic backward Euler in velocity of ch. 6, (6.63)-(6.66) (ALGORITHMS.md 3.2), on the
// linear-bulk march (integrator/linear_contact_march.hpp). The unknown of step n is the velocity
// w_n of the free dofs; with M the mass, C the viscosity (Kelvin-Voigt's, 0 for a Hooke body)
// and K the stiffness,
//
//   S   = M / k + C + k K                                             (constant)
//   b_n = f(t_n) - K u_{n-1} + (M / k) w_{n-1}
//   u_n = u_{n-1} + k w_n                                             (6.66)
//
// from u_0, w_0 = u_1 (INITIAL u=, v=; (6.65)). f(t) = f + change(t) holds the moving and ramped
// loads (assembly/time_loads.hpp).
//
// Contact laws in the displacement on the march in velocity. A node's penetration at step n is
// u_n,n - d = k (w_n,n - o_n) with o_n = (d - u_{n-1},n) / k, u_n,n = -n . u the normal
// displacement towards the obstacle and d the initial gap: so a law p(q) of the penetration is the
// law p(k q') of q' = w_n,n - o_n, i.e. the same law with cn k in place of cn and a wall depth
// g / k (velocity_setting), and o_n the march's normal origin (normal_origin). Its tangential
// variable is the slip rate w_t, the variable of FRICTION of=slip-rate (ch. 6, (6.6)); the forces
// stay forces. The methods' parameters are stiffnesses per unit displacement as in a static
// solve (SOLVER r, gamma; c a compliance): per unit velocity they are r k, gamma k and c / k
// (velocity_parameters), so that one SOLVER card means the same whatever k.
//
// Cost. accept() forms K u_n and M w_n once: the next step's right side and the energies of the
// state read them, so a step holds one product with K and one with M (pruned of the stored zeros
// of its x-y couplings) beside its solve. They are the right side's work done at the end of the
// previous step: products_seconds() times them, so that a benchmark counts them with the right
// side, never with the solve.
//
// Energy. Without load, viscosity and contact, E_n = 1/2 w_n.M w_n + 1/2 u_n.K u_n obeys
//   E_n - E_{n-1} = -1/2 (w_n - w_{n-1}).M (w_n - w_{n-1}) - 1/2 (u_n - u_{n-1}).K (u_n - u_{n-1})
//                   - k w_n.C w_n <= 0,
// and a compliance adds its (convex) potential to E: backward Euler never gains energy
// (ALGORITHMS.md 3.6 check 3); friction only takes more.
#include "integrator/linear_contact_march.hpp"
#include "integrator/viscoelastic_problem.hpp"
#include "solver/symmetric_product.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace sig {

class DynamicBackwardEuler final : public VelocityScheme {
public:
  /// The stiffness, viscosity (empty: none), mass and loads of `problem`; k > 0; u0 and w0
  /// (empty: 0); `gap` the initial gap d of each contact node and `setting` their laws of the
  /// displacement and weights (CONT order; both empty without contact). sig::Error if the
  /// problem has memory terms (ch. 6 has none) or for inconsistent sizes.
  DynamicBackwardEuler(ViscoelasticProblem problem, double k, Eigen::VectorXd u0 = {},
                       Eigen::VectorXd w0 = {}, Eigen::VectorXd gap = {},
                       ContactSetting setting = {});

  std::string name() const override { return "backward-euler"; }
  double time_step() const override { return k_; }
  const Eigen::SparseMatrix<double>& step_matrix() const override { return S_; }
  bool rank_rows() const override { return rank_rows_; }
  Eigen::VectorXd right_side(int n) const override;
  void accept(int n, const Eigen::VectorXd& w) override;
  const Eigen::VectorXd& displacement() const override { return u_; }
  /// o_n = (d - u_{n-1},n) / k per contact node (header).
  Eigen::VectorXd normal_origin(int n, const VelocityContact& contact) const override;

  /// The laws of the displacement as laws of w_n: cn k, g / k (header).
  ContactSetting velocity_setting() const;
  /// The method's parameters per unit velocity: r k, gamma k, c / k (header).
  ContactSolverParameters velocity_parameters(ContactSolverParameters parameters) const;

  /// w after the last accepted step (w_0 before the first).
  const Eigen::VectorXd& velocity() const { return w_; }
  /// Wall seconds of the products K u and M w formed by the last accept() (header).
  double products_seconds() const { return seconds_products_; }
  /// 1/2 w.M w and 1/2 u.K u at the last accepted step.
  double kinetic_energy() const;
  double elastic_energy() const;
  bool has_energy() const override { return true; }
  /// kinetic_energy(), elastic_energy(), their sum and, with contact, sum_i w_i times the
  /// compliance's potential of the penetration u_n,i - d_i (contact/contact_kernel.hpp).
  EnergyRecord energy(const VelocityContact* contact) const override;

  const Eigen::SparseMatrix<double>& mass() const { return M_; }

private:
  void update_products();
  /// n . u at contact node p (u_n = -n . u), in the body's dimension.
  double normal_dot_u(const VelocityContact& contact, int p) const;

  LoadHistory load_;
  Eigen::SparseMatrix<double> M_;
  double k_;
  Eigen::SparseMatrix<double> S_;
  Eigen::VectorXd u_, w_;
  bool rank_rows_ = false;
  SymmetricProduct K_product_, M_product_; ///< K u and M_ w
  Eigen::VectorXd Ku_, Mw_;                ///< K u_ and M_ w_
  double seconds_products_ = 0;
  Eigen::VectorXd gap_;
  ContactSetting setting_; ///< the laws of the displacement
};

} // namespace sig
