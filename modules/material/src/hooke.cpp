#include "material/hooke.hpp"

#include "core/datafile.hpp"

#include <cmath>
#include <sstream>

namespace sig {

double Hooke::mu() const {
  return E / (2.0 * (1.0 + nu));
}

double Hooke::lambda() const {
  // Plane stress replaces lambda by 2 lambda mu / (lambda + 2 mu) = E nu / (1 - nu^2).
  if (plane == PlaneMode::stress) return E * nu / (1.0 - nu * nu);
  return E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
}

Eigen::Matrix3d Hooke::D() const {
  const double l = lambda();
  const double m = mu();
  Eigen::Matrix3d d;
  d << l + 2 * m, l, 0, //
      l, l + 2 * m, 0,  //
      0, 0, m;
  return d;
}

Eigen::Matrix<double, 6, 6> isotropic_d3(double lambda, double mu) {
  Eigen::Matrix<double, 6, 6> d = Eigen::Matrix<double, 6, 6>::Zero();
  d.topLeftCorner<3, 3>().setConstant(lambda);
  for (int k = 0; k < 3; ++k) {
    d(k, k) += 2 * mu;
    d(3 + k, 3 + k) = mu;
  }
  return d;
}

Eigen::Matrix<double, 6, 6> Hooke::D3() const {
  return isotropic_d3(E * nu / ((1 + nu) * (1 - 2 * nu)), mu());
}

Eigen::Vector3d Hooke::stress(const Eigen::Vector3d& strain) const {
  return D() * strain;
}

double Hooke::energy_density(const Eigen::Vector3d& strain) const {
  return 0.5 * strain.dot(D() * strain);
}

double Hooke::stress33(const Eigen::Vector3d& strain) const {
  if (plane == PlaneMode::stress) return 0.0;
  const Eigen::Vector3d s = stress(strain);
  return nu * (s(0) + s(1));
}

double Hooke::von_mises(const Eigen::Vector3d& strain) const {
  const Eigen::Vector3d s = stress(strain);
  return von_mises_stress(s(0), s(1), s(2), stress33(strain));
}

double von_mises_stress(double s11, double s22, double s12, double s33) {
  const double j2 =
      ((s11 - s22) * (s11 - s22) + (s22 - s33) * (s22 - s33) + (s33 - s11) * (s33 - s11)) / 6.0 +
      s12 * s12;
  return std::sqrt(3.0 * j2);
}

Hooke hooke_from_card(const Card& card) {
  return hooke_from_card(card, plane_mode_from_card(card));
}

Hooke hooke_from_card(const Card& card, PlaneMode plane) {
  Hooke law;
  law.E = card.real("E"); // E > 0, -1 < nu < 0.5: the card's ranges (core/ranges.hpp)
  law.nu = card.real("nu");
  law.plane = plane;
  return law;
}

PlaneMode plane_mode_from_card(const Card& card) {
  return card.choice("plane", {"strain", "stress"}) == "stress" ? PlaneMode::stress
                                                                : PlaneMode::strain;
}

} // namespace sig
