#pragma once
// Kelvin-Voigt viscoelasticity with memory (thesis (5.1), section 1.2.3): the stress of a
// velocity field u with strain rate eps(du/dt),
//
//   sigma(t) = A eps(du/dt(t)) + B eps(u(t)) + int_0^t K(t - s) eps(du/dt(s)) ds,
//
// with the viscosity A (tau) = eta1 tr(tau) I + eta2 tau (the thesis's mu1, mu2, l.9831), B
// Hooke's law (material/hooke.hpp) and the relaxation kernel K a sum of exponential terms
// exp(-beta t) KK, each KK an isotropic elasticity tensor of its own (E, nu). The thesis writes
// eps(du/dt(t)) under the integral (l.8045); its proofs use eps(du/dt(s)) (l.8716), which is what
// a memory means and what this code integrates (ALGORITHMS.md 2.5 item 2).
//
// Cards (sig-material):
//   MATERIAL [region=] law=kelvin-voigt E= nu= eta1= eta2= [plane=] [thickness=] [rho=]
//   MEMORY   [region=] E= nu= beta=        repeatable: one exponential term each (none: K = 0)
// A is the 2D operator as the thesis prints it whatever plane= says (plane= reduces B and the
// memory tensors); on a 3D body (no plane=) A, B and the memory tensors are the 3D tensors, whose
// plane-strain restrictions the 2D ones are; eta1, eta2 >= 0 (eta1 = eta2 = 0: no viscosity, each
// step of the quasistatic march is then a static solve); beta > 0.
#include "material/hooke.hpp"

#include <Eigen/Core>

#include <vector>

namespace sig {

class Card;

/// The viscosity tensor A of (5.1): (A tau) = eta1 tr(tau) I + eta2 tau, i.e. Hooke's form with
/// "Lame" constants (eta1, eta2 / 2) (ALGORITHMS.md 0.7).
struct Viscosity {
  double eta1 = 0; ///< >= 0, the coefficient of tr(tau) I (thesis mu1, GPa s)
  double eta2 = 0; ///< >= 0, the coefficient of tau (thesis mu2, GPa s)

  /// The 3x3 matrix of A on Voigt vectors with the engineering shear (as Hooke::D): sigma = D eps.
  Eigen::Matrix3d D() const;
  /// The 6x6 matrix of A on a 3D body (as Hooke::D3); D() is its plane-strain restriction.
  Eigen::Matrix<double, 6, 6> D3() const;
};

/// One exponential term of the memory kernel: K(t) = exp(-beta t) modulus.
struct MemoryTerm {
  Hooke modulus;   ///< the isotropic tensor KK of the term
  double beta = 1; ///< decay rate, > 0 (1 / time)
};

struct KelvinVoigt {
  Viscosity viscosity;
  std::vector<MemoryTerm> memory; ///< empty: K = 0
};

/// eta1 and eta2 of a MATERIAL law=kelvin-voigt card (each >= 0, default 0); sig::InputError
/// naming the line and field otherwise.
Viscosity viscosity_from_card(const Card& card);

/// The term of a MEMORY card: E > 0, -1 < nu < 1/2, beta > 0, with the plane mode of the
/// sub-domain's law; sig::InputError naming the line and field otherwise.
MemoryTerm memory_term_from_card(const Card& card, PlaneMode plane);

} // namespace sig
