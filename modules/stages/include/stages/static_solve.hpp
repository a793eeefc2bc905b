#pragma once
// The static problem of sig-solve: a linear elastic bulk, with or without node-to-rigid contact.
// Without contact it is one factorization and one solve. With contact the stiffness is turned
// into nodal frames (tangent, normal) at the contact nodes and condensed once onto their normal
// displacements, and their slips when some element has friction (one sparse factorization,
// solver/schur.hpp); the contact method then iterates on the small dense problem
// (solver/condensed_bulk.hpp) with the one Newton driver (solver/contact_newton.hpp). A
// nonmonotone friction law runs the convexification loop (solver/convexification.hpp) on that
// one condensed problem, its outer test in the norm ||eps(u)||_L2 of the whole body.
#include "assembly/system.hpp"
#include "contact/contact_elements.hpp"
#include "contact/contact_status.hpp"
#include "solver/contact_method.hpp"
#include "solver/contact_newton.hpp"
#include "solver/convexification.hpp"
#include "solver/mumps_statistics.hpp"

#include <map>
#include <optional>
#include <string>

namespace sig {

struct Mesh;

struct StaticSolution {
  Eigen::VectorXd u;          ///< full displacement (d dofs per node)
  Eigen::VectorXd multiplier; ///< normal contact force per element (empty without contact)
  /// tangential contact force per element: along t in 2D, the components along t1, t2 in 3D
  /// with friction (two per element, element i's at 2 i)
  Eigen::VectorXd tangential;
  std::vector<NormalStatus> normal_status;
  std::vector<FrictionStatus> friction_status;
  bool converged = true;
  NewtonFailure reason = NewtonFailure::none; ///< why it did not converge (newton_guard.hpp)
  std::string failure;
  double drift = 0;                     ///< reason drift: the length of the unbounded step
  std::vector<IterationRecord> history; ///< every Newton iteration (of every convex solve)
  std::optional<ConvexificationResult> convexification; ///< with a nonmonotone law
  int unknowns = 0;                      ///< dofs of the Newton vector, as the thesis counts them
  std::map<std::string, double> seconds; ///< factorize, frames, schur, solve
  std::string ordering; ///< of MUMPS's analysis (SchurComplement::ordering); empty for the others
  int ranks = 1;        ///< the processes of the solve (mpirun -np)
  std::optional<MumpsStatistics> mumps; ///< MUMPS's factorization of the condensation
};

/// The convexification loop of a nonmonotone law: its options, and the mesh whose ||eps(u)||_L2
/// is the norm of V in its outer test (null: the Euclidean norm of the nodal displacements).
struct StaticConvexification {
  ConvexificationOptions options;
  const Mesh* mesh = nullptr;
};

StaticSolution solve_linear_elasticity(const LinearSystem& system, const std::string& backend);

/// The Dirichlet conditions of `system` on contact nodes (a roller on a corner of Gamma3) moved
/// into the laws of `contact`, each in the node's frame: a held normal component takes the node
/// out of contact (ContactLaw::held_normal, a warning naming it), a held tangential one sticks
/// at its slip (held_tangent; in 3D the node's other tangent keeps its friction law). Returns the
/// held dofs, sorted: the contact solve imposes them, so the reduced system keeps them free.
/// sig::Error naming the node for a held component that is neither the node's normal nor one of
/// its tangents (contact_frame: in 3D an axis of the tangent plane that is not t1 or t2).
std::vector<int> hold_on_contact_nodes(const LinearSystem& system, ContactElements& contact);

/// Where the mesh axis `component` sits in a contact node's frame (contact_frame: its tangents
/// and -n as columns): along its normal (a held component takes the node out of contact), along
/// its tangent `tangent` (a held slip), or neither (an axis that mixes them: refused).
struct HeldAxis {
  enum class Kind { normal, tangent, oblique } kind = Kind::oblique;
  int tangent = -1;         ///< k of t_k when kind == tangent
  double along_normal = 0;  ///< e_c . n
  double along_tangent = 0; ///< e_c . t_k when kind == tangent
};
HeldAxis held_axis(const ContactFrame& frame, int component);
/// The words of the refusal of an oblique held axis, after "a DIRICHLET card ".
std::string oblique_hold_problem(const ContactElements& contact, int p, int component);

/// Before the solve, with the deck: a DIRICHLET card that holds a component of a contact node
/// that hold_on_contact_nodes cannot honour (an oblique axis; any held component under
/// method=penalty) is an InputError naming the card's file, line and field.
void verify_held_contact_components(const Mesh& mesh, const Datafile& datafile,
                                    const LinearSystem& system, const ContactElements& contact,
                                    const std::string& method);

/// Why SOLVER candidate_gap= cannot serve these contact elements (a law that acts on nodes apart
/// from the obstacle: Tresca, compliance-bilateral, a law of the velocity, the nonmonotone loop),
/// or empty.
std::string candidate_zone_problem(const ContactElements& contact);

/// `start` (empty: 0) is the first iterate of the displacement, d dofs per node: a warm start.
/// The contact elements (indices, increasing) a solve condenses under SOLVER candidate_gap=
/// `bound`: those of initial gap at most `bound`, and those with a Dirichlet condition (held in
/// their frames by the contact solve).
std::vector<int> candidates(const LinearSystem& system, const ContactElements& contact,
                            double bound);

/// With a finite parameters.candidate_gap only the contact nodes of small initial gap are
/// condensed, the zone widening until no node outside it comes to touch (the history then holds
/// every round's iterations); sig::Error if candidate_zone_problem says it cannot serve.
/// A nonmonotone law runs the loop with `loop`. Dirichlet conditions on contact nodes are held
/// in the nodes' frames (hold_on_contact_nodes). Non-convergence of the method (or of the loop)
/// is returned; a body with a rigid motion that neither its
/// Dirichlet conditions nor its contact laws can hold (no equilibrium exists) is a sig::Error.
StaticSolution solve_static_contact(const LinearSystem& system, ContactElements contact,
                                    const ContactSolverParameters& parameters,
                                    const std::string& backend, const Eigen::VectorXd& start = {},
                                    const StaticConvexification& loop = {});

} // namespace sig
