#pragma once
// The per-step tables of a march (sig-march), beside its case.hist (stages/history_io.hpp):
//   energy.csv  elastodynamics and hyperelastic dynamics: one row per step done, the energies and
//               the work of the loads and of the contact forces (energy.hpp);
//   steps.csv   the marches in velocity: one row per step done or failed, the Newton iterations,
//               the contact statuses counted, the largest normal velocity, normal displacement and
//               pressure, the seconds; then the energies where the scheme has them and the
//               march's own step columns.
#include "stages/history_io.hpp"

#include <string>

namespace sig {

/// The header line of energy.csv; the contact columns are 0 without contact.
inline constexpr const char* energy_csv_header =
    "step,time,kinetic,elastic,total,contact_work,max_penetration,active_nodes,newton_iterations,"
    "interface,friction_work,wall_work,normal_force,tangential_force";

/// energy.csv (header above, one row per step done, 17 significant digits). Without contact the
/// schemes solve one linear system per step: newton_iterations is 1 on every step but step 0
/// (0: the initial state is given, not solved for); with contact it counts the strategy's
/// iterations.
std::string energy_csv(const MarchHistory& history);

/// The first columns of steps.csv.
inline constexpr const char* steps_csv_header =
    "step,time,converged,newton_iterations,free,rni,cuv,stick,slip_plus,slip_minus,"
    "max_velocity_n,max_displacement_n,max_pressure,seconds";

/// steps.csv: one row per step done (or failed), 17 significant digits; the status counts and
/// maxima over the contact nodes of `info` (0 without contact); then kinetic, elastic, total
/// (and interface with contact) where the history has energies, and info's step columns.
std::string steps_csv(const MarchHistory& history, const HistoryInfo& info);

} // namespace sig
