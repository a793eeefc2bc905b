#include "stages/time_card.hpp"

#include "core/datafile.hpp"
#include "core/log.hpp"
#include "core/ranges.hpp"
#include "integrator/time_scheme.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sig {

TimeParameters time_parameters(const Card& time, bool has_contact) {
  TimeParameters p;
  p.scheme = time.choice("scheme", {"midpoint", "newmark", "quasistatic", "backward-euler"});
  p.final_time = time.real("T"); // T, k > 0, output_every >= 1: core/ranges.hpp
  p.k = time.real("k");
  // A step count that is not whole would make the last step end before or after T.
  const double ratio = p.final_time / p.k;
  if (const std::string excess = work_excess(max_time_steps(), ratio); !excess.empty())
    time.fail("k", "T / k is " + excess);
  const double steps = std::round(ratio);
  if (steps < 1 || std::abs(ratio - steps) > 1e-9 * ratio) {
    std::ostringstream what;
    what << "T / k = " << ratio << " is not a whole number of steps";
    time.fail("k", what.str());
  }
  p.steps = static_cast<int>(steps);
  const long every = time.integer("output_every");
  p.output_every = static_cast<int>(std::min<long>(every, p.steps));
  if (time_scheme_traits(p.scheme).march == MarchKind::quasistatic && time.has("mass"))
    time.fail("mass", "a quasistatic march has no inertia: remove mass=");
  p.mass = mass_choice_from_string(time.choice("mass", {"consistent", "lumped", "emm"}));
  if (p.mass == MassChoice::emm && !has_contact)
    time.fail("mass", "mass=emm needs a CONTACT card: the Equivalent Mass Matrix (3.54) removes "
                      "the normal inertia of the contact nodes of Gamma3");
  p.stress = algorithmic_stress_named(time.choice("stress", {"gonzalez", "midpoint"}));
  return p;
}

void warn_unused_solver_fields(const Card* solver) {
  if (solver == nullptr) return;
  for (const auto& [name, value] : solver->fields)
    if (name != "linear" && name != "maxit" && name != "gamma" && name != "eps" &&
        name != "candidate_gap")
      log_warning(solver->file + ":" + std::to_string(solver->line) + ": SOLVER " + name + "=" +
                  value +
                  " is not used by sig-march (a TIME deck uses linear=, maxit=, gamma=, eps= and "
                  "candidate_gap=): " +
                  "ignored");
}

} // namespace sig
