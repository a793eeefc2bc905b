#include "assembly/nonlinear.hpp"

#include "assembly/p1_simplex.hpp"
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

// The kinematics of one cell (a triangle in 2D, a tetrahedron in 3D): F = I + u_e g^T, with
// g(J, a) = dlambda_a/dX_J the P1 gradients.
template <int d> struct Kinematics {
  double volume; // thickness * reference area in 2D, the reference volume in 3D
  SimplexVertices<d> g;
  Tensor<d> F;
};

template <int d>
Kinematics<d> kinematics(const Mesh& mesh, int t, const SubdomainMaterial& material,
                         const Eigen::VectorXd& u) {
  const SimplexVertices<d> x = simplex_vertices<d>(mesh, t);
  Kinematics<d> k;
  k.g = p1_simplex_gradients<d>(x);
  // Displacements relative to the first vertex's: the gradients sum to zero, so this changes
  // nothing but rounding, and a body far from its reference position (a ring thrown 100 m) keeps
  // F exact for a translation instead of carrying |u| eps / h of noise into the stress.
  SimplexVertices<d> ue;
  const Eigen::Matrix<double, d, 1> u0 = u.segment<d>(d * mesh.cells[t][0]);
  for (int a = 0; a <= d; ++a)
    ue.col(a) = u.segment<d>(d * mesh.cells[t][a]) - u0;
  // A 3D body has no thickness (mili.cpp refuses the field there).
  k.volume = (d == 2 ? material.thickness : 1.0) * p1_measure<d>(x);
  k.F = Tensor<d>::Identity() + ue * k.g.transpose();
  return k;
}

void verify_size(const Mesh& mesh, const Eigen::VectorXd& u) {
  SIG_VERIFY(u.size() == mesh.dim * mesh.num_nodes(),
             "displacement has " << u.size() << " values for " << mesh.num_nodes() << " nodes in "
                                 << mesh.dim << "D");
}

template <int d>
double energy_in(const Mesh& mesh, const MaterialTable& table, const Eigen::VectorXd& u) {
  double energy = 0.0;
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const SubdomainMaterial& material = table.of(mesh.subdomain[t]);
    const HyperelasticLaw& law = law_of(material);
    const Kinematics<d> k = kinematics<d>(mesh, t, material, u);
    if (!(k.F.determinant() > 0.0)) return std::numeric_limits<double>::infinity();
    // A law with no admissible state at F (plane-stress Saint Venant-Kirchhoff stretched past
    // its limit) is, for a line search, the same as an inverted cell.
    try {
      energy += k.volume * piola_response(law, k.F, false).energy;
    } catch (const Error&) {
      return std::numeric_limits<double>::infinity();
    }
  }
  return energy;
}

/// What a cell's law gives at its F: energy, first Piola stress, and dP/dF when asked.
template <int d>
using CellResponse = std::function<StepResponse<d>(int t, const HyperelasticLaw& law,
                                                   const Tensor<d>& F, bool with_tangent)>;

/// The loop of every assembly here: energy and force always, the tangent into K when K is given.
template <int d>
void assemble_over_cells(const Mesh& mesh, const MaterialTable& table,
                         const SparsityPattern* pattern, const Eigen::VectorXd& u,
                         HyperelasticState& state, Eigen::SparseMatrix<double>* K,
                         const CellResponse<d>& response) {
  state.internal_force.setZero(d * mesh.num_nodes());
  state.energy = 0.0;
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const SubdomainMaterial& material = table.of(mesh.subdomain[t]);
    const HyperelasticLaw& law = law_of(material);
    const Kinematics<d> kin = kinematics<d>(mesh, t, material, u);
    SIG_VERIFY(kin.F.determinant() > 0.0,
               mesh.cell_name() << " " << t + 1 << " is inverted: det F = " << kin.F.determinant());
    StepResponse<d> r;
    try {
      r = response(t, law, kin.F, K != nullptr);
    } catch (const Error& e) {
      throw Error(std::string(mesh.cell_name()) + " " + std::to_string(t + 1) + ": " + e.what());
    }
    // Virtual work, with dF = du_e g^T: f_e(d a + i) = |T| t (P g)(i, a) and
    // K_e(d a + i, d b + k) = |T| t (g^T A_ik g)(a, b), A_ik the d x d block dP_i./dF_k. of A.
    const SimplexVertices<d> f = kin.volume * (r.stress * kin.g);
    state.energy += kin.volume * r.energy;
    for (int a = 0; a <= d; ++a)
      state.internal_force.segment<d>(d * mesh.cells[t][a]) += f.col(a);
    if (K) {
      SimplexMatrix<d> Ke;
      for (int i = 0; i < d; ++i)
        for (int k = 0; k < d; ++k) {
          const Eigen::Matrix<double, d + 1, d + 1> block =
              kin.volume *
              (kin.g.transpose() * r.tangent.template block<d, d>(d * i, d * k) * kin.g);
          for (int a = 0; a <= d; ++a)
            for (int b = 0; b <= d; ++b)
              Ke(d * a + i, d * b + k) = block(a, b);
        }
      pattern->add(*K, t, Ke);
    }
  }
}

/// The hyperelastic law's own response: P = dW/dF and its tangent.
template <int d>
StepResponse<d> law_response(int, const HyperelasticLaw& law, const Tensor<d>& F,
                             bool with_tangent) {
  return piola_response(law, F, with_tangent);
}

/// The tangent's layout: reused in place when it already has the pattern's.
void reset_tangent(const SparsityPattern& pattern, Eigen::SparseMatrix<double>& K) {
  if (K.isCompressed() && K.rows() == pattern.num_dofs() && K.cols() == pattern.num_dofs() &&
      K.nonZeros() == pattern.nnz())
    K.coeffs().setZero();
  else
    K = pattern.zero_matrix();
}

template <int d>
void assemble_in(const Mesh& mesh, const MaterialTable& table, const SparsityPattern* pattern,
                 const Eigen::VectorXd& u, HyperelasticState& state) {
  if (pattern) reset_tangent(*pattern, state.tangent);
  assemble_over_cells<d>(mesh, table, pattern, u, state, pattern ? &state.tangent : nullptr,
                         law_response<d>);
}

template <int d>
PreviousStrain previous_strain_in(const Mesh& mesh, const MaterialTable& table,
                                  const Eigen::VectorXd& u_prev) {
  PreviousStrain previous;
  previous.F.resize(static_cast<std::size_t>(d * d * mesh.num_cells()));
  previous.energy.resize(mesh.num_cells());
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const SubdomainMaterial& material = table.of(mesh.subdomain[t]);
    const Kinematics<d> k = kinematics<d>(mesh, t, material, u_prev);
    SIG_VERIFY(k.F.determinant() > 0.0,
               mesh.cell_name() << " " << t + 1 << " is inverted: det F = " << k.F.determinant());
    previous.F_of<d>(t) = k.F;
    previous.energy[t] = step_energy(law_of(material), k.F);
  }
  return previous;
}

template <int d>
void assemble_step_in(const Mesh& mesh, const MaterialTable& table, const SparsityPattern& pattern,
                      const PreviousStrain& previous, AlgorithmicStress stress,
                      const Eigen::VectorXd& u, HyperelasticState& state, bool with_tangent,
                      PreviousStrain* strain) {
  if (strain) {
    strain->F.resize(previous.F.size());
    strain->energy.resize(previous.energy.size());
  }
  const CellResponse<d> response = [&](int t, const HyperelasticLaw& law, const Tensor<d>& F,
                                       bool tangent) {
    StepResponse<d> r =
        step_response(law, stress, Tensor<d>(previous.F_of<d>(t)), previous.energy[t], F, tangent);
    if (strain) {
      strain->F_of<d>(t) = F;
      strain->energy[t] = r.energy;
    }
    return r;
  };
  if (with_tangent) reset_tangent(pattern, state.tangent);
  assemble_over_cells<d>(mesh, table, &pattern, u, state, with_tangent ? &state.tangent : nullptr,
                         response);
}

} // namespace

double hyperelastic_energy(const Mesh& mesh, const MaterialTable& table, const Eigen::VectorXd& u) {
  verify_size(mesh, u);
  return with_dimension(mesh.dim, [&]<int d>(std::integral_constant<int, d>) {
    return energy_in<d>(mesh, table, u);
  });
}

void assemble_hyperelastic(const Mesh& mesh, const MaterialTable& table,
                           const SparsityPattern& pattern, const Eigen::VectorXd& u,
                           HyperelasticState& state) {
  SIG_VERIFY(u.size() == pattern.num_dofs() && pattern.num_dofs() == mesh.dim * mesh.num_nodes(),
             "displacement has " << u.size() << " values, pattern " << pattern.num_dofs()
                                 << " dofs, mesh " << mesh.num_nodes() << " nodes");
  with_dimension(mesh.dim, [&]<int d>(std::integral_constant<int, d>) {
    return assemble_in<d>(mesh, table, &pattern, u, state);
  });
}

void assemble_hyperelastic_force(const Mesh& mesh, const MaterialTable& table,
                                 const Eigen::VectorXd& u, HyperelasticState& state) {
  verify_size(mesh, u);
  with_dimension(mesh.dim, [&]<int d>(std::integral_constant<int, d>) {
    return assemble_in<d>(mesh, table, nullptr, u, state);
  });
}

PreviousStrain previous_strain(const Mesh& mesh, const MaterialTable& table,
                               const Eigen::VectorXd& u_prev) {
  verify_size(mesh, u_prev);
  return with_dimension(mesh.dim, [&]<int d>(std::integral_constant<int, d>) {
    return previous_strain_in<d>(mesh, table, u_prev);
  });
}

void assemble_hyperelastic_step(const Mesh& mesh, const MaterialTable& table,
                                const SparsityPattern& pattern, const PreviousStrain& previous,
                                AlgorithmicStress stress, const Eigen::VectorXd& u,
                                HyperelasticState& state, bool with_tangent,
                                PreviousStrain* strain) {
  SIG_VERIFY(u.size() == pattern.num_dofs() && pattern.num_dofs() == mesh.dim * mesh.num_nodes() &&
                 static_cast<int>(previous.energy.size()) == mesh.num_cells(),
             "time step: displacement has " << u.size() << " values, pattern " << pattern.num_dofs()
                                            << " dofs, the step start " << previous.energy.size()
                                            << " cells");
  with_dimension(mesh.dim, [&]<int d>(std::integral_constant<int, d>) {
    return assemble_step_in<d>(mesh, table, pattern, previous, stress, u, state, with_tangent,
                               strain);
  });
}

} // namespace sig
