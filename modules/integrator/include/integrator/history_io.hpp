#pragma once
// What sig-march leaves behind: the DS "HIST" and the per-step energy table energy.csv.
//
// DS HIST (arrays): scheme, mass, linear (text); k, T, time_march (scalars); steps,
// output_every, ndof (integers); output_step (step numbers of the kept states, 0 = the
// initial state), output_time; u and v, shape {outputs, ndof}, on the full dofs (imposed values
// on the Dirichlet dofs, whose velocity is zero); step, time, kinetic, elastic, total,
// external_work: one value per step 0 .. steps (energy.hpp, (8.33)).
#include "integrator/march.hpp"
#include "integrator/time_card.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace sig {

struct ReducedSystem;

/// The header line of energy.csv; the contact columns stay 0 until contact strategies march.
inline constexpr const char* energy_csv_header =
    "step,time,kinetic,elastic,total,contact_work,max_penetration,active_nodes,newton_iterations";

/// energy.csv (header above, one row per record, 17 significant digits). The linear schemes
/// solve one linear system per step: newton_iterations is 1 on every step but step 0 (0: the
/// initial state is given, not solved for).
std::string energy_csv(const std::vector<EnergyRecord>& energy);

/// Write the DS HIST of a march on the Dirichlet-reduced problem `reduced` (atomic).
void write_hist(const std::filesystem::path& path, const MarchHistory& history,
                const ReducedSystem& reduced, const TimeParameters& time,
                const std::string& linear_solver, double seconds, const std::string& title);

} // namespace sig
