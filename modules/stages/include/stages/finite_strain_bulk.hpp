#pragma once
// The hyperelastic bulk in large deformation as the contact Newton driver sees it
// (solver/contact_bulk.hpp): the residual f_int(u) - s f_ext and the tangent of the assembly
// module (assembly/nonlinear.hpp), with u = s u_D on the Dirichlet dofs at load factor s.
//
// The body is 2D or 3D (the mesh's dimension d, d dofs a node). Contact kinematics at the
// CURRENT position x_p = X_p + u_p of each contact node: the penetration q_n = -d(x_p) beyond the
// obstacle surface, and the frame contact_frame(n_p) (the tangents and -n_p) of the obstacle's
// normal n_p = n(x_p) (the foundation's normal, thesis Remark 1.1). The Jacobian is
// consistent for any obstacle whose d is the true distance (grad d = n): the constraint rows use
// n, and the contact force N_p n(x_p) adds -N_p dn/dx (the obstacle's curvature, zero for a
// plane) to the tangent; dn/dx is a central difference of Obstacle::normal, since the obstacle
// interface offers n only. Friction (the march's): the slip since the step's start along each
// tangent of the node's present frame (t in 2D, t1 and t2 in 3D; contact_bulk.hpp's flat
// layout), the force law of each tangential component on its rotated dof.
//
// Cost: the Newton matrix keeps ONE sparsity pattern for the whole solve (newton_matrix.hpp), so
// the linear solver's symbolic analysis is done once and a step costs one numeric factorization
// and solve. A move to alpha = 1 is assembled with its tangent (it is accepted in most
// iterations), the other line-search trials with the force only; an accepted force-only trial
// gets its tangent when the next step needs it. evaluations() counts the assemblies.
#include "assembly/nonlinear.hpp"
#include "assembly/pattern.hpp"
#include "contact/contact_elements.hpp"
#include "contact/obstacle.hpp"
#include "material/algorithmic_stress.hpp"
#include "solver/contact_bulk.hpp"
#include "solver/linear_solver.hpp"
#include "solver/newton_matrix.hpp"

#include <memory>
#include <string>
#include <vector>

namespace sig {

struct Mesh;
struct MaterialTable;

/// The data of the hyperelastic contact problem at the final load (scaled by the load factor).
/// The contact nodes must carry no Dirichlet condition.
struct FiniteStrainProblem {
  const Mesh* mesh = nullptr;
  const MaterialTable* materials = nullptr; ///< every sub-domain hyperelastic
  /// sorted, unique, dof = d node + component, d the mesh's dimension
  std::vector<int> dirichlet_dofs;
  Eigen::VectorXd dirichlet_values;         ///< imposed displacement at the final step
  Eigen::VectorXd load;                     ///< external nodal force at the final step (or empty)
  const ContactElements* contact = nullptr; ///< may be null or empty: no contact
  const Obstacle* obstacle = nullptr;       ///< required when there are contact elements
  /// Dynamics: the mass on the mesh's dofs (its entries on the P1 pattern), the time step k and
  /// the stress of a step. Null: a static solve.
  const Eigen::SparseMatrix<double>* mass = nullptr;
  double time_step = 0;
  AlgorithmicStress stress = AlgorithmicStress::gonzalez;
};

class FiniteStrainBulk final : public ContactBulk {
public:
  /// At u = 0. `backend`: cholmod (spd tangent only) | umfpack | mumps; `eps` the tolerance of
  /// settled() on the Dirichlet values. sig::Error for inconsistent input (sizes, a Dirichlet
  /// contact node, an inverted reference configuration).
  FiniteStrainBulk(const FiniteStrainProblem& problem, const std::string& backend, double eps);

  /// The load factor s of the next solves (the targets of the Dirichlet dofs become s u_D).
  void set_load_factor(double s);
  /// A static solve's first iterate: u, or theta u for the largest theta = 1, 1/2, ... 1/64
  /// without an inverted triangle (a linear displacement may fold elements a large one does
  /// not); theta, or 0 when none is admissible and the iterate stays at rest.
  double start_from(const Eigen::VectorXd& u);
  /// The tangent at rest, right after the construction of a static bulk (the first solve()
  /// takes it over into the Newton matrix).
  const Eigen::SparseMatrix<double>& tangent() const { return now_.bulk.tangent; }

  /// Dynamics: the next time step starts from (u_prev, v_prev) (full dofs); the iterate becomes
  /// the predictor u_prev + k v_prev (shortened towards u_prev if it inverts a triangle) and the
  /// slips are measured from u_prev. sig::Error without a mass, or if u_prev has an inverted
  /// triangle.
  void start_time_step(const Eigen::VectorXd& u_prev, const Eigen::VectorXd& v_prev);
  /// (2 / k)(u - u_prev) - v_prev at the iterate; on a dof without mass (the Gamma3 nodes of an
  /// Equivalent Mass Matrix) the mean velocity of the step (u - u_prev) / k: the midpoint
  /// recurrence there is neutral, it neither changes the dynamics nor damps its rounding, and
  /// would make the next predictor (and two-step's persistency) extrapolate noise.
  Eigen::VectorXd velocity() const;

  int contacts() const override { return contacts_; }
  bool has_tangential() const override { return friction_; }
  /// With friction d - 1 (2D: one), else one (the slips are then zeros).
  int tangents() const override { return friction_ ? d_ - 1 : 1; }
  Eigen::VectorXd penetration() const override { return now_.penetration; }
  Eigen::VectorXd slip() const override { return now_.slip; }
  double equilibrium_residual(const Eigen::VectorXd& N, const Eigen::VectorXd& T) const override;
  double force_scale() const override;
  Eigen::VectorXd contact_stiffness() const override;
  StepSolution solve(const std::vector<NodeConditions>& conditions,
                     const Eigen::VectorXd& normal_force) override;
  bool move(double alpha) override;
  void keep() override { swap_states(); }
  void restore() override { swap_states(); }
  void checkpoint() override { checkpoint_u_ = now_.u; }
  void rewind() override;
  double displacement_norm() const override { return now_.u.norm(); }
  double displacement_step() const override { return (now_.u - base_).norm(); }
  bool nonlinear() const override { return true; }
  double trusted_length() const override;
  void damp(double factor) override { damping_ = factor; }
  bool settled() const override;

  const Eigen::VectorXd& displacement() const { return now_.u; }
  /// The stored energy sum_T |T| t W(F) at the iterate.
  double strain_energy() const { return now_.bulk.energy; }
  /// Hyperelastic assemblies so far (line-search trials and completed tangents).
  int evaluations() const { return evaluations_; }

private:
  struct State {
    Eigen::VectorXd u;
    HyperelasticState bulk;
    Eigen::VectorXd penetration; ///< q_n per contact node
    Eigen::VectorXd slip;        ///< q_t, d - 1 per contact node with friction (else zeros)
    std::vector<Point> normal;   ///< obstacle normal at the current position
    double inertia = 0;          ///< ||(2 / k^2) M (u - u_prev)||: dynamics' force scale
    PreviousStrain strain;       ///< dynamics: F and W per triangle at u
    bool has_tangent = false;    ///< bulk.tangent belongs to u
  };

  /// now_ <-> kept_ without copying the tangents: Eigen 3.4's SparseMatrix has no move, so a
  /// plain std::swap of two States copied the tangent three times, twice per Newton iteration
  /// (about 5 % of a one-step solve of the ring at N = 512 in a perf profile, commit abf6cca).
  void swap_states();

  const FiniteStrainProblem& problem_;
  int d_; ///< the mesh's dimension: dofs a node
  int contacts_ = 0;
  bool friction_ = false;
  double eps_;
  SparsityPattern pattern_;
  std::vector<char> dirichlet_;
  std::unique_ptr<LinearSolver> solver_;
  std::unique_ptr<NewtonMatrix> J_;
  double load_factor_ = 1;
  State now_, kept_;
  Eigen::VectorXd base_, step_;
  Eigen::VectorXd checkpoint_u_; ///< the watchdog's iterate (checkpoint())
  int evaluations_ = 0;
  // Dynamics (problem_.mass): the mass on the pattern's layout, the step's start.
  Eigen::SparseMatrix<double> mass_;
  std::vector<char> massless_; ///< per dof: no mass in its column
  PreviousStrain previous_;
  Eigen::VectorXd u_prev_, v_prev_;
  Eigen::VectorXd slip_origin_; ///< u at which the slips are 0
  /// The diagonal of the tangent at rest: the scale of a Dirichlet dof's mismatch in the
  /// residual (a force) and of a contact node's complementarity (contact_stiffness)
  Eigen::VectorXd rest_diagonal_;
  double damping_ = 0; ///< Levenberg-Marquardt's mu (contact_bulk.hpp damp)

  bool dynamic() const { return problem_.mass != nullptr; }

  int node(int p) const { return problem_.contact->node[p]; }
  Eigen::VectorXd load() const;
  /// rest_diagonal_ from the tangent at u = 0.
  void take_rest_diagonal();
  /// Fill s at s.u, the tangent only `with_tangent`; false outside the law's domain.
  bool evaluate(State& s, bool with_tangent);
  /// -N dn/dx at contact node p: the obstacle's curvature (0 for a plane). The friction force's
  /// T dt/dx is left out: the driver hands the normal forces only, and every frictional scene
  /// has a plane obstacle.
  Eigen::MatrixXd curvature_block(int p, double force) const;
  /// The nodal frames (nodal_frames.hpp) of the normals of `s`.
  std::vector<ContactFrame> frames(const State& s) const;
};

} // namespace sig
