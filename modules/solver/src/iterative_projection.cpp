// Iterative projection, thesis section 7.2, (7.16)-(7.22): the fixed point
// u_n = -[-u_n - c lambda]_+ (7.18) solved with an implicit scheme on Gamma3 (7.19). Active
// nodes, (q_n - g) + c lambda >= 0, get q_n = g (7.21): the Alart-Curnier test with r = 1 / c.
// Inactive nodes get the Robin condition q_n(k+1) = q_n(k) + c lambda(k+1) (7.22), with lambda
// the pressure: the nodal force is w (q_n(k+1) - q_n(k)) / c, a spring w / c on the normal. A
// small c holds the inactive nodes back, hence more iterations (Table 7.1).
//
// In step (ii) the multiplier of a node the previous iteration left inactive is taken as zero,
// its contact multiplier by Signorini: the Robin force there is the relaxation of the implicit
// scheme (7.19), not a contact force, and vanishes at convergence. Feeding it to (ii) instead
// tests the extrapolation u_n(k) + (u_n(k) - u_n(k-1)) for every c and costs two or three
// iterations more than Table 7.1 reports (measured at N = 128: 16/11/10/9/9 against
// 12/9/8/7/7 for c = 1 ... 1e4; thesis 11/8/7/7/7).
//
// [choice] Chapter 7 has no friction. With a friction law the tangential test uses r_t = 1 / c
// as the normal one, and a slipping node the Neumann condition t = sigma s.
#include "solver/methods.hpp"

namespace sig {

namespace {

class IterativeProjection final : public ContactMethod {
public:
  explicit IterativeProjection(double c) : ContactMethod(1.0 / c) {}
  std::string name() const override { return "projection"; }
  double tested_multiplier(double lambda, bool was_inactive) const override {
    return was_inactive ? 0.0 : lambda;
  }
  /// The Robin spring w / c = w r.
  double inactive_stiffness(double weight) const override { return weight * augmentation(); }
};

} // namespace

std::unique_ptr<ContactMethod> make_iterative_projection(const ContactSolverParameters& p) {
  return std::make_unique<IterativeProjection>(p.c);
}

} // namespace sig
