#pragma once
// Saint Venant-Kirchhoff, the simplest hyperelastic law (thesis 1.62): Hooke's law written
// between the Green-Lagrange strain E = (C - I) / 2 and the second Piola-Kirchhoff stress,
//
//   W = lambda / 2 (tr E)^2 + mu E:E,   S = lambda tr(E) I + 2 mu E,
//
// with the Lame parameters of the 3D law. It is not polyconvex and softens in compression (the
// thesis notes there is no global existence result); in plane stress the out-of-plane stretch
// C33 = 1 - 2 lambda tr(E_2D) / (lambda + 2 mu) must stay positive, which fails under large
// in-plane stretching.
#include "material/hyperelastic.hpp"

namespace sig {

class SaintVenantKirchhoff final : public HyperelasticLaw {
public:
  /// E > 0, -1 < nu < 1/2 (sig::Error otherwise).
  SaintVenantKirchhoff(double E, double nu, PlaneMode plane = PlaneMode::strain);

  std::string name() const override { return "svk"; }
  double young() const { return E_; }
  double poisson() const { return nu_; }

  MaterialPoint3d at(const Eigen::Matrix3d& C, bool with_tangent = true) const override;
  double lambda() const override { return E_ * nu_ / ((1.0 + nu_) * (1.0 - 2.0 * nu_)); }
  double mu() const override { return E_ / (2.0 * (1.0 + nu_)); }

private:
  double E_, nu_;
};

} // namespace sig
