// The hyperelastic bulk of the large-deformation contact solve (finite_strain_bulk.hpp).
#include "stages/finite_strain_bulk.hpp"

#include "assembly/p1_simplex.hpp"
#include "assembly/rigid_motion.hpp"
#include "core/error.hpp"
#include "material/mili.hpp"
#include "mesh/mesh.hpp"
#include "solver/nodal_frames.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace sig {

namespace {

/// The largest spectral norm of an element's linearized stretch change alpha grad_x du that a
/// static step is trusted with (trusted_length): the update maps each element by
/// I + alpha grad_x du, which keeps it one to one while that norm is below 1 (the sharp bound:
/// det > 0); at 1/2 every principal stretch stays within a factor [1/2, 3/2] of the present one
/// and the area within [1/4, 9/4], where the tangent of the law at the present state still
/// describes the element. [choice] 1/2, the bound with that reading, not a fit. The contact
/// driver starts only the first step of a contact solve there (its cold active set): bounding
/// every step stalled a clamped block (the gradient of a linear step is singular at a clamped
/// corner, trusted lengths 0.07 down to 0.002, then cycling). Measured on every relaxed step on
/// the seven off-scene rings of drivers/ring-meshes.sh (pdas, both starts, 14 pairs within 1.3x
/// of GetFEM): 1/2 13, 0.35 and 0.7 14, 1/4 13, 1 (the sharp bound) 9, no bound 6; the first
/// step only, 1/2: 13 (modules/solver/NEWTON.md).
constexpr double kStretchTrust = 0.5;

/// max over the cells of ||grad_x du||_2, the gradient of the increment du with respect to
/// the present positions X + u (P1: one per cell).
template <int d>
double largest_stretch_change(const Mesh& mesh, const Eigen::VectorXd& u,
                              const Eigen::VectorXd& du) {
  using Matrix = Eigen::Matrix<double, d, d>;
  double largest = 0;
  for (const Simplex& cell : mesh.cells) {
    Matrix x, e;
    for (int j = 0; j < d; ++j) {
      const int a = d * cell[j + 1], b = d * cell[0];
      x.col(j) = mesh.nodes[cell[j + 1]] - mesh.nodes[cell[0]] + u.segment<d>(a) - u.segment<d>(b);
      e.col(j) = du.segment<d>(a) - du.segment<d>(b);
    }
    const Matrix g = e * x.inverse();
    if constexpr (d == 2) {
      // sigma_max^2 of a 2 x 2 matrix: (|g|_F^2 + sqrt(|g|_F^4 - 4 det^2)) / 2.
      const double f2 = g.squaredNorm(), det = g.determinant();
      largest = std::max(largest,
                         std::sqrt(0.5 * (f2 + std::sqrt(std::max(0.0, f2 * f2 - 4 * det * det)))));
    } else {
      // sigma_max^2 the largest eigenvalue of g^T g.
      const Eigen::SelfAdjointEigenSolver<Matrix> eigen(g.transpose() * g, Eigen::EigenvaluesOnly);
      largest = std::max(largest, std::sqrt(std::max(0.0, eigen.eigenvalues()[d - 1])));
    }
  }
  return largest;
}

/// Relative step of the central differences of the obstacle normal (error O(h^2) ~ 1e-12,
/// round-off ~ 1e-16 / h ~ 1e-10 of the curvature).
constexpr double kNormalDifferenceStep = 1e-6;

/// Why the step matrix of an iterate failed to factorize, in the deck's words rather than the
/// linear solver's ("not positive definite"): a part of the body that this iterate's held dofs
/// (the Dirichlet dofs, the contact nodes on the wall, in their frames) leave free, or else the
/// tangent of the deformed body, which law=svk loses in strong compression.
std::string singular_step_cause(const FiniteStrainProblem& problem,
                                const std::vector<std::pair<int, double>>& imposed,
                                const std::vector<Point>& normals, const std::string& library) {
  const Mesh& mesh = *problem.mesh;
  const std::string held =
      " (" + std::to_string(imposed.size()) + " dofs held at this iterate; " + library + ")";
  // A static 2D solve: a part of the body its holds leave free (3D bodies march only, issue 28;
  // a march's mass holds every part).
  if (problem.mass == nullptr && mesh.dim == 2) {
    std::vector<int> contact_of_node(mesh.num_nodes(), -1);
    for (int p = 0; problem.contact && p < problem.contact->size(); ++p)
      contact_of_node[problem.contact->node[p]] = p;
    std::vector<Hold> holds;
    for (const auto& [dof, value] : imposed) {
      Hold hold;
      hold.node = dof / 2;
      const Eigen::Vector2d axis =
          dof % 2 == 0 ? Eigen::Vector2d::UnitX() : Eigen::Vector2d::UnitY();
      const int p = contact_of_node[hold.node];
      hold.along = p < 0 ? axis : Eigen::Vector2d(nodal_frame(Eigen::Vector2d(normals[p])) * axis);
      holds.push_back(hold);
    }
    if (const std::vector<FreePart> free = free_parts(mesh, holds); !free.empty())
      return describe(free.front()) + held;
  }
  bool svk = false;
  for (const SubdomainMaterial& m : problem.materials->entries)
    svk = svk || (m.hyperelastic && m.hyperelastic->name() == "svk");
  return std::string("the tangent stiffness of the deformed body is not positive definite: the "
                     "body lost its stability at this deformation") +
         (svk ? " (MATERIAL law=svk softens in strong compression, in one dimension beyond a "
                "stretch of 1/sqrt(3): its stored energy is not polyconvex; law=ciarlet-geymonat "
                "does not)"
              : " (a buckling)") +
         held;
}

} // namespace

FiniteStrainBulk::FiniteStrainBulk(const FiniteStrainProblem& problem, const std::string& backend,
                                   double eps)
    : problem_(problem), d_(problem.mesh->dim), eps_(eps), pattern_(*problem.mesh) {
  SIG_VERIFY(problem.mesh && problem.materials, "finite-strain contact needs a mesh and materials");
  const int d = d_;
  const int ndof = d * problem.mesh->num_nodes();
  contacts_ = problem.contact ? problem.contact->size() : 0;
  SIG_VERIFY(contacts_ == 0 || problem.obstacle, "contact elements without an obstacle");
  SIG_VERIFY(problem.load.size() == 0 || problem.load.size() == ndof,
             "load has " << problem.load.size() << " values for " << ndof << " dofs");
  SIG_VERIFY(static_cast<Eigen::Index>(problem.dirichlet_dofs.size()) ==
                 problem.dirichlet_values.size(),
             problem.dirichlet_dofs.size()
                 << " Dirichlet dofs but " << problem.dirichlet_values.size() << " values");
  dirichlet_.assign(ndof, 0);
  for (std::size_t k = 0; k < problem.dirichlet_dofs.size(); ++k) {
    const int dof = problem.dirichlet_dofs[k];
    SIG_VERIFY(dof >= 0 && dof < ndof && (k == 0 || dof > problem.dirichlet_dofs[k - 1]),
               "Dirichlet dofs must be sorted, unique and < " << ndof);
    dirichlet_[dof] = 1;
  }
  std::vector<int> contact_nodes(contacts_);
  for (int p = 0; p < contacts_; ++p) {
    contact_nodes[p] = node(p);
    for (int a = 0; a < d; ++a)
      SIG_VERIFY(!dirichlet_[d * node(p) + a],
                 "contact node " << node(p) + 1 << " has a Dirichlet condition");
  }
  friction_ = contacts_ > 0 && any_friction(problem.contact->law);
  if (dynamic()) {
    SIG_VERIFY(problem.time_step > 0, "time step k = " << problem.time_step << " must be > 0");
    mass_ = pattern_.zero_matrix();
    SIG_VERIFY(problem.mass->rows() == ndof && problem.mass->cols() == ndof,
               "mass is " << problem.mass->rows() << " x " << problem.mass->cols() << " for "
                          << ndof << " dofs");
    const int* outer = mass_.outerIndexPtr();
    const int* inner = mass_.innerIndexPtr();
    for (int j = 0; j < ndof; ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(*problem.mass, j); it; ++it) {
        const int* slot = std::lower_bound(inner + outer[j], inner + outer[j + 1], it.row());
        SIG_VERIFY(slot != inner + outer[j + 1] && *slot == it.row(),
                   "mass entry (" << it.row() + 1 << ", " << j + 1
                                  << ") is off the mesh's P1 pattern");
        mass_.valuePtr()[slot - inner] += it.value();
      }
    massless_.assign(static_cast<std::size_t>(ndof), 1);
    for (int j = 0; j < ndof; ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(mass_, j); it; ++it)
        if (it.value() != 0.0) massless_[static_cast<std::size_t>(j)] = 0;
  }
  // Gonzalez's tangent and the Coulomb coupling on the wall are not symmetric: LU.
  const bool symmetric =
      !friction_ && !(dynamic() && problem.stress == AlgorithmicStress::gonzalez);
  solver_ = make_linear_solver(backend, symmetric ? backend_traits(backend).symmetric_kind()
                                                  : MatrixKind::general);
  J_ = std::make_unique<NewtonMatrix>(pattern_.zero_matrix(), dirichlet_, contact_nodes, d);
  now_.u = Eigen::VectorXd::Zero(ndof);
  slip_origin_ = now_.u;
  if (dynamic()) start_time_step(now_.u, now_.u); // at rest: the predictor is u = 0
  SIG_VERIFY(evaluate(now_, true), "the reference configuration has an inverted triangle");
  take_rest_diagonal();
  base_ = now_.u;
  step_ = Eigen::VectorXd::Zero(ndof);
}

void FiniteStrainBulk::take_rest_diagonal() {
  rest_diagonal_ = now_.bulk.tangent.diagonal();
  // A dof without stiffness of its own (none in a P1 mesh): the largest, a force scale.
  const double largest = rest_diagonal_.cwiseAbs().maxCoeff();
  for (Eigen::Index i = 0; i < rest_diagonal_.size(); ++i)
    if (!(rest_diagonal_[i] > 0)) rest_diagonal_[i] = largest > 0 ? largest : 1.0;
}

void FiniteStrainBulk::start_time_step(const Eigen::VectorXd& u_prev,
                                       const Eigen::VectorXd& v_prev) {
  SIG_VERIFY(dynamic(), "a time step of a static problem (no mass)");
  SIG_VERIFY(u_prev.size() == now_.u.size() && v_prev.size() == now_.u.size(),
             "time step: " << u_prev.size() << " displacements and " << v_prev.size()
                           << " velocities for " << now_.u.size() << " dofs");
  // The strain at u_prev: the last evaluated iterate's when the step starts where the previous
  // one ended (the march), else a pass over the mesh.
  if (now_.strain.F.size() == problem_.mesh->cells.size() && u_prev == now_.u)
    previous_ = std::move(now_.strain);
  else
    previous_ = previous_strain(*problem_.mesh, *problem_.materials, u_prev);
  u_prev_ = u_prev;
  v_prev_ = v_prev;
  slip_origin_ = u_prev;
  // The predictor u_prev + k v_prev, shortened towards u_prev (always admissible) when a fast
  // rotation's straight-line extrapolation would invert a triangle.
  bool admissible = false;
  // The force alone: a free flight's step is its predictor and needs no tangent (solve()
  // assembles it when a Newton step is taken).
  for (double theta = 1; !admissible && theta >= 1.0 / 64; theta /= 2) {
    now_.u = u_prev + theta * problem_.time_step * v_prev;
    admissible = evaluate(now_, false);
  }
  if (!admissible) {
    now_.u = u_prev;
    SIG_VERIFY(evaluate(now_, false), "the state at the start of the time step has an inverted "
                                      "triangle");
  }
  base_ = now_.u;
}

Eigen::VectorXd FiniteStrainBulk::velocity() const {
  const double k = problem_.time_step;
  Eigen::VectorXd v = (2.0 / k) * (now_.u - u_prev_) - v_prev_;
  for (Eigen::Index i = 0; i < v.size(); ++i)
    if (massless_[static_cast<std::size_t>(i)]) v[i] = (now_.u[i] - u_prev_[i]) / k;
  return v;
}

double FiniteStrainBulk::start_from(const Eigen::VectorXd& u) {
  SIG_VERIFY(!dynamic(), "a time step starts from its predictor (start_time_step)");
  SIG_VERIFY(u.size() == now_.u.size(), "start of " << u.size() << " dofs for " << now_.u.size());
  for (double theta = 1; theta >= 1.0 / 64; theta /= 2) {
    now_.u = theta * u;
    if (evaluate(now_, true)) {
      base_ = now_.u;
      return theta;
    }
  }
  now_.u.setZero();
  SIG_VERIFY(evaluate(now_, true), "the reference configuration has an inverted triangle");
  base_ = now_.u;
  return 0;
}

void FiniteStrainBulk::set_load_factor(double s) {
  load_factor_ = s;
}

Eigen::VectorXd FiniteStrainBulk::load() const {
  return problem_.load.size() ? Eigen::VectorXd(load_factor_ * problem_.load)
                              : Eigen::VectorXd(Eigen::VectorXd::Zero(now_.u.size()));
}

bool FiniteStrainBulk::evaluate(State& s, bool with_tangent) {
  ++evaluations_;
  // The assembly refuses an inverted triangle or a law without admissible state there.
  try {
    if (dynamic())
      assemble_hyperelastic_step(*problem_.mesh, *problem_.materials, pattern_, previous_,
                                 problem_.stress, s.u, s.bulk, with_tangent, &s.strain);
    else if (with_tangent)
      assemble_hyperelastic(*problem_.mesh, *problem_.materials, pattern_, s.u, s.bulk);
    else
      assemble_hyperelastic_force(*problem_.mesh, *problem_.materials, s.u, s.bulk);
  } catch (const Error&) {
    return false;
  }
  if (dynamic()) { // the inertia of the step: (2 / k^2) M (u - u_prev - k v_prev)
    const double k = problem_.time_step, c = 2.0 / (k * k);
    s.bulk.internal_force.noalias() += c * (mass_ * (s.u - u_prev_ - k * v_prev_));
    s.inertia = c * (mass_ * (s.u - u_prev_)).norm();
    if (with_tangent) s.bulk.tangent.coeffs() += c * mass_.coeffs();
  }
  s.has_tangent = with_tangent;
  s.penetration.resize(contacts_);
  s.slip = Eigen::VectorXd::Zero(tangents() * contacts_);
  s.normal.resize(contacts_);
  for (int p = 0; p < contacts_; ++p) {
    const int a = d_ * node(p);
    const Point x = problem_.mesh->nodes[node(p)] + s.u.segment(a, d_);
    s.penetration[p] = -problem_.obstacle->signed_distance(x);
    s.normal[p] = problem_.obstacle->normal(x);
    // With friction the slip since the step's start along each tangent of the present frame
    // (contact_frame: t in 2D, t1 and t2 in 3D), node p's at (d - 1) p.
    if (!friction_) continue;
    const ContactFrame frame = contact_frame(s.normal[p]);
    const Eigen::VectorXd moved = s.u.segment(a, d_) - slip_origin_.segment(a, d_);
    for (int k = 0; k < d_ - 1; ++k)
      s.slip[(d_ - 1) * p + k] = frame.col(k).dot(moved);
  }
  return true;
}

double FiniteStrainBulk::equilibrium_residual(const Eigen::VectorXd& N,
                                              const Eigen::VectorXd& T) const {
  Eigen::VectorXd r = now_.bulk.internal_force - load();
  for (int p = 0; p < contacts_; ++p) {
    r.segment(d_ * node(p), d_) -= N[p] * now_.normal[p];
    if (!friction_) continue;
    const ContactFrame frame = contact_frame(now_.normal[p]);
    for (int k = 0; k < d_ - 1; ++k)
      r.segment(d_ * node(p), d_) += T[(d_ - 1) * p + k] * frame.col(k);
  }
  // A Dirichlet dof's row is its mismatch with the load step's target, times its stiffness: the
  // force that would move it there (a step shorter than 1 leaves part of it).
  for (std::size_t k = 0; k < problem_.dirichlet_dofs.size(); ++k) {
    const int dof = problem_.dirichlet_dofs[k];
    const double target = load_factor_ * problem_.dirichlet_values[static_cast<Eigen::Index>(k)];
    r[dof] = rest_diagonal_[dof] * (now_.u[dof] - target);
  }
  return r.norm();
}

Eigen::VectorXd FiniteStrainBulk::contact_stiffness() const {
  Eigen::VectorXd k(contacts_);
  for (int p = 0; p < contacts_; ++p) {
    const Point n = problem_.obstacle->normal(problem_.mesh->nodes[node(p)]);
    const int a = d_ * node(p);
    k[p] = n[0] * n[0] * rest_diagonal_[a];
    for (int i = 1; i < d_; ++i)
      k[p] += n[i] * n[i] * rest_diagonal_[a + i];
  }
  return k;
}

double FiniteStrainBulk::force_scale() const {
  return std::max({load().norm(), now_.bulk.internal_force.norm(), now_.inertia, 1e-300});
}

std::vector<ContactFrame> FiniteStrainBulk::frames(const State& s) const {
  std::vector<ContactFrame> out;
  out.reserve(s.normal.size());
  for (const Point& n : s.normal)
    out.push_back(contact_frame(n));
  return out;
}

Eigen::MatrixXd FiniteStrainBulk::curvature_block(int p, double force) const {
  const Point x = problem_.mesh->nodes[node(p)] + now_.u.segment(d_ * node(p), d_);
  const double h = kNormalDifferenceStep * (1.0 + x.norm());
  Eigen::MatrixXd block(d_, d_);
  for (int j = 0; j < d_; ++j) {
    const Point e = h * Eigen::VectorXd::Unit(d_, j);
    block.col(j) =
        -force * (problem_.obstacle->normal(x + e) - problem_.obstacle->normal(x - e)) / (2 * h);
  }
  return block;
}

StepSolution FiniteStrainBulk::solve(const std::vector<NodeConditions>& conditions,
                                     const Eigen::VectorXd& normal_force) {
  if (!now_.has_tangent) evaluate(now_, true); // an accepted force-only trial
  // The tangent moves into the Newton matrix instead of a copy (2.8 MB per iteration of the
  // ring at N = 512): the driver moves the iterate before it solves again, and an evaluation
  // with the tangent resets the values it gets back.
  J_->take_tangent(now_.bulk.tangent);
  now_.has_tangent = false;
  for (int p = 0; p < contacts_; ++p)
    if (normal_force[p] != 0.0) J_->add_node_block(p, curvature_block(p, normal_force[p]));
  const std::vector<ContactFrame> frame = frames(now_);
  J_->rotate(frame);
  // r0 = Q^T (f_int - s f_ext), plus the contact force laws of the free normal components.
  Eigen::VectorXd r0 = now_.bulk.internal_force - load();
  for (int p = 0; p < contacts_; ++p) {
    const Point r = r0.segment(d_ * node(p), d_);
    r0.segment(d_ * node(p), d_) = frame[p].transpose() * r;
  }

  // Imposed increments: the Dirichlet dofs towards their targets (never contact nodes) and the
  // imposed contact components; the others carry their force laws (contact_bulk.hpp).
  std::vector<std::pair<int, double>> imposed;
  for (std::size_t k = 0; k < problem_.dirichlet_dofs.size(); ++k) {
    const int dof = problem_.dirichlet_dofs[k];
    imposed.emplace_back(
        dof, load_factor_ * problem_.dirichlet_values[static_cast<Eigen::Index>(k)] - now_.u[dof]);
  }
  for (int p = 0; p < contacts_; ++p) {
    const int normal_dof = d_ * node(p) + d_ - 1;
    const DofCondition& c = conditions[p].normal;
    if (c.imposed) {
      imposed.emplace_back(normal_dof, c.value);
    } else {
      J_->diagonal(normal_dof) += c.stiffness;
      r0[normal_dof] += c.force;
    }
  }
  // Tangential rows, one per tangent k (the rotated dofs d node + k): T_k = force + stiffness
  // dw_tk + coupling N + cross dw_n (+ tangential_12 dw_t of the other tangent in 3D). With an
  // imposed normal, N = -(r0_n + A_n dw) is its reaction, so the row r0_t + A_t dw + T = 0
  // becomes (r0_t - coupling r0_n) + (A_t - coupling A_n) dw + force + ... = 0.
  for (int p = 0; p < contacts_ && friction_; ++p) {
    const int normal_dof = d_ * node(p) + d_ - 1;
    for (int k = 0; k < d_ - 1; ++k) {
      const int tangential_dof = d_ * node(p) + k;
      const DofCondition& c = conditions[p].tangent(k);
      if (c.imposed) {
        imposed.emplace_back(tangential_dof, c.value);
        continue;
      }
      if (c.coupling != 0.0) {
        J_->add_row(tangential_dof, normal_dof, -c.coupling);
        r0[tangential_dof] -= c.coupling * r0[normal_dof];
      }
      J_->diagonal(tangential_dof) += c.stiffness;
      J_->entry(tangential_dof, normal_dof) += c.cross;
      if (d_ == 3 && conditions[p].tangential_12 != 0.0)
        J_->entry(tangential_dof, d_ * node(p) + 1 - k) += conditions[p].tangential_12;
      r0[tangential_dof] += c.force;
    }
  }
  std::sort(imposed.begin(), imposed.end());
  if (damping_ > 0) // on every dof: the imposed ones' rows are eliminated whatever their diagonal
    for (Eigen::Index dof = 0; dof < rest_diagonal_.size(); ++dof)
      J_->diagonal(static_cast<int>(dof)) += damping_ * rest_diagonal_[dof];
  Eigen::VectorXd dw;
  try {
    dw = J_->solve(r0, imposed, *solver_);
  } catch (const Error& e) {
    throw Error(singular_step_cause(problem_, imposed, now_.normal, e.what()));
  }

  // Forces: the reaction of an imposed normal (r0 + A dw + N = 0 on its row), else the force law.
  StepSolution s;
  s.normal_increment.resize(contacts_);
  s.normal_force.resize(contacts_);
  s.tangential_force = Eigen::VectorXd::Zero(tangents() * contacts_);
  for (int p = 0; p < contacts_; ++p) {
    const int normal_dof = d_ * node(p) + d_ - 1;
    const DofCondition& c = conditions[p].normal;
    s.normal_increment[p] = dw[normal_dof];
    s.normal_force[p] = c.imposed ? -(r0[normal_dof] + J_->normal_row_times(p, dw))
                                  : c.force + c.stiffness * dw[normal_dof];
    if (!friction_) continue;
    for (int k = 0; k < d_ - 1; ++k) {
      const DofCondition& t = conditions[p].tangent(k);
      const int tangential_dof = d_ * node(p) + k;
      double& T = s.tangential_force[(d_ - 1) * p + k];
      T = t.imposed ? -(r0[tangential_dof] + J_->row_times(tangential_dof, dw))
                    : t.force + t.stiffness * dw[tangential_dof] + t.coupling * s.normal_force[p] +
                          t.cross * dw[normal_dof];
      if (d_ == 3 && !t.imposed) T += conditions[p].tangential_12 * dw[d_ * node(p) + 1 - k];
    }
  }
  // du = Q dw.
  step_ = dw;
  for (int p = 0; p < contacts_; ++p) {
    const int a = d_ * node(p);
    step_.segment(a, d_) = frame[p] * dw.segment(a, d_);
  }
  base_ = now_.u;
  return s;
}

double FiniteStrainBulk::trusted_length() const {
  // A static step is trusted while no element's stretches change by more than kStretchTrust (a
  // time step starts from its predictor, within a step of its solution: left as it was).
  // Computed when asked (the driver asks on a solve's first step only), not at every solve.
  if (dynamic()) return std::numeric_limits<double>::infinity();
  const Mesh& mesh = *problem_.mesh;
  const double change = with_dimension(mesh.dim, [&]<int d>(std::integral_constant<int, d>) {
    return largest_stretch_change<d>(mesh, base_, step_);
  });
  return change > 0 ? kStretchTrust / change : std::numeric_limits<double>::infinity();
}

void FiniteStrainBulk::swap_states() {
  Eigen::SparseMatrix<double> now_tangent, kept_tangent;
  now_tangent.swap(now_.bulk.tangent); // O(1): the States keep empty tangents while swapped
  kept_tangent.swap(kept_.bulk.tangent);
  std::swap(now_, kept_);
  now_.bulk.tangent.swap(kept_tangent);
  kept_.bulk.tangent.swap(now_tangent);
}

void FiniteStrainBulk::rewind() {
  SIG_VERIFY(checkpoint_u_.size() == now_.u.size(), "finite strain bulk: rewind without a "
                                                    "checkpoint");
  now_.u = checkpoint_u_;
  // The checkpoint was an accepted iterate, inside the law's domain.
  SIG_VERIFY(evaluate(now_, true), "finite strain bulk: the checkpoint has an inverted element");
  base_ = now_.u;
}

bool FiniteStrainBulk::move(double alpha) {
  now_.u = base_ + alpha * step_;
  return evaluate(now_, alpha == 1.0);
}

bool FiniteStrainBulk::settled() const {
  double mismatch = 0, target = 0;
  for (std::size_t k = 0; k < problem_.dirichlet_dofs.size(); ++k) {
    const double value = load_factor_ * problem_.dirichlet_values[static_cast<Eigen::Index>(k)];
    mismatch = std::max(mismatch, std::abs(value - now_.u[problem_.dirichlet_dofs[k]]));
    target = std::max(target, std::abs(value));
  }
  return mismatch <= eps_ * std::max(target, now_.u.lpNorm<Eigen::Infinity>());
}

} // namespace sig
