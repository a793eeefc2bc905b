#pragma once
// Hyperelastic laws in total Lagrangian form for P1 triangles (thesis 1.60-1.63). A law is
// written once in 3D, as an isotropic function of the right Cauchy-Green tensor C = F^T F; this
// base class reduces it to the 2x2 in-plane deformation gradient F of the 2D problem:
//
//  - plane strain: F33 = 1 (C33 = 1); the 2D stress and tangent are the in-plane blocks of the
//    3D ones;
//  - plane stress: C33 is the root of S33(C) = 0, found by a safeguarded scalar Newton at each
//    point, and the tangent is statically condensed, A_2D = A_pp - A_p3 A_3p / A_33 (with
//    P33 = 0 the out-of-plane stretch is an internal variable of the 2D law).
//
// Energies are per unit reference volume. 2x2 tensors enter the tangent in the row-major Voigt
// order of F, (F11, F12, F21, F22), index 2 i + J:  tangent(2 i + J, 2 k + L) = dP_iJ / dF_kL.
// The 3D material tangent uses the same convention with index 3 I + J.
#include "material/hooke.hpp"

#include <Eigen/Core>
#include <string>

namespace sig {

using Matrix9d = Eigen::Matrix<double, 9, 9>;

/// Energy, stress and tangent at one deformation gradient, computed together (one Newton for
/// the out-of-plane stretch in plane stress).
struct HyperelasticResponse {
  double energy = 0.0;                               ///< W(F), per unit reference volume
  Eigen::Matrix2d stress = Eigen::Matrix2d::Zero();  ///< first Piola-Kirchhoff P = dW/dF
  Eigen::Matrix4d tangent = Eigen::Matrix4d::Zero(); ///< dP/dF, Voigt order (F11, F12, F21, F22)
  double stretch33 = 1.0; ///< F33: 1 in plane strain, from S33 = 0 in plane stress
};

/// The 3D law at one C: W, the second Piola-Kirchhoff stress S = 2 dW/dC and the material
/// tangent CC = 2 dS/dC (index 3 I + J, with both minor symmetries).
struct MaterialPoint3d {
  double energy = 0.0;
  Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
  Matrix9d CC = Matrix9d::Zero();
};

/// The 2D law as a function of the in-plane block C of the right Cauchy-Green tensor: W(C),
/// S = 2 dW/dC and CC = 2 dS/dC (2 x 2 blocks, index 2 I + J, both minor symmetries). In plane
/// strain these are the in-plane blocks of the 3D law at C33 = 1; in plane stress C33 follows C
/// (S33 = 0), W is the reduced energy W(C, C33(C)) and CC is condensed.
struct MaterialPoint2d {
  double energy = 0.0;
  Eigen::Matrix2d S = Eigen::Matrix2d::Zero();
  Eigen::Matrix4d CC = Eigen::Matrix4d::Zero();
};

class HyperelasticLaw {
public:
  virtual ~HyperelasticLaw() = default;

  PlaneMode plane() const { return plane_; }
  /// The card name of the law: "svk" or "ciarlet-geymonat".
  virtual std::string name() const = 0;

  /// Everything at F (det F > 0). Throws sig::Error when F is outside the law's domain
  /// (det F <= 0, or no out-of-plane stretch with zero stress in plane stress).
  HyperelasticResponse response(const Eigen::Matrix2d& F) const;
  double energy(const Eigen::Matrix2d& F) const { return response(F).energy; }
  Eigen::Matrix2d stress(const Eigen::Matrix2d& F) const { return response(F).stress; }
  Eigen::Matrix4d tangent(const Eigen::Matrix2d& F) const { return response(F).tangent; }

  /// The 3D law at C (symmetric, det C > 0); CC only `with_tangent` (zero otherwise: a force
  /// evaluation skips its 81 entries).
  virtual MaterialPoint3d at(const Eigen::Matrix3d& C, bool with_tangent = true) const = 0;
  /// The 2D law at the in-plane C (symmetric, det C > 0): what an algorithmic stress of the
  /// time step is built from (material/algorithmic_stress.hpp); CC only `with_tangent`. Throws
  /// as response().
  MaterialPoint2d in_plane(const Eigen::Matrix2d& C, bool with_tangent = true) const;

  /// Lame parameters of the small-strain limit of the 3D law: S = lambda tr(E) I + 2 mu E +
  /// O(|E|^2) with E = (C - I) / 2.
  virtual double lambda() const = 0;
  virtual double mu() const = 0;
  /// Hooke's law with the same small-strain limit and plane mode: E = mu (3 lambda + 2 mu) /
  /// (lambda + mu), nu = lambda / (2 (lambda + mu)). Its D is the 2D tangent at F = I.
  Hooke linearized() const;

protected:
  explicit HyperelasticLaw(PlaneMode plane) : plane_(plane) {}

  /// The in-plane blocks of the 3D law at C3 = diag(C, 1), plane strain's C (CC only
  /// `with_tangent`). This default takes them from at(); a law overrides it with its 2D closed
  /// form, because the assembly calls it once per triangle and Newton iteration and needs 16 of
  /// the 81 entries of CC.
  virtual MaterialPoint2d at_plane_strain(const Eigen::Matrix2d& C, bool with_tangent) const;

private:
  HyperelasticResponse plane_strain(const Eigen::Matrix2d& F) const;
  HyperelasticResponse plane_stress(const Eigen::Matrix2d& F) const;
  /// C33 > 0 with S33 = 0 for the in-plane block C2 (the scalar Newton of plane stress).
  double out_of_plane_c33(const Eigen::Matrix2d& C2) const;

  PlaneMode plane_;
};

/// dP/dF of the 3D law (index 3 i + J): A_iJkL = delta_ik S_JL + F_iI CC_IJKL F_kK.
Matrix9d first_piola_tangent(const Eigen::Matrix3d& F, const MaterialPoint3d& point);

/// (A x B)_IJKL = A_IJ B_KL, index 3 I + J by 3 K + L.
Matrix9d tensor_outer(const Eigen::Matrix3d& A, const Eigen::Matrix3d& B);
/// (A_IK A_JL + A_IL A_JK) / 2 for a symmetric A: the symmetric identity for A = I, and
/// d(C^-1)/dC = -symmetric_product(C^-1).
Matrix9d symmetric_product(const Eigen::Matrix3d& A);

} // namespace sig
