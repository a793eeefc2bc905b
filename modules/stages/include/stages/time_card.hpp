#pragma once
// The cards of a dynamic case (stage sig-march):
//
//   TIME scheme=midpoint|newmark T= k= [output_every=1] [mass=consistent|lumped|emm]
//        [stress=gonzalez|midpoint]   (hyperelastic bodies: the stress of a time step,
//                                      material/algorithmic_stress.hpp; default gonzalez)
//   TIME scheme=quasistatic T= k= [output_every=1]   (ch. 5: no inertia, a march in velocity,
//                                                      integrator/kelvin_voigt_scheme.hpp)
//   TIME scheme=backward-euler T= k= [output_every=1] [mass=consistent|lumped]   (ch. 6: with
//                           inertia, in velocity, integrator/backward_euler_scheme.hpp)
//   INITIAL [u=ux,uy] [v=vx,vy] [region=...]   (repeatable; sets only the fields it gives)
//
// Every check names the file, the line and the field (sig::InputError), so that a bad deck is
// refused before anything is factorized.
#include "assembly/initial.hpp"
#include "integrator/elastodynamics.hpp"
#include "material/algorithmic_stress.hpp"

#include <Eigen/Core>
#include <string>

namespace sig {

class Card;
class Datafile;
struct Mesh;

struct TimeParameters {
  std::string scheme = "midpoint"; ///< time_scheme_names
  double final_time = 0.0;         ///< T
  double k = 0.0;                  ///< time step
  int steps = 0;                   ///< T / k, a whole number
  int output_every = 1;
  MassChoice mass = MassChoice::consistent;
  AlgorithmicStress stress = AlgorithmicStress::gonzalez; ///< hyperelastic bodies only
};

/// The TIME card, checked: k > 0, T > 0, T / k within 1e-9 relative of a whole number of steps,
/// output_every >= 1, mass=emm only when the deck has a CONTACT card (`has_contact`), no mass= in a
/// quasistatic deck.
TimeParameters time_parameters(const Card& time, bool has_contact);

/// The SOLVER fields a TIME deck uses (linear=, maxit=, and the strategies' gamma= and eps=); a
/// warning names each other field given (method=, r= ... belong to sig-solve): a parameter
/// silently ignored is a trap.
void warn_unused_solver_fields(const Card* solver);

} // namespace sig
