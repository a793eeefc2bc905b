// The SOLVER and LOADSTEPS cards (solver_card.hpp).
#include "solver/solver_card.hpp"

#include "core/datafile.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/ranges.hpp"

#include <algorithm>
#include <sstream>
#include <vector>

namespace sig {

namespace {

// A static solve's parameter of one method given beside another is ignored, which is said (the
// studies give every method one SOLVER card, so it is not refused; sig-march says the same of the
// fields a TIME deck does not use).
void warn_parameters_of_other_methods(const Card& solver, const std::string& method) {
  struct Owner {
    const char* field;
    std::vector<std::string> methods;
  };
  static const Owner owners[] = {
      {"r", {"alm", "penalty"}}, {"gamma", {"pdas"}}, {"c", {"projection"}}};
  for (const Owner& owner : owners) {
    if (!solver.has(owner.field) ||
        std::find(owner.methods.begin(), owner.methods.end(), method) != owner.methods.end())
      continue;
    std::string of;
    for (const std::string& m : owner.methods)
      of += (of.empty() ? "method=" : " and method=") + m;
    log_warning(solver.file + ":" + std::to_string(solver.line) + ": SOLVER " + owner.field + "=" +
                solver.text(owner.field) + " is not used by method=" + method +
                " (it is a parameter of " + of + "): ignored");
  }
}

} // namespace

SolverCard read_solver_card(const Datafile& datafile, bool march) {
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
  // method=linear is the solve without contact; every other method needs contact elements.
  const bool linear = p.method == "linear";
  if (linear && has_contact)
    solver.fail("method",
                "the datafile has a CONTACT card: choose alm, penalty, pdas or projection");
  if (!linear && !has_contact)
    solver.fail("method", "method " + p.method + " needs a CONTACT card");
  // Without a CONTACT card no stage reads FRICTION: refuse it rather than ignore it.
  if (const Card* friction = datafile.find("FRICTION"); friction != nullptr && !has_contact)
    friction->fail("ref", "friction needs a CONTACT card on the same reference (this deck has "
                          "none, so no contact stage runs)");
  if (!march && card != nullptr) warn_parameters_of_other_methods(*card, p.method);
  p.r = solver.real("r");
  p.gamma = solver.real("gamma");
  p.c = solver.real("c");
  p.eps = solver.real("eps", p.eps);
  p.max_iterations = static_cast<int>(solver.integer("maxit", p.max_iterations));
  p.search = solver.choice("search", {"auto", "yes", "no"});
  if (solver.has("candidate_gap")) {
    if (march) // said as sig-march says every SOLVER field it does not use
      log_warning(solver.file + ":" + std::to_string(solver.line) +
                  ": SOLVER candidate_gap=" + solver.text("candidate_gap") +
                  " is not used by sig-march (a march condenses every contact node): ignored");
    else
      p.candidate_gap = solver.real("candidate_gap");
  }
  // r, gamma, c > 0, eps, maxit and LOADSTEPS n: the cards' ranges (core/ranges.hpp).

  if (const Card* loop = datafile.find("CONVEXIFICATION")) {
    const Card* friction = datafile.find("FRICTION");
    if (friction == nullptr || friction->choice("law", friction_law_choices) != "nonmonotone")
      loop->fail("", "the convexification loop belongs to FRICTION law=nonmonotone, which this "
                     "deck does not have");
    ConvexificationOptions& o = result.convexification;
    // eps, maxit and relaxation have their ranges in core/ranges.hpp.
    o.eps = loop->real("eps", o.eps);
    o.max_iterations = static_cast<int>(loop->integer("maxit", o.max_iterations));
    o.relaxation = loop->real("relaxation", o.relaxation);
    // A march starts each step's loop from the previous step's slip rate (ALGORITHMS.md 3.3).
    const std::string start =
        loop->choice("start", {"rest", "slipped", "previous"}, march ? "previous" : "rest");
    if (start == "previous" && !march)
      loop->fail("start", "previous is the slip rate of a march's previous time step: a static "
                          "solve has none (rest or slipped)");
    o.start = start == "rest"      ? ConvexificationStart::rest
              : start == "slipped" ? ConvexificationStart::slipped
                                   : ConvexificationStart::given;
  }
  if (const Card* steps = datafile.find("LOADSTEPS")) {
    result.load_steps = static_cast<int>(steps->integer("n"));
    result.small_strain_start = steps->choice("start", {"small-strain", "rest"}) == "small-strain";
  }
  return result;
}

void verify_total_iterations(const Datafile& datafile, int default_maxit, long time_steps) {
  struct Factor {
    const Card* card; ///< nullptr: a default
    const char* field;
    double value;
    std::string text;
  };
  std::vector<Factor> factors;
  const auto number = [](double x) {
    std::ostringstream out;
    out << x;
    return out.str();
  };
  if (time_steps > 0)
    factors.push_back({datafile.find("TIME"), "k", static_cast<double>(time_steps),
                       "TIME T / k = " + number(static_cast<double>(time_steps)) + " steps"});
  if (const Card* steps = datafile.find("LOADSTEPS")) {
    const double n = static_cast<double>(steps->integer("n"));
    factors.push_back({steps, "n", n, "LOADSTEPS n = " + number(n)});
  }
  const auto maxit = [&](const Card* card, const char* keyword, int fallback) {
    const bool given = card != nullptr && card->has("maxit");
    const double value = given ? static_cast<double>(card->integer("maxit")) : fallback;
    factors.push_back(
        {given ? card : nullptr, "maxit", value,
         std::string(keyword) + " maxit = " + number(value) + (given ? "" : " (the default)")});
  };
  maxit(datafile.find("SOLVER"), "SOLVER", default_maxit);
  if (const Card* loop = datafile.find("CONVEXIFICATION"))
    maxit(loop, "CONVEXIFICATION", ConvexificationOptions{}.max_iterations);

  double total = 1;
  std::string product;
  const Factor* largest = nullptr;
  for (const Factor& f : factors) {
    total *= f.value;
    product += (product.empty() ? "" : " x ") + f.text;
    if (f.card != nullptr && (largest == nullptr || f.value > largest->value)) largest = &f;
  }
  const std::string excess = work_excess(max_newton_iterations(), total);
  if (excess.empty()) return;
  const std::string what = "the deck may ask for " + product + " = " + excess +
                           "; lower one of them (to bound a run's wall clock instead, every "
                           "stage takes --time-limit SECONDS)";
  // The product exceeds the bound only with a factor some card gives (the defaults' is 2e4).
  if (largest != nullptr) largest->card->fail(largest->field, what);
  throw InputError(datafile.path, 0, "maxit", what);
}

void warn_unused_iteration_fields(const Datafile& datafile, const std::string& why) {
  const Card* solver = datafile.find("SOLVER");
  if (solver == nullptr) return;
  for (const char* field : {"eps", "maxit", "search", "candidate_gap"})
    if (solver->has(field))
      log_warning(solver->file + ":" + std::to_string(solver->line) + ": SOLVER " + field + "=" +
                  solver->text(field) + " is not used: " + why + ": ignored");
}

void refuse_load_steps(const Datafile& datafile, const std::string& why) {
  if (const Card* steps = datafile.find("LOADSTEPS"))
    steps->fail(steps->has("n") ? "n" : "", "LOADSTEPS would be ignored: " + why +
                                                "; load steps are for a hyperelastic MATERIAL "
                                                "in a static deck (remove the card)");
}

} // namespace sig
