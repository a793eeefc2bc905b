// Primal-dual active set, thesis section 3.2, (3.20)-(3.32): a semi-smooth Newton method on the
// complementarity function lambda - [lambda + gamma (q_n - g)]_+, which is Alart-Curnier's with
// r = gamma. Active nodes get the Dirichlet condition q_n = g (3.31), inactive ones the Neumann
// condition lambda = 0 (3.32); no multiplier unknowns are added to the system. With friction the
// same test on t + gamma q_t splits the active nodes into sticking (q_t = 0 imposed) and slipping
// (t = sigma s) ones, the primal-dual active set of Hueber, Stadler and Wohlmuth. Test (iv) asks
// the active set, stick and slip included, to repeat.
#include "solver/methods.hpp"

namespace sig {

namespace {

class PrimalDualActiveSet final : public ContactMethod {
public:
  explicit PrimalDualActiveSet(double gamma) : ContactMethod(gamma) {}
  std::string name() const override { return "pdas"; }
};

} // namespace

std::unique_ptr<ContactMethod> make_primal_dual_active_set(const ContactSolverParameters& p) {
  return std::make_unique<PrimalDualActiveSet>(p.gamma);
}

} // namespace sig
