#pragma once
// The statuses the thesis reports per contact node (SCENES.md "Contact and friction laws",
// ALGORITHMS.md 0.5), read off the kernel's branches (contact_kernel.hpp) at the converged state:
//   normal      free (no normal force), CN (compliance, 0 < q_n < g), CU (on the wall: the
//               Signorini contact or the unilateral wall of (1.26)), held (a Dirichlet condition
//               holds the normal component: out of contact, ContactLaw::held_normal)
//   tangential  S= (stick, the kernel's stick branch), S+ / S- (slip towards +t / -t: a zero
//               Tresca threshold slips everywhere), or none: no friction law, Coulomb-type friction
//               (coulomb, nonmonotone) on a node with no normal force (no friction acts), or a zero
//               bound with nothing to slip along. In 3D a slipping node is S+: it slips along
//               its slip's direction, which the solution's slip vector gives (contact.csv's
//               slip_1..3)
// The integer codes are the ones DS files store (case.b arrays normal_status, friction_status).
#include "contact/contact_kernel.hpp"

#include <string>

namespace sig {

enum class NormalStatus { free = 0, compliance = 1, unilateral = 2, held = 3 };
enum class FrictionStatus { none = 0, stick = 1, slip_forward = 2, slip_backward = 3 };

NormalStatus normal_status(const ContactKernel& kernel);
FrictionStatus friction_status(const ContactLaw& law, const ContactKernel& kernel);
NormalStatus normal_status(const ContactKernelIn<3>& kernel);
FrictionStatus friction_status(const ContactLaw& law, const ContactKernelIn<3>& kernel);

/// "free", "CN", "CU", "held"; "-", "S=", "S+", "S-" (the thesis's labels).
std::string label(NormalStatus status);
/// The same for a node of law `law`: the laws in velocity call CN and CU RNI (instantaneous normal
/// response, 0 < v_n < g) and CUV (unilateral condition in velocity, v_n = g), as chapter 5.
std::string label(NormalStatus status, const ContactLaw& law);
std::string label(FrictionStatus status);
/// The statuses of their DS codes; sig::Error for a code out of range.
NormalStatus normal_status_of_code(long code);
FrictionStatus friction_status_of_code(long code);

} // namespace sig
