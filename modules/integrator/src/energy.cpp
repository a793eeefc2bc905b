#include "integrator/energy.hpp"

#include "core/error.hpp"
#include "integrator/elastodynamics.hpp"
#include "integrator/time_scheme.hpp"

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

} // namespace sig
