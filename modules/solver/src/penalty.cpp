// Penalty method, thesis Remark 3.2: the augmented Lagrangian with its multipliers set to zero,
// so the foundation acts as a bed of springs of stiffness r per unit area (Winkler): the wall
// force is r [q_n - g]_+ and the friction force proj_[-s, s](r q_t), a stick spring r up to the
// slip bound. The result penetrates by pressure / r and creeps by traction / r; a larger r
// penetrates less but conditions the system worse. Newton's method on these piecewise-linear
// forces: nothing is imposed, there are no multiplier unknowns.
#include "solver/methods.hpp"

namespace sig {

namespace {

class Penalty final : public ContactMethod {
public:
  explicit Penalty(double r) : ContactMethod(r) {}
  std::string name() const override { return "penalty"; }
  bool has_multipliers() const override { return false; }
};

} // namespace

std::unique_ptr<ContactMethod> make_penalty(const ContactSolverParameters& p) {
  return std::make_unique<Penalty>(p.r);
}

} // namespace sig
