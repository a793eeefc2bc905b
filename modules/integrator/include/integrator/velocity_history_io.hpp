#pragma once
// What a march in velocity (integrator/linear_contact_march.hpp; sig-march scheme=quasistatic)
// leaves behind: the DS "HIST" and the per-step table steps.csv.
//
// DS HIST, the arrays every HIST has (integrator/history_io.hpp): scheme, linear (text); k, T,
// time_march (scalars); steps, output_every, ndof (integers); output_step, output_time; u and v
// {outputs, ndof} on the full dofs (v the velocity w, zero on the Dirichlet dofs); converged,
// failure. Then: method (text, the contact method); time_factorize (scalar: frames, sparse
// factorization, Schur complement and the condensed problem's Cholesky); sparse_factorizations,
// dense_factorizations (integers: 1 and 1 unless the condensed bulk reordered); per step
// 0 .. the last step done or failed: step, time, newton_iterations, step_converged,
// step_seconds, and of it step_seconds_right_side (the scheme's b_n) and step_seconds_contact
// (the contact problem). With contact: contact_node (1-based mesh nodes, CONT order), weight; per
// step {rows, p} (row 0 the initial state, zeros): velocity_n, velocity_t (the normal velocity
// towards the obstacle and the tangential one), displacement_n (sum of k velocity_n: the normal
// displacement since t = 0), force_n, force_t (nodal forces), normal_status, friction_status
// (contact/contact_status.hpp codes: free 0, RNI 1, CUV 2; none 0, S= 1, S+ 2, S- 3); and
// pressure {outputs, p} (force_n / weight at the kept steps, as the dynamic HIST). A scheme's own
// per-step values (VelocityHistoryInfo::step_columns: the energies of the dynamic march, the
// convexification counts) follow as arrays of one value per step 0 .. the last, and as the last
// columns of steps.csv.
#include "integrator/linear_contact_march.hpp"

#include <Eigen/Core>

#include <filesystem>
#include <string>
#include <vector>

namespace sig {

struct ReducedSystem;

/// What HIST records beside the history.
struct VelocityHistoryInfo {
  std::string scheme;  ///< "quasistatic"
  std::string backend; ///< cholmod | umfpack | mumps
  std::string method;  ///< the contact method
  double k = 0, T = 0;
  int steps = 0, output_every = 1;
  double seconds_factorize = 0;
  int dense_factorizations = 0;
  std::vector<int> contact_nodes; ///< 0-based mesh nodes, empty without contact
  Eigen::VectorXd weight;         ///< nodal weights of the contact nodes
  /// Extra per-step arrays: a name and one value per step 0 .. the last step done or failed.
  struct StepColumn {
    std::string name;
    std::vector<double> values;
  };
  std::vector<StepColumn> step_columns;
};

/// The header line of steps.csv.
inline constexpr const char* velocity_steps_csv_header =
    "step,time,converged,newton_iterations,free,rni,cuv,stick,slip_plus,slip_minus,"
    "max_velocity_n,max_displacement_n,max_pressure,seconds";

/// steps.csv: one row per step done (or failed), 17 significant digits; the status counts and
/// maxima over the contact nodes (0 without contact).
std::string velocity_steps_csv(const VelocityHistory& history, const VelocityHistoryInfo& info);

/// Write the DS HIST (atomic).
void write_velocity_hist(const std::filesystem::path& path, const VelocityHistory& history,
                         const ReducedSystem& reduced, const VelocityHistoryInfo& info,
                         const std::string& title);

} // namespace sig
