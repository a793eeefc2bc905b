// The SOLVER and LOADSTEPS cards (solver_card.hpp).
#include "solver/solver_card.hpp"

#include "core/datafile.hpp"

namespace sig {

SolverCard read_solver_card(const Datafile& datafile) {
  const bool has_contact = datafile.find("CONTACT") != nullptr;
  const Card* card = datafile.find("SOLVER");
  Card defaults; // no SOLVER card: every field takes the schema's default
  defaults.keyword = "SOLVER";
  const Card& solver = card ? *card : defaults;
  SolverCard result;
  result.backend = solver.choice("linear", {"cholmod", "umfpack", "mumps"});
  ContactSolverParameters& p = result.parameters;
  p.method = solver.choice("method", {"linear", "alm", "penalty", "pdas", "projection"},
                           has_contact ? "pdas" : "linear");
  if (p.method == "linear" && has_contact)
    solver.fail("method",
                "the datafile has a CONTACT card: choose alm, penalty, pdas or projection");
  if (p.method != "linear" && !has_contact)
    solver.fail("method", "method " + p.method + " needs a CONTACT card");
  p.r = solver.real("r");
  p.gamma = solver.real("gamma");
  p.c = solver.real("c");
  p.eps = solver.real("eps");
  p.max_iterations = static_cast<int>(solver.integer("maxit", p.max_iterations));
  p.search = solver.choice("search", {"auto", "yes", "no"});
  for (const char* positive : {"r", "gamma", "c", "eps", "maxit"})
    if (solver.has(positive) && solver.real(positive) <= 0)
      solver.fail(positive, "must be positive");

  if (const Card* steps = datafile.find("LOADSTEPS")) {
    result.load_steps = static_cast<int>(steps->integer("n"));
    if (result.load_steps < 1) steps->fail("n", "must be at least 1");
  }
  return result;
}

} // namespace sig
