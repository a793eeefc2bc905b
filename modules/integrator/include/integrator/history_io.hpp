#pragma once
// What sig-march leaves behind: the DS "HIST" and the per-step energy table energy.csv.
//
// DS HIST (arrays): scheme, mass, linear (text), stress (text, hyperelastic bodies:
// material/algorithmic_stress.hpp); k, T, time_march (scalars); steps,
// output_every, ndof (integers); output_step (step numbers of the kept states, 0 = the
// initial state), output_time; u and v, shape {outputs, ndof}, on the full dofs (imposed values
// on the Dirichlet dofs, whose velocity is zero); step, time, kinetic, elastic, total,
// external_work: one value per step 0 .. steps (energy.hpp, (8.33)); converged (integer, 0 if
// a step's Newton failed and the march stopped there: the per-step arrays then end at the last
// step done and the last state done is kept) and failure (text naming the step, empty otherwise).
//
// With contact (a CONTACT card), also: strategy (text, contact_strategy_names); r and depth
// (scalars: the card's foundation stiffness per unit area and wall depth g, 0 if not given);
// contact_node (1-based mesh nodes of the p contact elements, CONT order); pressure, shape
// {outputs, p}: lambda / weight at the kept states (0 at the initial state); step_converged
// {steps + 1}: 1 for step 0 and every step done, 0 for the failed step and those never reached;
// contact_work, max_penetration, active_nodes, newton_iterations, interface, friction_work,
// wall_work: per step as energy.csv; with friction tangential_pressure {outputs, p}: T / weight.
#include "integrator/march.hpp"
#include "integrator/time_card.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sig {

class Ds;
struct ReducedSystem;

/// The header line of energy.csv; the contact columns are 0 without contact.
inline constexpr const char* energy_csv_header =
    "step,time,kinetic,elastic,total,contact_work,max_penetration,active_nodes,newton_iterations,"
    "interface,friction_work,wall_work,normal_force,tangential_force";

/// energy.csv (header above, one row per record, 17 significant digits). Without contact the
/// schemes solve one linear system per step: newton_iterations is 1 on every step but step 0
/// (0: the initial state is given, not solved for); with contact it counts the strategy's
/// iterations (EnergyRecord).
std::string energy_csv(const std::vector<EnergyRecord>& energy);

/// What HIST records of the CONTACT card of a march with contact.
struct ContactHistoryInfo {
  std::string strategy;
  double r = 0;
  double depth = 0;       ///< g: the wall at penetration g (contact_law.hpp)
  std::vector<int> nodes; ///< 0-based mesh nodes
};

/// The array contact_node: `nodes` (0-based mesh nodes, CONT order) numbered from 1.
void put_contact_nodes(Ds& ds, const std::vector<int>& nodes);

/// One kept state of a march: its step, time, and u and v on the free dofs.
struct KeptState {
  std::int64_t step = 0;
  double time = 0;
  const Eigen::VectorXd* u = nullptr;
  const Eigen::VectorXd* v = nullptr;
};

/// The arrays every HIST has for its kept states: ndof, output_step, output_time, and u and v
/// {outputs, ndof} on the full dofs of `reduced` (imposed values, zero imposed velocity).
void put_kept_states(Ds& ds, const ReducedSystem& reduced, const std::vector<KeptState>& kept);

/// Write the DS HIST of a march on the Dirichlet-reduced problem `reduced` (atomic); `contact`
/// is null for a march without contact; `hyperelastic` records the time step's stress.
void write_hist(const std::filesystem::path& path, const MarchHistory& history,
                const ReducedSystem& reduced, const TimeParameters& time,
                const std::string& linear_solver, double seconds, const std::string& title,
                const ContactHistoryInfo* contact = nullptr, bool hyperelastic = false);

} // namespace sig
