#pragma once
// What every march of sig-march leaves behind: the DS "HIST" (one layout for every march, one
// writer), and its per-step tables (stages/march_tables.hpp). The readers: sig-post
// (post/history_vtk.hpp), sig-error, the result checks (post/result_checks.hpp) and the scene
// reports (postproc/, through sig-dump).
//
// Every HIST:
//   scheme, linear (text: the TIME scheme, the linear solver's backend); k, T, time_march
//   (scalars: the seconds of the march); ranks (integer: the processes of the march, mpirun
//   -np; 1 in one process); steps, output_every, converged (integers: 0 if a step
//   failed and the march stopped there), failure (text naming the step and why, empty otherwise);
//   the kept states (step 0, every output_every-th step and the last step done): ndof,
//   output_step, output_time, u and v {outputs, ndof} on the full dofs (imposed values on the
//   Dirichlet dofs, whose velocity is zero; a march in velocity keeps its velocity w in v);
//   per step, rows 0 (the initial state) .. the last step done, then the failed step if one
//   stopped the march: step, time, newton_iterations, step_converged (1 done, 0 failed),
//   step_seconds.
// Optional parts, each where the march has it:
//   mass (text)       a march with a mass (TIME mass=)
//   ordering (text)   MUMPS's ordering of the step matrix (a march in velocity with linear=mumps)
//   stress (text)     a hyperelastic body: the time step's stress (material/algorithmic_stress.hpp)
//   energy            kinetic, elastic, total = kinetic + elastic (energy.hpp, (8.33)); with
//   contact
//                     interface, the energy the foundation's compliance stores (elastodynamics,
//                     hyperelastic dynamics, backward Euler); a failed step repeats the last one
//   balance           external_work; with contact contact_work, friction_work, wall_work,
//                     max_penetration, active_nodes (energy.hpp: total + interface -
//                     external_work - friction_work - wall_work is constant; elastodynamics and
//                     hyperelastic dynamics, the midpoint strategies)
//   setup             time_factorize (scalar: frames, sparse factorization, Schur complement and
//                     the condensed problem's Cholesky), sparse_factorizations,
//                     dense_factorizations (the marches in velocity: the step matrix factorized
//                     and condensed once), and method (text: the contact method, "linear"
//                     without contact); per step step_seconds_right_side (the scheme's b_n) and
//                     step_seconds_contact (the contact problem)
//   contact           contact_node (1-based mesh nodes of the p contact nodes, CONT order),
//                     weight {p}, pressure {outputs, p} (N / weight at the kept states, 0 at step
//                     0); with friction tangential_pressure {outputs, p} (T / weight; 3D:
//                     |T| / weight, T in the node's tangent plane)
//   strategy          strategy (text, contact_strategy_names), r and depth (scalars: the CONTACT
//                     card's foundation stiffness per unit area and wall depth g, 0 if not given)
//   contact per step  the marches in velocity, {rows, p} (row 0 zeros): velocity_n, velocity_t
//                     (the normal velocity towards the obstacle and the tangential one),
//                     displacement_n (sum of k velocity_n: the normal displacement since t = 0),
//                     force_n, force_t (nodal forces), normal_status, friction_status; in 3D
//                     with friction velocity_t and force_t are {rows, p, 2}, the components
//                     along the node's tangents t1, t2 (contact_frame)
//                     (contact/contact_status.hpp codes: free 0, RNI 1, CUV 2; none 0, S= 1,
//                     S+ 2, S- 3)
//   step columns      a march's own per-step values (HistoryInfo::step_columns: the
//                     convexification counts of the backward Euler; free_flight of a linear
//                     contact march, 1 where the predictor was the step: no Newton iteration,
//                     no force), one value per row
// Readers of an older case.hist: the backward-Euler march wrote its interface energy as
// compliance_energy and a total that included it; a march in velocity wrote no
// tangential_pressure (sig-post then reads force_t / weight).
#include "integrator/march.hpp"

#include <Eigen/Core>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sig {

struct ReducedSystem;

/// The CONTACT card of a march with a midpoint strategy (stages/contact_card.hpp).
struct ContactHistoryInfo {
  std::string strategy;
  double r = 0;
  double depth = 0; ///< g: the wall at penetration g (contact_law.hpp)
};

/// What HIST records beside the history (the header's arrays).
struct HistoryInfo {
  std::string scheme;   ///< TIME scheme=
  std::string linear;   ///< cholmod | umfpack | mumps
  std::string ordering; ///< of MUMPS's analysis (empty: another backend, or none)
  int ranks = 1;        ///< the processes of the march (mpirun -np)
  std::string mass;     ///< TIME mass= (empty: a march without mass)
  std::string stress;   ///< a hyperelastic body's stress (empty otherwise)
  double k = 0, T = 0;  ///< TIME k= and T=
  int steps = 0;        ///< the steps of the TIME card
  int output_every = 0; ///< TIME output_every=
  double seconds = 0;   ///< time_march
  /// The marches in velocity: the step matrix's factorizations and the contact method.
  struct Setup {
    double seconds_factorize = 0;
    int dense_factorizations = 0;
    std::string method;
  };
  std::optional<Setup> setup;
  std::vector<int> contact_nodes; ///< 0-based mesh nodes (CONT order); empty without contact
  Eigen::VectorXd weight;         ///< their nodal weights
  bool friction = false;          ///< some contact law has friction
  std::optional<ContactHistoryInfo> strategy;
  /// Extra per-step arrays: a name and one value per row of the history.
  struct StepColumn {
    std::string name;
    std::vector<double> values;
  };
  std::vector<StepColumn> step_columns;
};

/// Write the DS HIST of `history`, a march on the free dofs of `reduced` (atomic). sig::Error
/// for inconsistent sizes (a step column of another length, contact values of another size).
void write_hist(const std::filesystem::path& path, const MarchHistory& history,
                const ReducedSystem& reduced, const HistoryInfo& info, const std::string& title);

} // namespace sig
