#pragma once
// The hyperelastic bulk in large deformation (total Lagrangian, P1 simplices in R^d: triangles
// in 2D, tetrahedra in 3D, one code path templated on the mesh's dimension): the stored energy
// E(u) = sum_T thickness |T| W(F_T) (3D: no thickness), its gradient (the internal force) and
// its Hessian (the tangent stiffness), for the laws of the MILI table (law=svk |
// ciarlet-geymonat). Dofs are d per node, dof = d node + component.
//
// On each cell F = I + sum_a u_a (x) grad(lambda_a), with the barycentric gradients of the
// reference configuration, so F is constant and one point integrates exactly. The tangent is
// filled on the fixed SparsityPattern through its scatter map: in a Newton loop the matrix is
// allocated once and only its values are rewritten (DESIGN.md: no triplets in a Newton loop).
#include "assembly/pattern.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cstddef>
#include <vector>

namespace sig {

struct Mesh;
struct MaterialTable;
enum class AlgorithmicStress; // material/algorithmic_stress.hpp

/// Energy, internal force and tangent stiffness at one displacement.
struct HyperelasticState {
  double energy = 0.0;                 ///< stored energy of the body
  Eigen::VectorXd internal_force;      ///< dE/du, dof = d node + component
  Eigen::SparseMatrix<double> tangent; ///< d2E/du2, symmetric, on the pattern's layout
};

/// The strain at the start of a time step (material/algorithmic_stress.hpp): per cell F_{n-1}
/// and W(F_{n-1}), computed once per step.
struct PreviousStrain {
  std::vector<double> F; ///< d x d entries per cell (column-major), d the mesh's dimension
  std::vector<double> energy;

  /// F of cell t in a mesh of dimension d.
  template <int d> Eigen::Map<Eigen::Matrix<double, d, d>> F_of(int t) {
    return Eigen::Map<Eigen::Matrix<double, d, d>>(F.data() + static_cast<std::size_t>(d * d * t));
  }
  template <int d> Eigen::Map<const Eigen::Matrix<double, d, d>> F_of(int t) const {
    return Eigen::Map<const Eigen::Matrix<double, d, d>>(F.data() +
                                                         static_cast<std::size_t>(d * d * t));
  }
};

/// F and W of every cell at u_prev. Throws as assemble_hyperelastic.
PreviousStrain previous_strain(const Mesh& mesh, const MaterialTable& table,
                               const Eigen::VectorXd& u_prev);

/// The internal force of a midpoint time step from `previous` to u (thesis (3.40)): G_a =
/// sum_T |T| t Pi : grad(lambda_a), Pi the stress of the step (`stress`); its derivative in u
/// into state.tangent when `with_tangent` (not symmetric for Gonzalez's stress; the pattern's
/// layout, as assemble_hyperelastic), and the stored energy at u; the strain at u into `strain`
/// if given (the next step's start, without a second pass). Throws as assemble_hyperelastic.
void assemble_hyperelastic_step(const Mesh& mesh, const MaterialTable& table,
                                const SparsityPattern& pattern, const PreviousStrain& previous,
                                AlgorithmicStress stress, const Eigen::VectorXd& u,
                                HyperelasticState& state, bool with_tangent,
                                PreviousStrain* strain = nullptr);

/// The stored energy alone (for a line search). +infinity when a cell is inverted
/// (det F <= 0), so that a step that folds the mesh is refused rather than thrown. Every
/// sub-domain must have a hyperelastic law (sig::Error otherwise).
double hyperelastic_energy(const Mesh& mesh, const MaterialTable& table, const Eigen::VectorXd& u);

/// Energy, internal force and tangent at u (d * nodes values). state.tangent is reused when it
/// already has the pattern's layout (values zeroed and refilled in place, no allocation);
/// otherwise it is set to pattern.zero_matrix() first. Throws sig::Error naming the cell
/// when det F <= 0 or the law has no state at F, and when a sub-domain has no hyperelastic law.
void assemble_hyperelastic(const Mesh& mesh, const MaterialTable& table,
                           const SparsityPattern& pattern, const Eigen::VectorXd& u,
                           HyperelasticState& state);

/// Energy and internal force alone at u (a line-search trial: no tangent is needed until the
/// trial is accepted, and the scatter of (d (d + 1))^2 entries per cell is skipped). state.tangent
/// is left as it was, so it no longer matches u. Throws as assemble_hyperelastic.
void assemble_hyperelastic_force(const Mesh& mesh, const MaterialTable& table,
                                 const Eigen::VectorXd& u, HyperelasticState& state);

} // namespace sig
