#include "solver/contact_method.hpp"

#include "core/datafile.hpp"
#include "core/error.hpp"
#include "solver/methods.hpp"

namespace sig {
namespace {

// A SOLVER card without fields: every accessor answers the schema's default.
const Card& solver_defaults() {
  static const Card card = [] {
    Card c;
    c.keyword = "SOLVER";
    return c;
  }();
  return card;
}

} // namespace

double ContactSolverParameters::card_default(const char* field) {
  return solver_defaults().real(field);
}

std::string ContactSolverParameters::card_default_text(const char* field) {
  return solver_defaults().text(field);
}

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
