#include "stages/contact_card.hpp"

#include "contact/contact_elements.hpp"
#include "core/datafile.hpp"
#include "core/log.hpp"

namespace sig {

namespace {

std::string strategy_of(const Card& contact) {
  return contact.choice(
      "strategy", {"signorini", "compliance", "specific-penalty", "two-step", "ipm"}, "signorini");
}

} // namespace

ContactHistoryInfo contact_history_info(const Card& contact) {
  ContactHistoryInfo info;
  info.strategy = strategy_of(contact);
  const ContactStrategyTraits strategy = contact_strategy_traits(info.strategy);
  if (strategy.needs_r && !contact.has("r"))
    contact.fail("r", "strategy=" + info.strategy +
                          " needs the foundation stiffness per unit area r > 0");
  info.r = contact.real("r", 0.0); // > 0 when given: core/ranges.hpp
  if (contact.has("r") && !strategy.needs_r)
    log_warning("CONTACT r= is not used by strategy=" + info.strategy);
  // The strategies define their own normal forces; the card's law must be the default.
  if (contact.has("law") && contact.choice("law", normal_law_choices) != "signorini")
    contact.fail("law", "a TIME deck's contact law is its strategy= (signorini, compliance, "
                        "specific-penalty, two-step, ipm): remove law=");
  const char* depth = contact.has("gap") ? "gap" : "g";
  info.depth = wall_depth(contact);
  if (!(info.depth >= 0)) contact.fail(depth, "must be >= 0");
  if (info.depth > 0 && !strategy.has_wall)
    log_warning(std::string("CONTACT ") + depth + "= sets a unilateral bound, which strategy=" +
                info.strategy + " does not have: its force acts from the obstacle surface (" +
                depth + " is only read by a friction law=mu1|mu2)");
  return info;
}

ContactStrategyParameters contact_strategy_parameters(const Card& contact, const Card* solver) {
  ContactStrategyParameters p;
  p.r = contact.real("r", 0.0);
  if (contact.has("persistency") && !contact_strategy_traits(strategy_of(contact)).has_persistency)
    contact.fail("persistency", "is a field of strategy=two-step");
  p.persistency = contact.choice("persistency", {"midpoint", "increment"}) == "midpoint"
                      ? Persistency::midpoint
                      : Persistency::increment;
  if (solver != nullptr) {
    p.max_iterations = static_cast<int>(solver->integer("maxit", p.max_iterations)); // >= 1
    p.gamma = solver->real("gamma", p.gamma);                                        // > 0
    p.eps = solver->real("eps", p.eps);                                              // > 0
  }
  return p;
}

} // namespace sig
