// The SOLVER and LOADSTEPS cards (solver_card.hpp).
#include "solver/solver_card.hpp"

#include "core/datafile.hpp"

namespace sig {

SolverCard read_solver_card(const Datafile& datafile) {
  const bool has_contact = datafile.find("CONTACT") != nullptr;
  const Card* card = datafile.find("SOLVER");
  const Card defaults;
  const Card& solver = card ? *card : defaults;
  SolverCard result;
  result.backend = solver.choice("linear", {"cholmod", "umfpack", "mumps"}, "cholmod");
  ContactSolverParameters& p = result.parameters;
  p.method = solver.choice("method", {"linear", "alm", "penalty", "pdas", "projection"},
                           has_contact ? "pdas" : "linear");
  if (p.method == "linear" && has_contact)
    solver.fail("method",
                "the datafile has a CONTACT card: choose alm, penalty, pdas or projection");
  if (p.method != "linear" && !has_contact)
    solver.fail("method", "method " + p.method + " needs a CONTACT card");
  p.r = solver.real("r", p.r);
  p.gamma = solver.real("gamma", p.gamma);
  p.c = solver.real("c", p.c);
  p.eps = solver.real("eps", p.eps);
  p.max_iterations = static_cast<int>(solver.integer("maxit", p.max_iterations));
  p.search = solver.choice("search", {"auto", "yes", "no"}, "auto");
  // r, gamma, c, eps > 0, maxit >= 1, LOADSTEPS n >= 1: the cards' ranges (core/ranges.hpp).
  if (const Card* steps = datafile.find("LOADSTEPS"))
    result.load_steps = static_cast<int>(steps->integer("n", 1));
  return result;
}

} // namespace sig
