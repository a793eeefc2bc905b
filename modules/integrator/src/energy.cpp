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

EnergyRecord energy_of(const Elastodynamics& problem, const DynamicState& state) {
  EnergyRecord r;
  r.kinetic = kinetic_energy(problem.M, state.v);
  r.elastic = elastic_energy(problem.K, state.u);
  r.total = r.kinetic + r.elastic;
  return r;
}

void add_step_work(EnergyRecord& record, const EnergyRecord& before, const StepWork& work) {
  record.external_work = before.external_work + work.load;
  record.contact_work = before.contact_work + work.normal + work.friction;
  record.friction_work = before.friction_work + work.friction;
  record.wall_work = before.wall_work + work.normal + (record.interface - before.interface);
}

void add_contact_step(EnergyRecord& record, StepWork& work, const Eigen::VectorXd& N,
                      const Eigen::VectorXd& T, const Eigen::VectorXd& q_before,
                      const Eigen::VectorXd& q_after, const Eigen::VectorXd& slip,
                      double interface) {
  work.normal = -N.dot(q_after - q_before);
  work.friction = -T.dot(slip);
  record.interface = interface;
  record.max_penetration = q_after.size() ? std::max(q_after.maxCoeff(), 0.0) : 0.0;
  record.active_nodes = static_cast<int>((N.array() > 0).count());
  record.normal_force = N.sum();
  // 3D (two components a node, along t1 and t2): the magnitude of the sum of the tangent-plane
  // vectors, on a plane (one frame at every node) the resultant's.
  record.tangential_force = T.size() == 2 * N.size() && N.size() > 0
                                ? T.reshaped(2, N.size()).rowwise().sum().norm()
                                : T.sum();
}

} // namespace sig
