// Alart-Curnier augmented Lagrangian, thesis section 3.1.1, (3.7)-(3.19), solved by a generalized
// Newton method on x = (u, lambda, t) with the Lagrange nodes' multipliers as unknowns (Remark
// 3.1): the Newton vector is larger than the displacement vector by one (frictionless) or two
// (with friction) unknowns per Gamma3 node. On the branch [lambda + r (q_n - g)]_+ > 0 the
// multiplier row reads dq_n = g - q_n, on the other lambda = 0; the driver eliminates these rows
// (and the friction rows: stick dq_t = -q_t, slip t = sigma s), so that one linear step of the
// displacements remains, whose reactions are the multipliers. Its stopping test is the thesis's
// (iii): increment and residual, without the active set.
#include "solver/methods.hpp"

namespace sig {

namespace {

class AugmentedLagrangian final : public ContactMethod {
public:
  explicit AugmentedLagrangian(double r) : ContactMethod(r) {}
  std::string name() const override { return "alm"; }
  bool needs_settled_statuses() const override { return false; }
  int multiplier_unknowns(bool friction) const override { return friction ? 2 : 1; }
};

} // namespace

std::unique_ptr<ContactMethod> make_augmented_lagrangian(const ContactSolverParameters& p) {
  return std::make_unique<AugmentedLagrangian>(p.r);
}

} // namespace sig
