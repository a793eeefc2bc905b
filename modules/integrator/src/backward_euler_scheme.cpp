#include "integrator/backward_euler_scheme.hpp"

#include "contact/contact_kernel.hpp"
#include "core/error.hpp"
#include "core/log.hpp"

#include <cmath>

namespace sig {

DynamicBackwardEuler::DynamicBackwardEuler(ViscoelasticProblem problem, double k,
                                           Eigen::VectorXd u0, Eigen::VectorXd w0,
                                           Eigen::VectorXd gap, ContactSetting setting)
    : load_(std::move(problem.load)), M_(std::move(problem.M)), k_(k), u_(std::move(u0)),
      w_(std::move(w0)), rank_rows_(problem.rank_rows), gap_(std::move(gap)),
      setting_(std::move(setting)) {
  SIG_VERIFY(k_ > 0 && std::isfinite(k_), "backward Euler: time step k = " << k_);
  SIG_VERIFY(problem.memory.empty(),
             "backward Euler: the dynamic march of ch. 6 has no memory term (MEMORY cards are "
             "for the quasistatic march of ch. 5)");
  SIG_VERIFY(load_, "backward Euler: no load history");
  const int n = problem.num_dofs();
  if (u_.size() == 0) u_ = Eigen::VectorXd::Zero(n);
  if (w_.size() == 0) w_ = Eigen::VectorXd::Zero(n);
  SIG_VERIFY(u_.size() == n && w_.size() == n, "backward Euler: u0 of size "
                                                   << u_.size() << " and w0 of size " << w_.size()
                                                   << " for " << n << " free dofs");
  SIG_VERIFY(M_.rows() == n && M_.cols() == n, "backward Euler: a mass of " << M_.rows() << " x "
                                                                            << M_.cols() << " for "
                                                                            << n << " free dofs");
  // The consistent mass is assembled on the stiffness's pattern, whose x-y couplings it does
  // not have: without those stored zeros a product with it costs half.
  M_.prune(0.0);
  S_ = (1.0 / k_) * M_ + k_ * problem.K;
  if (problem.C.size() > 0) S_ += problem.C;
  K_product_ = SymmetricProduct(problem.K, rank_rows_);
  M_product_ = SymmetricProduct(M_, rank_rows_);
  update_products();
}

void DynamicBackwardEuler::update_products() {
  const Stopwatch clock;
  Ku_ = K_product_(u_);
  Mw_ = M_product_(w_);
  seconds_products_ = clock.seconds();
}

Eigen::VectorXd DynamicBackwardEuler::right_side(int n) const {
  Eigen::VectorXd b = load_(n * k_);
  b -= Ku_;
  b += (1.0 / k_) * Mw_;
  return b;
}

void DynamicBackwardEuler::accept(int, const Eigen::VectorXd& w) {
  SIG_VERIFY(w.size() == u_.size(),
             "backward Euler: a velocity of size " << w.size() << " for " << u_.size());
  u_ += k_ * w;
  w_ = w;
  update_products();
}

double DynamicBackwardEuler::normal_dot_u(const VelocityContact& contact, int p) const {
  return contact.normal[p].dot(u_.segment(contact.first_dof[p], contact.dim()));
}

Eigen::VectorXd DynamicBackwardEuler::normal_origin(int, const VelocityContact& contact) const {
  SIG_VERIFY(gap_.size() == contact.size(), "backward Euler: " << gap_.size() << " gaps for "
                                                               << contact.size()
                                                               << " contact nodes");
  Eigen::VectorXd origin(contact.size());
  for (int p = 0; p < contact.size(); ++p) {
    origin[p] = (gap_[p] + normal_dot_u(contact, p)) / k_; // (d - u_n) / k, u_n = -n . u
  }
  return origin;
}

ContactSetting DynamicBackwardEuler::velocity_setting() const {
  ContactSetting setting = setting_;
  for (ContactLaw& law : setting.law) {
    SIG_VERIFY(!law.in_velocity(),
               "backward Euler: law=" << to_string(law.normal)
                                      << " is a law in velocity; the dynamic march takes laws of "
                                         "the displacement (compliance, ...)");
    law.cn *= k_;
    law.depth /= k_;
  }
  return setting;
}

ContactSolverParameters
DynamicBackwardEuler::velocity_parameters(ContactSolverParameters parameters) const {
  parameters.r *= k_;
  parameters.gamma *= k_;
  parameters.c /= k_;
  return parameters;
}

double DynamicBackwardEuler::kinetic_energy() const {
  return 0.5 * w_.dot(Mw_);
}

double DynamicBackwardEuler::elastic_energy() const {
  return 0.5 * u_.dot(Ku_);
}

EnergyRecord DynamicBackwardEuler::energy(const VelocityContact* contact) const {
  EnergyRecord e;
  e.kinetic = kinetic_energy();
  e.elastic = elastic_energy();
  e.total = e.kinetic + e.elastic;
  if (contact == nullptr) return e;
  SIG_VERIFY(gap_.size() == contact->size() && setting_.size() == contact->size(),
             "backward Euler: " << gap_.size() << " gaps and " << setting_.size() << " laws for "
                                << contact->size() << " contact nodes");
  for (int p = 0; p < contact->size(); ++p) {
    e.interface += setting_.weight[p] *
                   compliance_energy(setting_.law[p], -normal_dot_u(*contact, p) - gap_[p]);
  }
  return e;
}

} // namespace sig
