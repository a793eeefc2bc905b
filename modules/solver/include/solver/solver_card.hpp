#pragma once
// The SOLVER and LOADSTEPS cards as sig-solve reads them, for every executable that solves a
// static deck (sig-solve, sig-bench-finite-strain): one reading, one set of checks.
//
//   SOLVER method=linear|alm|penalty|pdas|projection linear=cholmod|umfpack|mumps
//          r= gamma= c= eps= maxit=
//   LOADSTEPS n= start=small-strain|rest   (hyperelastic laws only; default 1, small-strain)
//   CONVEXIFICATION eps= maxit= relaxation= start=rest|slipped|previous
//                   (FRICTION law=nonmonotone; previous, the default of a march: ch. 6)
#include "solver/contact_method.hpp"
#include "solver/convexification.hpp"

#include <string>

namespace sig {

class Datafile;

struct SolverCard {
  std::string backend;                ///< cholmod | umfpack | mumps (default cholmod)
  ContactSolverParameters parameters; ///< method ("linear" without contact) and its parameters
  int load_steps = 1;
  bool small_strain_start = true;         ///< LOADSTEPS start=small-strain (default) or rest
  ConvexificationOptions convexification; ///< the CONVEXIFICATION card (or its defaults)
};

/// The SOLVER card (absent: the defaults) and LOADSTEPS. The method defaults to pdas with a
/// CONTACT card and to linear without; a contact method without a CONTACT card, linear with
/// one, a non-positive r, gamma, c, eps or maxit, or n < 1 is a sig::Error naming the file,
/// line and field. So is a CONVEXIFICATION card out of range or in a deck without a nonmonotone
/// friction law. `march`: the deck is read by sig-march (a time step's convexification starts
/// from the previous step's slip rate by default); the caller says so rather than the card
/// reader looking up TIME, so that each stage reads only the cards its --help lists.
SolverCard read_solver_card(const Datafile& datafile, bool march = false);

/// Refuse a deck whose bounds multiply to more Newton iterations than a run may take
/// (core/ranges.hpp max_newton_iterations): `time_steps` (a march's T / k; 0 for a static solve)
/// or LOADSTEPS n, times SOLVER maxit (`default_maxit`, the stage's, when the card has none),
/// times CONVEXIFICATION maxit. The error names the largest factor a card gives, lists them all
/// with the product, and points to --time-limit. Called where the run iterates (contact, or a
/// hyperelastic law): elsewhere maxit is unused.
void verify_total_iterations(const Datafile& datafile, int default_maxit, long time_steps = 0);

/// Warn that the SOLVER card's eps=, maxit= and search= are ignored, saying `why` the solve has
/// no iterations (a small-strain deck without contact is one linear solve).
void warn_unused_iteration_fields(const Datafile& datafile, const std::string& why);

/// LOADSTEPS belongs to the large-deformation static solve (a hyperelastic MATERIAL in
/// sig-solve): anywhere else it would be ignored, so a LOADSTEPS card is refused, saying `why`
/// the run has no load steps.
void refuse_load_steps(const Datafile& datafile, const std::string& why);

} // namespace sig
