#include "integrator/elastodynamics.hpp"

#include "core/error.hpp"

#include <utility>

namespace sig {

LoadHistory constant_load(Eigen::VectorXd f) {
  return [f = std::move(f)](double) { return f; };
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

} // namespace sig
