#pragma once
// sig-march's quasistatic path (TIME scheme=quasistatic, ch. 5): a small-strain body, Hooke or
// Kelvin-Voigt with memory (material/kelvin_voigt.hpp), marched in velocity by
// integrator/kelvin_voigt_scheme.hpp on the linear-bulk march of
// integrator/linear_contact_march.hpp, with node-to-rigid contact in velocity when the deck has a
// CONTACT card:
//
//   TIME scheme=quasistatic T= k= [output_every=1]
//   CONTACT ... law=damped cn= | law=damped-unilateral cn= g= [exclude=]   (laws in velocity)
//   FRICTION ref= law=coulomb mu= [bound=compliance] | law=tresca threshold= |
//            law=nonmonotone a= b= alpha= of=slip-rate   (of the slip rate w_t: d - 1 components
//            a node, the force in the Coulomb cone's disc in 3D)
//   CONVEXIFICATION [eps=] [maxit=] [relaxation=] [start=]   (law=nonmonotone: the loop of
//            stages/convexification_step.hpp in every step)
//   SOLVER [linear=] [method=pdas|alm|penalty|projection] [gamma= r= c=] [eps=] [maxit=]
//   INITIAL u=ux,uy[,uz] [region=]     (u_0; the first velocity w_0 is 0)
//
// Refused, each on its card and field: a contact law that is not in velocity, strategy= or r= of
// the dynamic strategies, law=nonmonotone of=slip (the march's tangential variable is the slip
// rate), INITIAL v=, a hyperelastic law.
// Writes OUTDIR/case.hist (stages/history_io.hpp, with the per-step contact values of a march in
// velocity) and OUTDIR/steps.csv (stages/march_tables.hpp). A step whose
// contact Newton fails stops the march: the files hold the steps done, a warning is printed and
// the stage exits 0.
#include "assembly/dirichlet.hpp"
#include "assembly/system.hpp"
#include "contact/contact_elements.hpp"
#include "integrator/linear_contact_march.hpp"
#include "solver/solver_card.hpp"
#include "stages/time_card.hpp"

#include <optional>

namespace sig {

class Datafile;
struct StageArgs;

/// A quasistatic case as the stage reads it: cards checked, the assembled system on its free
/// dofs, the initial displacement and the contact boundary.
struct QuasistaticCase {
  SolverCard solver;
  LinearSystem system;
  ReducedSystem reduced;
  Eigen::VectorXd u0; ///< free dofs
  std::optional<ContactElements> elements;
  std::optional<VelocityContact> contact; ///< on the free dofs of `reduced`
};

/// The cards of the header checked (InputError naming the line and field), then OUTDIR's case.nopo,
/// case.mili, case.tae and (with a CONTACT card) case.cont.
QuasistaticCase read_quasistatic_case(const StageArgs& args, const Datafile& datafile);

/// The stage: read the case, march, write case.hist and steps.csv, print a summary.
void run_quasistatic_march(const StageArgs& args, const Datafile& datafile,
                           const TimeParameters& time);

} // namespace sig
