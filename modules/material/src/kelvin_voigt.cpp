#include "material/kelvin_voigt.hpp"

#include "core/datafile.hpp"

#include <cmath>

namespace sig {

Eigen::Matrix3d Viscosity::D() const {
  Eigen::Matrix3d d;
  d << eta1 + eta2, eta1, 0, //
      eta1, eta1 + eta2, 0,  //
      0, 0, 0.5 * eta2;
  return d;
}

Eigen::Matrix<double, 6, 6> Viscosity::D3() const {
  return isotropic_d3(eta1, 0.5 * eta2); // Lame constants (eta1, eta2 / 2)
}

Viscosity viscosity_from_card(const Card& card) {
  const auto coefficient = [&](const char* field) {
    const double eta = card.real(field, 0.0);
    if (!(eta >= 0) || !std::isfinite(eta))
      card.fail(field, "a viscosity must be >= 0 (eta1 = eta2 = 0: no viscosity)");
    return eta;
  };
  return {coefficient("eta1"), coefficient("eta2")};
}

MemoryTerm memory_term_from_card(const Card& card, PlaneMode plane) {
  MemoryTerm term;
  term.modulus = hooke_from_card(card, plane);
  term.beta = card.real("beta");
  if (!(term.beta > 0) || !std::isfinite(term.beta))
    card.fail("beta", "the decay rate of exp(-beta t) must be > 0");
  return term;
}

} // namespace sig
