#include "integrator/energy.hpp"

#include "core/error.hpp"
#include "integrator/elastodynamics.hpp"
#include "integrator/time_scheme.hpp"

#include <algorithm>

namespace sig {

double kinetic_energy(const Eigen::SparseMatrix<double>& M, const Eigen::VectorXd& v) {
  SIG_VERIFY(M.rows() == v.size() && M.cols() == v.size(),
             "kinetic energy: " << v.size() << " velocities for a " << M.rows() << " x " << M.cols()
                                << " mass");
  return 0.5 * v.dot(M * v);
}

double elastic_energy(const Eigen::SparseMatrix<double>& K, const Eigen::VectorXd& u) {
  SIG_VERIFY(K.rows() == u.size() && K.cols() == u.size(),
             "elastic energy: " << u.size() << " displacements for a " << K.rows() << " x "
                                << K.cols() << " stiffness");
  return 0.5 * u.dot(K * u);
}

EnergyRecord energy_record(const Elastodynamics& problem, const DynamicState& state, int step,
                           double external_work) {
  EnergyRecord r;
  r.step = step;
  r.time = state.time;
  r.kinetic = kinetic_energy(problem.M, state.v);
  r.elastic = elastic_energy(problem.K, state.u);
  r.total = r.kinetic + r.elastic;
  r.external_work = external_work;
  return r;
}

void add_contact_step(EnergyRecord& record, const EnergyRecord& before, const Eigen::VectorXd& N,
                      const Eigen::VectorXd& T, const Eigen::VectorXd& q_before,
                      const Eigen::VectorXd& q_after, const Eigen::VectorXd& slip,
                      double interface) {
  const double normal = -N.dot(q_after - q_before), tangential = -T.dot(slip);
  record.contact_work = before.contact_work + normal + tangential;
  record.friction_work = before.friction_work + tangential;
  record.interface = interface;
  record.wall_work = before.wall_work + normal + (interface - before.interface);
  record.max_penetration = q_after.size() ? std::max(q_after.maxCoeff(), 0.0) : 0.0;
  record.active_nodes = static_cast<int>((N.array() > 0).count());
  record.normal_force = N.sum();
  record.tangential_force = T.sum();
}

} // namespace sig
