#pragma once
// The bulk as the contact Newton driver (contact_newton.hpp) sees it: never the mesh, only the
// displacement of each contact node in its nodal frame (slip w_t along t, normal displacement
// w_n towards the obstacle), the bulk residual, and one linearized solve with a condition on
// each of those components. Two bulks implement it:
//   CondensedBulk (condensed_bulk.hpp)  a linear bulk condensed once onto the contact dofs
//   FiniteStrainBulk (stages/)          the hyperelastic residual and tangent of the assembly
//
// Sign convention of a linearized step (frames at the contact nodes): with r the bulk residual
// (internal minus external force), dw the increment and N, T the nodal contact forces after the
// step (N >= 0 pushes the node away from the obstacle, i.e. along -w_n; T opposes slip),
//     r + J dw + N e_n + T e_t = 0     on the two rows of each contact node,
//     r + J dw = 0                     on the other free dofs.
// Each contact component is either imposed (its increment given, its force the reaction) or
// carries a force law linear in the increments:
//     N = force + stiffness dw_n
//     T = force + stiffness dw_t + coupling N + cross dw_n
// (Coulomb's slip, T = sigma mu N: coupling = sigma mu where the normal is imposed, N its
// reaction; otherwise force and cross carry sigma mu times N's own force law).
// In 3D (d = 3) the slip w_t and the force T have two components, along the node's tangents t1
// and t2 (contact_frame): each component has its own condition, and a force law's stiffness is
// a 2 x 2 block, its off-diagonal entry `tangential_12` (dT1/dw_t2 = dT2/dw_t1: the slip
// branch's s r (I - e e^T) / (|z| - s), symmetric). Both components are imposed or neither. The
// per-node vectors of the tangential quantities (slip(), T, StepSolution::tangential_force) are
// then flat, the components of node p at (d - 1) p + k; in 2D that is one value per node.
#include <Eigen/Core>

#include <limits>
#include <vector>

namespace sig {

struct DofCondition {
  bool imposed = false;
  double value = 0; ///< the increment, where imposed
  double force = 0; ///< otherwise: the force law of the header
  double stiffness = 0;
  double coupling = 0; ///< tangential component only: times the node's normal force N
  double cross = 0;    ///< tangential component only: times the node's dw_n
  bool operator==(const DofCondition&) const = default;
};

struct NodeConditions {
  DofCondition normal, tangential; ///< tangential: along t (2D), t1 (3D)
  DofCondition tangential2;        ///< 3D: along t2
  double tangential_12 = 0;        ///< 3D: the force laws' stiffness between w_t1 and w_t2
  /// The condition of tangential component k (0: t or t1, 1: t2).
  DofCondition& tangent(int k) { return k == 0 ? tangential : tangential2; }
  const DofCondition& tangent(int k) const { return k == 0 ? tangential : tangential2; }
};

struct StepSolution {
  Eigen::VectorXd normal_increment; ///< dw_n per contact node
  Eigen::VectorXd normal_force;     ///< N after the step, per node
  Eigen::VectorXd tangential_force; ///< T after the step, d - 1 components per node (header)
  /// ||eps dw||, the force of a proximal term eps dw the step carries (0 without one): where it
  /// balances a part of the residual, the conditions hold no rigid motion of the body that the
  /// load pushes (the driver's unheld steps, contact_newton.hpp).
  double proximal_force = 0;
};

/// |v_p|^2 per contact node of a flat per-node tangential vector (the header's layout: node p's
/// components at (d - 1) p + k, one per node in 2D, where it is v_p^2); v's size a multiple of
/// `nodes`, which the caller checks.
inline Eigen::VectorXd tangential_squares(const Eigen::VectorXd& v, Eigen::Index nodes) {
  const Eigen::Index tangents = nodes > 0 ? v.size() / nodes : 1;
  return Eigen::Map<const Eigen::MatrixXd>(v.data(), tangents, nodes)
      .colwise()
      .squaredNorm()
      .transpose();
}

class ContactBulk {
public:
  virtual ~ContactBulk() = default;

  virtual int contacts() const = 0;
  /// True if the contact nodes' slips are unknowns (friction); otherwise only w_n is, and the
  /// tangential conditions are ignored (T = 0).
  virtual bool has_tangential() const = 0;
  /// The tangential components per contact node where has_tangential(): d - 1.
  virtual int tangents() const { return 1; }

  /// Penetration q_n = w_n - d beyond the obstacle surface, per contact node, and slip q_t
  /// (tangents() components per node, flat as the header says) at the iterate.
  virtual Eigen::VectorXd penetration() const = 0;
  virtual Eigen::VectorXd slip() const = 0;

  /// ||r + contact forces|| over the free dofs at the iterate, with nodal contact forces N and T
  /// (T flat, tangents() per node).
  virtual double equilibrium_residual(const Eigen::VectorXd& N, const Eigen::VectorXd& T) const = 0;
  /// The force the residual test divides by.
  virtual double force_scale() const = 0;
  /// Per contact node, the bulk's stiffness of its normal component (force per length, > 0): the
  /// diagonal entry of the node's normal displacement. It scales the driver's complementarity
  /// residual (contact_newton.hpp), so that every row of the residual is a force.
  virtual Eigen::VectorXd contact_stiffness() const = 0;

  /// The linearized step at the iterate under `conditions` (one per contact node); `normal_force`
  /// holds the present normal forces (a curved obstacle turns them into stiffness). Throws
  /// sig::Error when the step matrix cannot be factorized.
  virtual StepSolution solve(const std::vector<NodeConditions>& conditions,
                             const Eigen::VectorXd& normal_force) = 0;
  /// Move the iterate to (iterate of the last solve) + alpha (its increment); false, and the
  /// iterate undefined until the next move, if that state is outside the bulk's domain (an
  /// inverted element).
  virtual bool move(double alpha) = 0;
  /// A line search's bookkeeping: keep() remembers the present (admissible) iterate, restore()
  /// returns to the kept one without evaluating it again. After keep() the present iterate is
  /// undefined (a bulk may swap it into the kept slot) until the next move() or restore().
  virtual void keep() = 0;
  virtual void restore() = 0;
  /// The watchdog's bookkeeping (contact_newton.hpp): checkpoint() remembers the present
  /// iterate, rewind() makes the remembered one present again (the next solve() linearizes
  /// there). The line search's kept iterate is left as it was.
  virtual void checkpoint() = 0;
  virtual void rewind() = 0;

  /// ||u|| at the iterate and ||u - u of the last solve||, for the increment test.
  virtual double displacement_norm() const = 0;
  virtual double displacement_step() const = 0;

  /// Levenberg-Marquardt damping of the next solves (newton_guard.hpp's Damping): `factor` times
  /// the bulk's rest stiffness diagonal added to its tangent on the free dofs, 0 for none. A
  /// linear bulk has no near-singular tangent to damp and ignores it.
  virtual void damp(double /*factor*/) {}
  /// The longest fraction of the last solve's increment that the bulk trusts its linearization
  /// over (the search of a contact solve's first step starts there instead of at the full
  /// step): infinite for a bulk linear in u; FiniteStrainBulk bounds the change of every
  /// element's stretches.
  virtual double trusted_length() const { return std::numeric_limits<double>::infinity(); }
  /// A bulk whose residual is not linear in u: its steps need a line search.
  virtual bool nonlinear() const = 0;
  /// The bulk's own targets are met (a load step's imposed displacements reached).
  virtual bool settled() const { return true; }
};

} // namespace sig
