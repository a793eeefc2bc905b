#pragma once
// sig-march's dynamic march in velocity (TIME scheme=backward-euler, ch. 6): a small-strain body
// with mass, Hooke or Kelvin-Voigt (no memory), marched by the backward Euler of
// integrator/backward_euler_scheme.hpp on the linear-bulk march of
// integrator/linear_contact_march.hpp (the step matrix M / k + C + k K factorized and condensed
// once), with node-to-rigid contact by a law of the displacement:
//
//   TIME scheme=backward-euler T= k= [output_every=1] [mass=consistent|lumped]
//   MATERIAL ... rho= (> 0)                          [law=kelvin-voigt eta1= eta2=: C]
//   INITIAL u=ux,uy v=vx,vy [region=]               (u_0 and w_0 = u_1, (6.65))
//   CONTACT ... law=compliance cn= [c3=] | compliance-unilateral cn= g= | signorini [g=] |
//               compliance-bilateral cn=           [exclude=]
//   FRICTION ref= law=coulomb mu= | tresca threshold= | nonmonotone a= b= alpha= of=slip-rate
//               [bound=]                             (of the slip rate w_t, (6.6))
//   CONVEXIFICATION eps= maxit= relaxation= start=previous|rest|slipped   (nonmonotone)
//   SOLVER [linear=] [method=pdas|alm|penalty|projection] [gamma= r= c=] [eps=] [maxit=]
//
// FRICTION law=nonmonotone runs the convexification loop of solver/convexification.hpp inside
// every step (ALGORITHMS.md 3.3, [choice] C12): mu frozen per node at the previous outer
// iterate's slip rate, from mu(|w_{n-1,t}|) (start=previous), the thesis's relative tests with
// [choice] the contact nodes' velocities (normal and tangential) in place of the whole body's
// ||.||_V: the interior follows them linearly, and its V-norm would cost a sparse solve per
// outer iteration. Its counts per step go to case.hist and steps.csv (outer_iterations,
// outer_converged, status_cycle: the period of a stick-slip cycle the loop stopped on, 0 if
// none).
//
// Refused, each on its card and field: a contact law in velocity, strategy= or r= of the
// midpoint strategies, of=slip (a slip from the reference is not this march's variable), a
// MEMORY card, mass=emm, a body without mass, a hyperelastic law.
//
// Writes OUTDIR/case.hist (stages/history_io.hpp: the per-step contact values of a march in
// velocity, its energies per step (kinetic, elastic, total and the compliance's potential as
// interface: integrator/backward_euler_scheme.hpp) and the convexification counts) and
// OUTDIR/steps.csv (stages/march_tables.hpp). A step whose contact Newton or convexification
// loop fails stops the march: the files hold the steps done, a warning is printed and the stage
// exits 0.
#include "stages/time_card.hpp"

namespace sig {

class Datafile;
struct StageArgs;

void run_backward_euler_march(const StageArgs& args, const Datafile& datafile,
                              const TimeParameters& time);

} // namespace sig
