#pragma once
// The four contact methods of the thesis as policies of the one semi-smooth Newton driver
// (contact_newton.hpp). Each is the Alart-Curnier kernel of contact/contact_kernel.hpp with its
// own augmentation parameters and its own treatment of a node off the wall; one class and file
// each (src/):
//   alm         Alart-Curnier augmented Lagrangian (3.7)-(3.19), generalized Newton on
//               (u, lambda, t): r_n = r_t = r; the thesis's stopping test (iii), without the
//               active set
//   pdas        primal-dual active set (3.20)-(3.32): the same Newton steps with gamma; active
//               nodes are Dirichlet conditions, inactive ones Neumann (lambda = 0)
//   projection  iterative projection (7.16)-(7.22): active iff (q_n - g) + c lambda >= 0, i.e.
//               r_n = 1 / c; a node off the wall gets the Robin condition (7.22), a normal
//               spring w / c, and the multiplier the active-set test sees is 0 at a node the
//               previous iteration left inactive (iterative_projection.cpp says why).
//               [choice] Chapter 7 is frictionless; the tangential test uses r_t = 1 / c too
//   penalty     Remark 3.2: the kernel with lambda = t = 0 and r the foundation stiffness per
//               unit area: the contact forces are springs, there are no multipliers
#include "contact/contact_law.hpp"

#include <limits>
#include <memory>
#include <string>

namespace sig {

/// The contact method and its parameters, as the SOLVER card gives them. The defaults of r, gamma,
/// c and search are the card schema's (core/src/cards.cpp), declared there once; those of maxit
/// and eps depend on the stage (sig-solve's are here, a march's in ContactStrategyParameters), so
/// the schema only names both in its help text, and the card fingerprint records them only when
/// a deck gives them (a march's eps=1e-5 is then a change, not the default).
struct ContactSolverParameters {
  /// The schema's default of the SOLVER field `field`.
  static double card_default(const char* field);
  static std::string card_default_text(const char* field);
  static constexpr int solve_max_iterations = 100; ///< sig-solve's maxit
  static constexpr double solve_eps = 1e-5;        ///< sig-solve's eps

  std::string method = "pdas";          ///< alm | penalty | pdas | projection
  double r = card_default("r");         ///< ALM augmentation / penalty stiffness
  double gamma = card_default("gamma"); ///< PDAS
  double c = card_default("c");         ///< projection
  double eps = solve_eps;               ///< stopping tolerance of test (iv)
  int max_iterations = solve_max_iterations;
  /// Globalization of the contact Newton (solver/NEWTON.md): "auto" and "yes" globalize every
  /// method on every bulk; "no" takes the thesis's full steps (contact_newton.hpp).
  std::string search = card_default_text("search");
  /// The static small-strain solve's candidates (static_solve.hpp): the contact nodes whose
  /// initial gap is at most this are condensed; infinite (every node) by default.
  double candidate_gap = std::numeric_limits<double>::infinity();
};

/// Card field `SOLVER method=` of the contact methods.
inline constexpr const char* contact_method_names = "alm | penalty | pdas | projection";

class ContactMethod {
public:
  explicit ContactMethod(double augmentation) : augmentation_(augmentation) {}
  virtual ~ContactMethod() = default;
  virtual std::string name() const = 0;
  /// r of the kernel, the same for the wall and the friction (r_n = r_t, pressure per unit
  /// length): each method has one parameter.
  double augmentation() const { return augmentation_; }
  /// False for penalty: the kernel's forces are the contact forces, nothing is imposed.
  virtual bool has_multipliers() const { return true; }
  /// The normal multiplier the active-set test sees at a node the previous iteration left off
  /// the wall (`was_inactive`; false at the first iteration).
  virtual double tested_multiplier(double lambda, bool /*was_inactive*/) const { return lambda; }
  /// The normal spring of a node off the wall, of weight w (0: the Neumann condition lambda = 0).
  virtual double inactive_stiffness(double /*weight*/) const { return 0.0; }
  /// Test (iv) asks the statuses to repeat; alm's test (iii) does not.
  virtual bool needs_settled_statuses() const { return true; }
  /// Unknowns beyond the displacements, per contact node (alm: its Lagrange node's multipliers).
  virtual int multiplier_unknowns(bool /*friction*/) const { return 0; }

private:
  double augmentation_;
};

/// The normal spring of a node of law `law` and weight w while it is off the wall: the method's
/// inactive stiffness where there is a wall and multipliers, 0 elsewhere (a compliance has no
/// wall, penalty imposes nothing).
inline double off_wall_stiffness(const ContactMethod& method, const ContactLaw& law, double w) {
  return method.has_multipliers() && law.has_wall() ? method.inactive_stiffness(w) : 0.0;
}

/// The method of `parameters.method`; sig::Error for an unknown name.
std::unique_ptr<ContactMethod> make_contact_method(const ContactSolverParameters& parameters);

} // namespace sig
