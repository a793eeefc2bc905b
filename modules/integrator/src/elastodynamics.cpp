#include "integrator/elastodynamics.hpp"

#include "assembly/dirichlet.hpp"
#include "assembly/system.hpp"
#include "core/error.hpp"
#include "integrator/emm.hpp"

#include <memory>
#include <utility>

namespace sig {

LoadHistory constant_load(Eigen::VectorXd f) {
  return [f = std::move(f)](double) { return f; };
}

LoadHistory reduced_load(const ReducedSystem& reduced) {
  if (reduced.time_loads.empty()) return constant_load(reduced.f);
  // What ReducedSystem::load_at reads, without the stiffness.
  auto loads = std::make_shared<ReducedSystem>();
  loads->f = reduced.f;
  loads->free_dofs = reduced.free_dofs;
  loads->reduced_index = reduced.reduced_index;
  loads->time_loads = reduced.time_loads;
  return [loads](double t) { return loads->load_at(t); };
}

Eigen::VectorXd Elastodynamics::load_at(double t) const {
  if (!load) return Eigen::VectorXd::Zero(num_dofs());
  Eigen::VectorXd f = load(t);
  SIG_VERIFY(f.size() == num_dofs(),
             "load at t = " << t << ": " << f.size() << " values for " << num_dofs() << " dofs");
  return f;
}

MassChoice mass_choice_from_string(const std::string& name) {
  if (name == "consistent") return MassChoice::consistent;
  if (name == "lumped") return MassChoice::lumped;
  if (name == "emm") return MassChoice::emm;
  SIG_VERIFY(false, "unknown mass '" << name << "' (choose " << mass_choice_names << ")");
  return MassChoice::consistent;
}

std::string to_string(MassChoice choice) {
  switch (choice) {
  case MassChoice::consistent:
    return "consistent";
  case MassChoice::lumped:
    return "lumped";
  case MassChoice::emm:
    return "emm";
  }
  return "?";
}

Eigen::SparseMatrix<double> diagonal_mass(const Eigen::VectorXd& lumped) {
  const auto n = lumped.size();
  Eigen::SparseMatrix<double> D(n, n);
  D.reserve(Eigen::VectorXi::Ones(n));
  for (Eigen::Index i = 0; i < n; ++i)
    D.insert(i, i) = lumped(i);
  D.makeCompressed();
  return D;
}

Eigen::SparseMatrix<double> mass_matrix(const LinearSystem& system, MassChoice choice,
                                        const Mesh& mesh, const std::vector<int>& contact_nodes) {
  SIG_VERIFY(system.M.rows() == system.num_dofs() && system.M.nonZeros() > 0,
             "the system has no mass: give the MATERIAL cards a density rho > 0");
  switch (choice) {
  case MassChoice::consistent:
    return system.M;
  case MassChoice::lumped:
    return diagonal_mass(system.M_lumped);
  case MassChoice::emm:
    // Without contact nodes the EMM would be the consistent mass under another name.
    SIG_VERIFY(!contact_nodes.empty(), "mass=emm needs the contact nodes (a CONTACT card)");
    return equivalent_mass_matrix(system.M, mesh, contact_nodes);
  }
  return system.M;
}

Elastodynamics reduced_elastodynamics(const ReducedSystem& reduced,
                                      const Eigen::SparseMatrix<double>& mass) {
  Elastodynamics problem;
  problem.K = reduced.K;
  problem.M = reduced.restrict_matrix(mass);
  problem.load = reduced_load(reduced);
  return problem;
}

} // namespace sig
