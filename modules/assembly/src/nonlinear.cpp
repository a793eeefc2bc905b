#include "assembly/nonlinear.hpp"

#include "assembly/p1.hpp"
#include "core/error.hpp"
#include "material/algorithmic_stress.hpp"
#include "material/hyperelastic.hpp"
#include "material/mili.hpp"
#include "mesh/mesh.hpp"

#include <Eigen/LU>

#include <functional>
#include <limits>
#include <string>

namespace sig {

namespace {

const HyperelasticLaw& law_of(const SubdomainMaterial& material) {
  SIG_VERIFY(material.hyperelastic, "sub-domain " << material.subdomain
                                                  << " has law=hooke; the large-deformation "
                                                     "assembly needs law=svk or ciarlet-geymonat");
  return *material.hyperelastic;
}

// The kinematics of one triangle: F = I + u_e g^T, with g(J, a) = dlambda_a/dX_J the P1
// gradients.
struct Kinematics {
  double volume; // thickness * reference area
  Matrix23 g;
  Eigen::Matrix2d F;
};

Kinematics kinematics(const Mesh& mesh, int t, double thickness, const Eigen::VectorXd& u) {
  const Matrix23 x = triangle_vertices(mesh, t);
  Kinematics k;
  k.g = p1_gradients(x);
  // Displacements relative to the first vertex's: the gradients sum to zero, so this changes
  // nothing but rounding, and a body far from its reference position (a ring thrown 100 m) keeps
  // F exact for a translation instead of carrying |u| eps / h of noise into the stress.
  Matrix23 ue;
  const Eigen::Vector2d u0 = u.segment<2>(2 * mesh.cells[t][0]);
  for (int a = 0; a < 3; ++a)
    ue.col(a) = u.segment<2>(2 * mesh.cells[t][a]) - u0;
  k.volume = thickness * p1_area(x);
  k.F = Eigen::Matrix2d::Identity() + ue * k.g.transpose();
  return k;
}

} // namespace

double hyperelastic_energy(const Mesh& mesh, const MaterialTable& table, const Eigen::VectorXd& u) {
  SIG_VERIFY(u.size() == 2 * mesh.num_nodes(),
             "displacement has " << u.size() << " values for " << mesh.num_nodes() << " nodes");
  double energy = 0.0;
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const SubdomainMaterial& material = table.of(mesh.subdomain[t]);
    const HyperelasticLaw& law = law_of(material);
    const Kinematics k = kinematics(mesh, t, material.thickness, u);
    if (!(k.F.determinant() > 0.0)) return std::numeric_limits<double>::infinity();
    // A law with no admissible state at F (plane-stress Saint Venant-Kirchhoff stretched past
    // its limit) is, for a line search, the same as an inverted triangle.
    try {
      energy += k.volume * law.energy(k.F);
    } catch (const Error&) {
      return std::numeric_limits<double>::infinity();
    }
  }
  return energy;
}

namespace {

/// What a triangle's law gives at its F: energy, first Piola stress, and dP/dF when asked.
using TriangleResponse = std::function<StepResponse(int t, const HyperelasticLaw& law,
                                                    const Eigen::Matrix2d& F, bool with_tangent)>;

/// The loop of every assembly here: energy and force always, the tangent into K when K is given.
void assemble_over_triangles(const Mesh& mesh, const MaterialTable& table,
                             const SparsityPattern* pattern, const Eigen::VectorXd& u,
                             HyperelasticState& state, Eigen::SparseMatrix<double>* K,
                             const TriangleResponse& response) {
  state.internal_force.setZero(2 * mesh.num_nodes());
  state.energy = 0.0;
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const SubdomainMaterial& material = table.of(mesh.subdomain[t]);
    const HyperelasticLaw& law = law_of(material);
    const Kinematics kin = kinematics(mesh, t, material.thickness, u);
    SIG_VERIFY(kin.F.determinant() > 0.0,
               "triangle " << t + 1 << " is inverted: det F = " << kin.F.determinant());
    StepResponse r;
    try {
      r = response(t, law, kin.F, K != nullptr);
    } catch (const Error& e) {
      throw Error("triangle " + std::to_string(t + 1) + ": " + e.what());
    }
    // Virtual work, with dF = du_e g^T: f_e(2 a + i) = |T| t (P g)(i, a) and
    // K_e(2 a + i, 2 b + k) = |T| t (g^T A_ik g)(a, b), A_ik the 2x2 block dP_i./dF_k. of A.
    const Matrix23 f = kin.volume * (r.stress * kin.g);
    state.energy += kin.volume * r.energy;
    for (int a = 0; a < 3; ++a)
      state.internal_force.segment<2>(2 * mesh.cells[t][a]) += f.col(a);
    if (K) {
      Matrix6d Ke;
      for (int i = 0; i < 2; ++i)
        for (int k = 0; k < 2; ++k) {
          const Eigen::Matrix3d block =
              kin.volume * (kin.g.transpose() * r.tangent.block<2, 2>(2 * i, 2 * k) * kin.g);
          for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
              Ke(2 * a + i, 2 * b + k) = block(a, b);
        }
      pattern->add(*K, t, Ke);
    }
  }
}

/// The hyperelastic law's own response: P = dW/dF and its tangent.
StepResponse law_response(int, const HyperelasticLaw& law, const Eigen::Matrix2d& F, bool) {
  const HyperelasticResponse r = law.response(F);
  return {r.stress, r.tangent, r.energy};
}

/// The tangent's layout: reused in place when it already has the pattern's.
void reset_tangent(const SparsityPattern& pattern, Eigen::SparseMatrix<double>& K) {
  if (K.isCompressed() && K.rows() == pattern.num_dofs() && K.cols() == pattern.num_dofs() &&
      K.nonZeros() == pattern.nnz())
    K.coeffs().setZero();
  else
    K = pattern.zero_matrix();
}

} // namespace

void assemble_hyperelastic(const Mesh& mesh, const MaterialTable& table,
                           const SparsityPattern& pattern, const Eigen::VectorXd& u,
                           HyperelasticState& state) {
  SIG_VERIFY(u.size() == pattern.num_dofs() && pattern.num_dofs() == 2 * mesh.num_nodes(),
             "displacement has " << u.size() << " values, pattern " << pattern.num_dofs()
                                 << " dofs, mesh " << mesh.num_nodes() << " nodes");
  reset_tangent(pattern, state.tangent);
  assemble_over_triangles(mesh, table, &pattern, u, state, &state.tangent, law_response);
}

void assemble_hyperelastic_force(const Mesh& mesh, const MaterialTable& table,
                                 const Eigen::VectorXd& u, HyperelasticState& state) {
  SIG_VERIFY(u.size() == 2 * mesh.num_nodes(),
             "displacement has " << u.size() << " values for " << mesh.num_nodes() << " nodes");
  assemble_over_triangles(mesh, table, nullptr, u, state, nullptr, law_response);
}

PreviousStrain previous_strain(const Mesh& mesh, const MaterialTable& table,
                               const Eigen::VectorXd& u_prev) {
  SIG_VERIFY(u_prev.size() == 2 * mesh.num_nodes(), "displacement has "
                                                        << u_prev.size() << " values for "
                                                        << mesh.num_nodes() << " nodes");
  PreviousStrain previous;
  previous.F.resize(mesh.num_cells());
  previous.energy.resize(mesh.num_cells());
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const SubdomainMaterial& material = table.of(mesh.subdomain[t]);
    const Kinematics k = kinematics(mesh, t, material.thickness, u_prev);
    SIG_VERIFY(k.F.determinant() > 0.0,
               "triangle " << t + 1 << " is inverted: det F = " << k.F.determinant());
    previous.F[t] = k.F;
    previous.energy[t] = step_energy(law_of(material), k.F);
  }
  return previous;
}

void assemble_hyperelastic_step(const Mesh& mesh, const MaterialTable& table,
                                const SparsityPattern& pattern, const PreviousStrain& previous,
                                AlgorithmicStress stress, const Eigen::VectorXd& u,
                                HyperelasticState& state, bool with_tangent,
                                PreviousStrain* strain) {
  SIG_VERIFY(u.size() == pattern.num_dofs() && pattern.num_dofs() == 2 * mesh.num_nodes() &&
                 static_cast<int>(previous.F.size()) == mesh.num_cells(),
             "time step: displacement has " << u.size() << " values, pattern " << pattern.num_dofs()
                                            << " dofs, the step start " << previous.F.size()
                                            << " triangles");
  if (strain) {
    strain->F.resize(previous.F.size());
    strain->energy.resize(previous.energy.size());
  }
  const TriangleResponse response = [&](int t, const HyperelasticLaw& law, const Eigen::Matrix2d& F,
                                        bool tangent) {
    StepResponse r = step_response(law, stress, previous.F[t], previous.energy[t], F, tangent);
    if (strain) {
      strain->F[t] = F;
      strain->energy[t] = r.energy;
    }
    return r;
  };
  if (with_tangent) reset_tangent(pattern, state.tangent);
  assemble_over_triangles(mesh, table, &pattern, u, state, with_tangent ? &state.tangent : nullptr,
                          response);
}

} // namespace sig
