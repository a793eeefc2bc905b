#include "contact/contact_status.hpp"

#include "core/error.hpp"

namespace sig {

namespace {

template <int d> NormalStatus normal_status_in(const ContactKernelIn<d>& kernel) {
  if (kernel.held) return NormalStatus::held;
  if (kernel.wall_active) return NormalStatus::unilateral;
  // != 0: a bilateral spring in tension is on its compliance branch too.
  return kernel.compliance != 0 ? NormalStatus::compliance : NormalStatus::free;
}

template <int d>
FrictionStatus friction_status_in(const ContactLaw& law, const ContactKernelIn<d>& kernel) {
  if (!law.has_friction()) return FrictionStatus::none;
  if (kernel.stick) return FrictionStatus::stick;
  // A held tangential component beside a free, frictionless one (3D): nothing rubs.
  if (law.friction == FrictionLaw::none) return FrictionStatus::none;
  if (law.has_coefficient() && normal_status_in<d>(kernel) == NormalStatus::free)
    return FrictionStatus::none; // no normal force, so no friction
  if constexpr (d == 2) {
    if (kernel.slip > 0) return FrictionStatus::slip_forward;
    if (kernel.slip < 0) return FrictionStatus::slip_backward;
  } else {
    if (!kernel.slip.isZero()) return FrictionStatus::slip_forward; // along its slip (header)
  }
  return FrictionStatus::none; // a zero bound and nothing to slip along
}

} // namespace

NormalStatus normal_status(const ContactKernel& kernel) {
  return normal_status_in<2>(kernel);
}

FrictionStatus friction_status(const ContactLaw& law, const ContactKernel& kernel) {
  return friction_status_in<2>(law, kernel);
}

NormalStatus normal_status(const ContactKernelIn<3>& kernel) {
  return normal_status_in<3>(kernel);
}

FrictionStatus friction_status(const ContactLaw& law, const ContactKernelIn<3>& kernel) {
  return friction_status_in<3>(law, kernel);
}

std::string label(NormalStatus status) {
  switch (status) {
  case NormalStatus::free:
    return "free";
  case NormalStatus::compliance:
    return "CN";
  case NormalStatus::unilateral:
    return "CU";
  case NormalStatus::held:
    return "held";
  }
  return "?";
}

std::string label(NormalStatus status, const ContactLaw& law) {
  if (!law.in_velocity() || status == NormalStatus::free || status == NormalStatus::held)
    return label(status);
  return status == NormalStatus::compliance ? "RNI" : "CUV";
}

std::string label(FrictionStatus status) {
  switch (status) {
  case FrictionStatus::none:
    return "-";
  case FrictionStatus::stick:
    return "S=";
  case FrictionStatus::slip_forward:
    return "S+";
  case FrictionStatus::slip_backward:
    return "S-";
  }
  return "?";
}

NormalStatus normal_status_of_code(long code) {
  SIG_VERIFY(code >= 0 && code <= 3,
             "normal status code " << code
                                   << " is unknown; known: 0 = free, 1 = CN, 2 = CU, 3 = held");
  return static_cast<NormalStatus>(code);
}

FrictionStatus friction_status_of_code(long code) {
  SIG_VERIFY(code >= 0 && code <= 3, "friction status code "
                                         << code
                                         << " is unknown; known: 0 = none, 1 = S=, 2 = S+, 3 = S-");
  return static_cast<FrictionStatus>(code);
}

} // namespace sig
