#pragma once
// sig-march's quasistatic path (TIME scheme=quasistatic, ch. 5): a small-strain body, Hooke or
// Kelvin-Voigt with memory (material/kelvin_voigt.hpp), marched in velocity by
// integrator/kelvin_voigt_scheme.hpp on the linear-bulk march of
// integrator/linear_contact_march.hpp, with node-to-rigid contact in velocity when the deck has a
// CONTACT card:
//
//   TIME scheme=quasistatic T= k= [output_every=1]
//   CONTACT ... law=damped cn= | law=damped-unilateral cn= g= [exclude=]   (laws in velocity)
//   FRICTION ref= law=coulomb mu= [bound=compliance] | law=tresca threshold=   (in velocity)
//   SOLVER [linear=] [method=pdas|alm|penalty|projection] [gamma= r= c=] [eps=] [maxit=]
//   INITIAL u=ux,uy [region=]     (u_0; the first velocity w_0 is 0)
//
// Refused, each on its card and field: a contact law that is not in velocity, strategy= or r= of
// the dynamic strategies, a nonmonotone friction law (its convexification per step is a
// StepSolver the march takes, not wired to the deck yet), INITIAL v=, a hyperelastic law.
// Writes OUTDIR/case.hist (integrator/velocity_history_io.hpp) and OUTDIR/steps.csv. A step whose
// contact Newton fails stops the march: the files hold the steps done, a warning is printed and
// the stage exits 0.
#include "integrator/time_card.hpp"

namespace sig {

class Datafile;
struct StageArgs;

void run_quasistatic_march(const StageArgs& args, const Datafile& datafile,
                           const TimeParameters& time);

} // namespace sig
