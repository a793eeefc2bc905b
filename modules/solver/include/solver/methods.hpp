#pragma once
// The four contact methods (contact_method.hpp), one file each in src/.
#include "solver/contact_method.hpp"

namespace sig {

std::unique_ptr<ContactMethod> make_augmented_lagrangian(const ContactSolverParameters& p);
std::unique_ptr<ContactMethod> make_primal_dual_active_set(const ContactSolverParameters& p);
std::unique_ptr<ContactMethod> make_iterative_projection(const ContactSolverParameters& p);
std::unique_ptr<ContactMethod> make_penalty(const ContactSolverParameters& p);

} // namespace sig
