#include "assembly/nonlinear.hpp"

#include "assembly/p1.hpp"
#include "core/error.hpp"
#include "material/hyperelastic.hpp"
#include "material/mili.hpp"
#include "mesh/mesh.hpp"

#include <Eigen/LU>

#include <limits>
#include <string>

namespace sig {

namespace {

using Matrix46 = Eigen::Matrix<double, 4, 6>;

const HyperelasticLaw& law_of(const SubdomainMaterial& material) {
  SIG_VERIFY(material.hyperelastic, "sub-domain " << material.subdomain
                                                  << " has law=hooke; the large-deformation "
                                                     "assembly needs law=svk or ciarlet-geymonat");
  return *material.hyperelastic;
}

// The kinematics of one triangle: F - I = B u_e in the row-major Voigt order of F (F11, F12,
// F21, F22), B(2 i + J, 2 a + k) = delta_ik dlambda_a/dX_J.
struct Kinematics {
  double volume; // thickness * reference area
  Matrix46 B;
  Eigen::Matrix2d F;
};

Kinematics kinematics(const Mesh& mesh, int t, double thickness, const Eigen::VectorXd& u) {
  const Matrix23 x = triangle_vertices(mesh, t);
  const Matrix23 g = p1_gradients(x);
  Matrix23 ue;
  for (int a = 0; a < 3; ++a)
    ue.col(a) = u.segment<2>(2 * mesh.triangles[t][a]);
  Kinematics k;
  k.volume = thickness * p1_area(x);
  k.F = Eigen::Matrix2d::Identity() + ue * g.transpose();
  k.B.setZero();
  for (int a = 0; a < 3; ++a)
    for (int i = 0; i < 2; ++i)
      for (int J = 0; J < 2; ++J)
        k.B(2 * i + J, 2 * a + i) = g(J, a);
  return k;
}

} // namespace

double hyperelastic_energy(const Mesh& mesh, const MaterialTable& table, const Eigen::VectorXd& u) {
  SIG_VERIFY(u.size() == 2 * mesh.num_nodes(),
             "displacement has " << u.size() << " values for " << mesh.num_nodes() << " nodes");
  double energy = 0.0;
  for (int t = 0; t < mesh.num_triangles(); ++t) {
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

/// The loop of assemble_hyperelastic and assemble_hyperelastic_force: energy and force always,
/// the tangent into K when K is given.
void assemble_over_triangles(const Mesh& mesh, const MaterialTable& table,
                             const SparsityPattern* pattern, const Eigen::VectorXd& u,
                             HyperelasticState& state, Eigen::SparseMatrix<double>* K) {
  state.internal_force.setZero(2 * mesh.num_nodes());
  state.energy = 0.0;
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const SubdomainMaterial& material = table.of(mesh.subdomain[t]);
    const HyperelasticLaw& law = law_of(material);
    const Kinematics k = kinematics(mesh, t, material.thickness, u);
    SIG_VERIFY(k.F.determinant() > 0.0,
               "triangle " << t + 1 << " is inverted: det F = " << k.F.determinant());
    HyperelasticResponse r;
    try {
      r = law.response(k.F);
    } catch (const Error& e) {
      throw Error("triangle " + std::to_string(t + 1) + ": " + e.what());
    }
    const Eigen::Vector4d P(r.stress(0, 0), r.stress(0, 1), r.stress(1, 0), r.stress(1, 1));
    // Virtual work: f_e = |T| t B^T P and K_e = |T| t B^T A B, with A = dP/dF.
    const Vector6d f = k.volume * (k.B.transpose() * P);
    state.energy += k.volume * r.energy;
    for (int a = 0; a < 3; ++a)
      state.internal_force.segment<2>(2 * mesh.triangles[t][a]) += f.segment<2>(2 * a);
    if (K) {
      const Matrix6d Ke = k.volume * (k.B.transpose() * r.tangent * k.B);
      pattern->add(*K, t, Ke);
    }
  }
}

} // namespace

void assemble_hyperelastic(const Mesh& mesh, const MaterialTable& table,
                           const SparsityPattern& pattern, const Eigen::VectorXd& u,
                           HyperelasticState& state) {
  SIG_VERIFY(u.size() == pattern.num_dofs() && pattern.num_dofs() == 2 * mesh.num_nodes(),
             "displacement has " << u.size() << " values, pattern " << pattern.num_dofs()
                                 << " dofs, mesh " << mesh.num_nodes() << " nodes");
  Eigen::SparseMatrix<double>& K = state.tangent;
  if (K.isCompressed() && K.rows() == pattern.num_dofs() && K.cols() == pattern.num_dofs() &&
      K.nonZeros() == pattern.nnz())
    K.coeffs().setZero();
  else
    K = pattern.zero_matrix();
  assemble_over_triangles(mesh, table, &pattern, u, state, &K);
}

void assemble_hyperelastic_force(const Mesh& mesh, const MaterialTable& table,
                                 const Eigen::VectorXd& u, HyperelasticState& state) {
  SIG_VERIFY(u.size() == 2 * mesh.num_nodes(),
             "displacement has " << u.size() << " values for " << mesh.num_nodes() << " nodes");
  assemble_over_triangles(mesh, table, nullptr, u, state, nullptr);
}

} // namespace sig
