#pragma once
// The contact Newton's parameter against the problem's own scale. alm's r, pdas's gamma and the
// projection's 1 / c are a pressure per length; the globalized Newton is checked over 1e-2 .. 1e4
// times the contact nodes' natural scale, their normal stiffness over their weight (E / h:
// drivers/robustness.sh). A value far outside, as the card's default 100 (GPa and mm decks) in a
// deck written in Pa and m (1e-10 of E / h), may stall a solve that converges at the scale. Many
// decks converge all the same (the frictionless ones: PDAS's active set does not need it), so the
// stage says it beside a failure only, naming the SOLVER card: a hint, not a verdict.
#include "assembly/system.hpp"
#include "contact/contact_elements.hpp"

#include <optional>
#include <string>

namespace sig {

class Datafile;

/// The median over the contact nodes of n^T K_ii n / weight_i, K_ii the node's d x d diagonal
/// block of `stiffness`; nothing when no node has one (a rank's rows elsewhere, no stiffness).
std::optional<double> natural_contact_scale(const Eigen::SparseMatrix<double>& stiffness,
                                            const ContactElements& contact);

/// The hint, or nothing: `field` (r, gamma or c) of the deck's SOLVER card (or its default) for
/// `method`, against natural_contact_scale, when outside [1e-4, 1e6] times it (a static solve);
/// a march's step matrix is stiffer than K (its mass over k^2), so `lower_only` there.
std::string augmentation_scale_hint(const Datafile& datafile, const std::string& method,
                                    const Eigen::SparseMatrix<double>& stiffness,
                                    const ContactElements& contact, bool lower_only);

/// augmentation_scale_hint's words logged as a warning, if any: called beside a failure.
void hint_augmentation_scale(const Datafile& datafile, const std::string& method,
                             const Eigen::SparseMatrix<double>& stiffness,
                             const ContactElements& contact, bool lower_only);

} // namespace sig
