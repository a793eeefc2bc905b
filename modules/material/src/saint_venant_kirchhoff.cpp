#include "material/saint_venant_kirchhoff.hpp"

#include "core/error.hpp"

namespace sig {

SaintVenantKirchhoff::SaintVenantKirchhoff(double E, double nu, PlaneMode plane)
    : HyperelasticLaw(plane), E_(E), nu_(nu) {
  SIG_VERIFY(E > 0.0 && nu > -1.0 && nu < 0.5,
             "Saint Venant-Kirchhoff law needs E > 0 and -1 < nu < 1/2 (got E = " << E << ", nu = "
                                                                                  << nu << ")");
}

MaterialPoint3d SaintVenantKirchhoff::at(const Eigen::Matrix3d& C, bool with_tangent) const {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d E = 0.5 * (C - I);
  const double trE = E.trace();
  const double l = lambda(), m = mu();
  MaterialPoint3d p;
  p.energy = 0.5 * l * trE * trE + m * E.squaredNorm(); // thesis (1.62), E:E = tr(E^2)
  p.S = l * trE * I + 2.0 * m * E;
  if (with_tangent) p.CC = l * tensor_outer(I, I) + 2.0 * m * symmetric_product(I);
  return p;
}

} // namespace sig
