#pragma once
// The dynamic fields of the CONTACT card (stage sig-march; sig-contact reads the geometry):
//
//   CONTACT ... [strategy=signorini|compliance|specific-penalty|two-step|ipm] [r=] [g=]
//               [persistency=midpoint|increment]
//   SOLVER [maxit=50] [gamma=100] [eps=1e-10]
//
// strategy defaults to signorini; r (foundation stiffness per unit area, nodal force
// r * weight * penetration) is required and > 0 for compliance, specific-penalty and ipm. g (old
// spelling gap=) keeps its static meaning, the depth of the wall beyond the obstacle surface
// (sig-contact stores it in the CONT depth): for ipm it is the allowed penetration; compliance
// and specific-penalty have no bound and ignore it (with a warning). The strategy is the normal
// law: law= other than signorini is refused. persistency (two-step only, default midpoint) is
// what its phase (b) holds at zero (contact_strategy.hpp). SOLVER maxit= sets the strategy's
// Newton iterations per phase, gamma= the PDAS parameter of its walls and friction, eps= the
// driver's tolerance (test (iv), relative). Errors are sig::InputError (file, line, field).
#include "integrator/contact_strategy.hpp"
#include "stages/history_io.hpp"

namespace sig {

class Card;

/// strategy, r, g of the card (the nodes are filled from the CONT file).
ContactHistoryInfo contact_history_info(const Card& contact);

/// The strategy's parameters: r and persistency of the CONTACT card, maxit, gamma and eps of the
/// SOLVER card (may be null).
ContactStrategyParameters contact_strategy_parameters(const Card& contact, const Card* solver);

} // namespace sig
