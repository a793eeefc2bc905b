#pragma once
// Linear isotropic elasticity (Hooke's law) for the 2D problems of the thesis: plane strain for
// every scene (sigma33 = nu (sigma11 + sigma22), eps33 = 0) and plane stress on request. Strains
// and stresses use Voigt vectors with the engineering shear, eps = (e11, e22, 2 e12) and
// sigma = (s11, s22, s12), so that sigma = D eps and the energy density is eps.D.eps / 2.
#include <Eigen/Core>

namespace sig {

class Card;

enum class PlaneMode { strain, stress };

struct Hooke {
  double E = 1.0;  ///< Young's modulus, > 0
  double nu = 0.0; ///< Poisson ratio, -1 < nu < 1/2
  PlaneMode plane = PlaneMode::strain;

  /// Lame's first parameter of the 3D law (plane strain) or of the reduced law (plane stress).
  double lambda() const;
  /// Shear modulus mu = E / (2 (1 + nu)), the same in both modes.
  double mu() const;
  /// The 3x3 elasticity matrix: sigma = D eps with the engineering shear in eps.
  Eigen::Matrix3d D() const;
  /// The 6x6 elasticity matrix of the 3D law (no plane mode: lambda = E nu / ((1 + nu)(1 - 2
  /// nu))), eps = (e11, e22, e33, 2 e23, 2 e13, 2 e12), sigma = (s11, s22, s33, s23, s13, s12).
  Eigen::Matrix<double, 6, 6> D3() const;
  Eigen::Vector3d stress(const Eigen::Vector3d& strain) const;
  /// W(eps) = eps.D.eps / 2, the stored energy per unit volume.
  double energy_density(const Eigen::Vector3d& strain) const;
  /// Out-of-plane stress: nu (s11 + s22) in plane strain, 0 in plane stress.
  double stress33(const Eigen::Vector3d& strain) const;
  /// von Mises equivalent stress of the 3D stress state (with sigma33 in plane strain).
  double von_mises(const Eigen::Vector3d& strain) const;
};

/// The 6x6 matrix of the isotropic 3D tensor of Lame constants (lambda, mu) on Voigt vectors with
/// the engineering shear: lambda tr(eps) I + 2 mu eps. Hooke::D3 and the viscosity's D3.
Eigen::Matrix<double, 6, 6> isotropic_d3(double lambda, double mu);

/// von Mises equivalent stress sqrt(3 J2) of the stress state (s11, s22, s12) with out-of-plane
/// s33 and no out-of-plane shear: what every 2D law reports.
double von_mises_stress(double s11, double s22, double s12, double s33);

/// Hooke's law of a MATERIAL card (fields E, nu, plane = strain | stress, default strain).
/// Throws sig::InputError naming the card line and the field when E <= 0 or nu is outside
/// (-1, 1/2): nu = 1/2 is the incompressible limit, where D does not exist.
Hooke hooke_from_card(const Card& card);
/// The same with the plane mode given, for a card without plane= (a memory term takes its
/// sub-domain's).
Hooke hooke_from_card(const Card& card, PlaneMode plane);

/// The card's `plane=strain|stress` (default strain), for every 2D law.
PlaneMode plane_mode_from_card(const Card& card);

} // namespace sig
