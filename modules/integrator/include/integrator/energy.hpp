#pragma once
// The discrete energy (8.33) of small-strain elastodynamics, E_n = 1/2 v_n.M v_n + 1/2 u_n.K u_n
// (the kinetic term is the discrete 1/2 int rho |delta u_n|^2, the elastic one int W with
// Hooke's W), and its balance with the work of the external forces, W_n = sum over the steps of
// f_bar . (u_{m+1} - u_m): without contact the energy-conserving schemes keep E_n - W_n = E_0
// to round-off.
#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace sig {

struct DynamicState;
struct Elastodynamics;

/// The energy part of a step's record (integrator/march.hpp; energy.csv after its step, time and
/// iterations): the energies of the state after the step and the work done since step 0.
struct EnergyRecord {
  double kinetic = 0.0;       ///< 1/2 v.M v
  double elastic = 0.0;       ///< 1/2 u.K u (hyperelastic: sum_T |T| t W(F))
  double total = 0.0;         ///< kinetic + elastic
  double external_work = 0.0; ///< work of the loads since step 0
  // The contact columns; 0 without contact.
  double contact_work = 0.0;    ///< work of the contact forces since step 0
  double max_penetration = 0.0; ///< max over the contact nodes of [u_n - d]_+ (d geometric)
  int active_nodes = 0;         ///< nodes with a positive contact force over the last step
  // The split of the contact work (ALGORITHMS.md 4.4): contact_work = friction_work + the normal
  // forces' work, and the normal work = -(interface - interface at step 0) + wall_work, so that
  //     total + interface - external_work - friction_work - wall_work
  // is constant. Each step's friction and wall work should be <= 0 (they only dissipate).
  double interface = 0.0;     ///< energy stored by the compliance of the foundation now
  double friction_work = 0.0; ///< work of the tangential forces since step 0: -sum T slip
  double wall_work = 0.0;     ///< work of the normal forces not stored in the interface
  /// The contact forces of the last step summed over the nodes, sum N and sum T (the momentum
  /// they give the body over the step is k times their resultant, ALGORITHMS.md 4.8 check 6);
  /// in 3D |sum T|, T the nodes' tangent-plane vectors (on a plane the resultant's magnitude).
  double normal_force = 0.0;
  double tangential_force = 0.0;
};

/// The work done over one step, which the march loop sums into the record's work columns.
struct StepWork {
  double load = 0.0;     ///< f_bar . (u_{n+1} - u_n)
  double normal = 0.0;   ///< -sum N (q_n - q_{n-1}): the normal contact forces'
  double friction = 0.0; ///< -sum T slip: the tangential forces'
};

/// The work columns of `record` after a step of work `work` from the record `before`: the
/// running sums, and the wall's work as the normal work not stored in the interface.
void add_step_work(EnergyRecord& record, const EnergyRecord& before, const StepWork& work);

/// The contact nodes' part of a step's record: the forces N, T over the step, the penetrations
/// after it and the interface energy after it (the state columns), and the work of the forces
/// over the step from the penetrations q_before and the slips (into `work`).
void add_contact_step(EnergyRecord& record, StepWork& work, const Eigen::VectorXd& N,
                      const Eigen::VectorXd& T, const Eigen::VectorXd& q_before,
                      const Eigen::VectorXd& q_after, const Eigen::VectorXd& slip,
                      double interface);

/// 1/2 v.M v.
double kinetic_energy(const Eigen::SparseMatrix<double>& M, const Eigen::VectorXd& v);
/// 1/2 u.K u.
double elastic_energy(const Eigen::SparseMatrix<double>& K, const Eigen::VectorXd& u);

/// The energies of `state` (kinetic, elastic, total; no work).
EnergyRecord energy_of(const Elastodynamics& problem, const DynamicState& state);

} // namespace sig
