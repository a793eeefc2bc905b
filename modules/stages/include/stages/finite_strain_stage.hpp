#pragma once
// The large-deformation branch of sig-solve (Scene 7b): a hyperelastic body (some MILI law with
// a hyperelastic part) pressed onto a rigid obstacle in load steps (stages/finite_strain_contact
// .hpp), from the files of the small-strain chain: case.tae gives the Dirichlet dofs with their
// FINAL imposed values and the loads (its K, the linearization at u = 0, is not used), case.cont
// the contact elements and the obstacle.
//
// The support reactions are reported because a thin ring may leave the symmetric branch and
// sway sideways (SCENES.md "Scene 7b"). Against a frictionless plane the horizontal reaction is
// zero by equilibrium whatever the state (the contact forces are all normal to the plane), so it
// cannot show a sway; the moment of the reactions can: for a deck symmetric about x1 = 0 it is
// zero on the symmetric branch and balances the moment of an off-centre contact zone otherwise.
#include "stages/finite_strain_contact.hpp"

#include <filesystem>
#include <memory>
#include <string>

namespace sig {

struct LinearSystem;

struct FiniteStrainStageResult {
  FiniteStrainSolution solution;
  /// Force that the supports exert on the body at the end of the last attempted step, summed
  /// over the Dirichlet dofs: sum of (f_int(u) - s f_ext) over the x (resp. y, z) rows.
  double reaction_x = 0;
  double reaction_y = 0;
  double reaction_z = 0; ///< a 3D body's
  /// Their moment about the origin, at the current positions: sum x1 f2 - x2 f1 (2D).
  double reaction_moment = 0;
  int dim = 2;        ///< the mesh's dimension
  double seconds = 0; ///< wall time of the solve
  /// Tributary length of each contact element (empty without contact): turns the nodal
  /// contact forces of every load step into pressures.
  Eigen::VectorXd contact_weight;
};

/// True if some sub-domain of `table` has a hyperelastic law.
bool has_hyperelastic_law(const MaterialTable& table);

/// The problem of the stages' files: `system`'s Dirichlet dofs, values and loads on `mesh` with
/// the laws of `table` and the contact elements `contact` (null: none), against `obstacle`,
/// made here from the contact's when it has nodes and kept alive by the caller. A march adds its
/// mass, time step and stress.
FiniteStrainProblem finite_strain_problem(const Mesh& mesh, const MaterialTable& table,
                                          const LinearSystem& system,
                                          const ContactElements* contact,
                                          std::unique_ptr<Obstacle>& obstacle);

/// Load-stepped Newton for the data of `system` (Dirichlet dofs and values, loads f), with the
/// contact elements `contact` (may be null: no contact). sig::Error as in
/// solve_finite_strain_contact, and if a sub-domain is not hyperelastic.
FiniteStrainStageResult solve_finite_strain_stage(const Mesh& mesh, const MaterialTable& table,
                                                  const LinearSystem& system,
                                                  const ContactElements* contact,
                                                  const FiniteStrainOptions& options);

/// DS "B" of a finite-strain solve: u, multiplier, status of the last attempted step; method,
/// linear, converged (1 iff every step converged), iterations (total), dofs, failure, load_steps;
/// per step step_load, step_iterations, step_converged; the histories of all steps concatenated
/// (put_history's arrays, history_step = 1-based step, history_step_length = the line search's
/// alpha);
/// finite_strain = 1; scalars reaction_x, reaction_y, reaction_moment, time_solve (the start
/// included); the first iterate: start ("small-strain", "rest", or "rest (fallback)" when the
/// small-strain start failed) and with a small-strain start start_iterations (its contact
/// Newton), start_fraction (theta of FiniteStrainBulk::start_from), start_note (why it fell
/// back, or empty), time_start.
/// One state per CONVERGED load step (the attempted steps stop at the first failure, so these
/// are steps 1 .. s, s = number of rows; row k belongs to step_load[k]), for ParaView's series
/// and Fig 7.13: step_u {s, ndof}; with contact step_multiplier, step_status, step_normal_status
/// (codes of contact/contact_status.hpp), step_pressure {s, m} (m contact elements, pressure =
/// multiplier / weight, the nominal pressure per unit reference length). s = 0 writes no step_*
/// state arrays. The final state's contact arrays are put_contact_state's (solution_ds.hpp).
void write_finite_strain_solution(const std::filesystem::path& path,
                                  const FiniteStrainStageResult& result, const std::string& method,
                                  const std::string& backend, const std::string& title);

} // namespace sig
