#include "solver/contact_method.hpp"

#include "core/error.hpp"
#include "solver/methods.hpp"

namespace sig {

std::unique_ptr<ContactMethod> make_contact_method(const ContactSolverParameters& parameters) {
  const std::string& m = parameters.method;
  if (m == "alm") return make_augmented_lagrangian(parameters);
  if (m == "penalty") return make_penalty(parameters);
  if (m == "pdas") return make_primal_dual_active_set(parameters);
  if (m == "projection") return make_iterative_projection(parameters);
  SIG_VERIFY(false, "unknown contact method '" << m << "'; known: " << contact_method_names);
  return nullptr;
}

} // namespace sig
