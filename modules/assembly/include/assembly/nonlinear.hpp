#pragma once
// The hyperelastic bulk in large deformation (total Lagrangian, P1 triangles): the stored energy
// E(u) = sum_T thickness |T| W(F_T), its gradient (the internal force) and its Hessian (the
// tangent stiffness), for the laws of the MILI table (law=svk | ciarlet-geymonat).
//
// On each triangle F = I + sum_a u_a (x) grad(lambda_a), with the barycentric gradients of the
// reference configuration, so F is constant and one point integrates exactly. The tangent is
// filled on the fixed SparsityPattern through its scatter map: in a Newton loop the matrix is
// allocated once and only its values are rewritten (DESIGN.md: no triplets in a Newton loop).
#include "assembly/pattern.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace sig {

struct Mesh;
struct MaterialTable;
enum class AlgorithmicStress; // material/algorithmic_stress.hpp

/// Energy, internal force and tangent stiffness at one displacement.
struct HyperelasticState {
  double energy = 0.0;                 ///< stored energy of the body
  Eigen::VectorXd internal_force;      ///< dE/du, dof = 2 node + component
  Eigen::SparseMatrix<double> tangent; ///< d2E/du2, symmetric, on the pattern's layout
};

/// The strain at the start of a time step (material/algorithmic_stress.hpp): per triangle
/// F_{n-1} and W(F_{n-1}), computed once per step.
struct PreviousStrain {
  std::vector<Eigen::Matrix2d> F;
  std::vector<double> energy;
};

/// F and W of every triangle at u_prev. Throws as assemble_hyperelastic.
PreviousStrain previous_strain(const Mesh& mesh, const MaterialTable& table,
                               const Eigen::VectorXd& u_prev);

/// The internal force of a midpoint time step from `previous` to u (thesis (3.40)): G_a =
/// sum_T |T| t Pi : grad(lambda_a), Pi the stress of the step (`stress`); its derivative in u
/// into state.tangent when `with_tangent` (not symmetric for Gonzalez's stress; the pattern's
/// layout, as assemble_hyperelastic), and the stored energy at u. Throws as
/// assemble_hyperelastic.
void assemble_hyperelastic_step(const Mesh& mesh, const MaterialTable& table,
                                const SparsityPattern& pattern, const PreviousStrain& previous,
                                AlgorithmicStress stress, const Eigen::VectorXd& u,
                                HyperelasticState& state, bool with_tangent);

/// The stored energy alone (for a line search). +infinity when a triangle is inverted
/// (det F <= 0), so that a step that folds the mesh is refused rather than thrown. Every
/// sub-domain must have a hyperelastic law (sig::Error otherwise).
double hyperelastic_energy(const Mesh& mesh, const MaterialTable& table, const Eigen::VectorXd& u);

/// Energy, internal force and tangent at u (2 * nodes values). state.tangent is reused when it
/// already has the pattern's layout (values zeroed and refilled in place, no allocation);
/// otherwise it is set to pattern.zero_matrix() first. Throws sig::Error naming the triangle
/// when det F <= 0 or the law has no state at F, and when a sub-domain has no hyperelastic law.
void assemble_hyperelastic(const Mesh& mesh, const MaterialTable& table,
                           const SparsityPattern& pattern, const Eigen::VectorXd& u,
                           HyperelasticState& state);

/// Energy and internal force alone at u (a line-search trial: no tangent is needed until the
/// trial is accepted, and the scatter of 36 entries per triangle is skipped). state.tangent is
/// left as it was, so it no longer matches u. Throws as assemble_hyperelastic.
void assemble_hyperelastic_force(const Mesh& mesh, const MaterialTable& table,
                                 const Eigen::VectorXd& u, HyperelasticState& state);

} // namespace sig
