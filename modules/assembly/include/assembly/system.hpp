#pragma once
// The linear(ized) system of small-strain elasticity on a mesh: stiffness, mass, loads and the
// Dirichlet conditions, as the stage sig-assemble writes it to the DS "TAE". K and M share one
// SparsityPattern (assembly/pattern.hpp): column-major, full symmetric, sorted indices.
//
//   DIRICHLET ref=R [ux=a] [uy=b]   fixes a component only if its field is given, on the nodes
//                                   of reference R (edges and vertices); a dof named by several
//                                   cards takes the value of the last one
#include "assembly/pattern.hpp"
#include "assembly/time_loads.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <filesystem>
#include <string>
#include <vector>

namespace sig {

class Card;
class Datafile;
struct Mesh;
struct MaterialTable;

/// The stiffness of one exponential term exp(-beta t) KK of a memory kernel (kelvin_voigt.hpp):
/// every sub-domain's terms of the same beta, summed.
struct MemoryStiffness {
  double beta = 0;
  Eigen::SparseMatrix<double> K;
};

struct LinearSystem {
  Eigen::SparseMatrix<double> K; ///< stiffness (for a Kelvin-Voigt law: of its elastic part B)
  Eigen::SparseMatrix<double> M; ///< consistent mass; 0 x 0 if every density is 0
  Eigen::VectorXd M_lumped;      ///< row sums of the consistent mass (zeros without density)
  Eigen::VectorXd f;             ///< loads at t = 0
  TimeLoads time_loads;          ///< their change in time (empty: constant loads)
  /// The viscosity's "stiffness" K_A (A of kelvin_voigt.hpp, on strain rates); 0 x 0 without a
  /// kelvin-voigt law. Same pattern as K.
  Eigen::SparseMatrix<double> V;
  std::vector<MemoryStiffness> memory; ///< one per distinct beta of the MEMORY cards
  std::vector<int> dirichlet_dofs;     ///< sorted, unique, 0-based
  Eigen::VectorXd dirichlet_values;
  double assemble_seconds = 0.0; ///< wall time of assemble_system
  /// K, f (and M, M_lumped, V, the memory terms) hold only the rows of this rank of an mpirun
  /// job (read_tae_rows), the rest empty; the time loads are whole.
  bool rank_rows = false;

  int num_dofs() const { return static_cast<int>(f.size()); }
  /// The loads at time t: f + time_loads.change(t).
  Eigen::VectorXd load_at(double t) const;
};

/// Stiffness sum over triangles of p1_stiffness with the law and thickness of their sub-domain.
Eigen::SparseMatrix<double> assemble_stiffness(const Mesh& mesh, const MaterialTable& table,
                                               const SparsityPattern& pattern);
/// The viscous K_A of the kelvin-voigt sub-domains (zero elsewhere), and the stiffness of every
/// distinct beta of their memory terms, in the order of first appearance in the table.
Eigen::SparseMatrix<double> assemble_viscosity(const Mesh& mesh, const MaterialTable& table,
                                               const SparsityPattern& pattern);
std::vector<MemoryStiffness> assemble_memory(const Mesh& mesh, const MaterialTable& table,
                                             const SparsityPattern& pattern);
/// Consistent mass on the same pattern.
Eigen::SparseMatrix<double> assemble_mass(const Mesh& mesh, const MaterialTable& table,
                                          const SparsityPattern& pattern);
/// Lumped (row-sum) mass, one value per dof.
Eigen::VectorXd assemble_lumped_mass(const Mesh& mesh, const MaterialTable& table);

/// The Dirichlet dofs and values of the DIRICHLET cards; a reference that no edge or vertex
/// carries is an InputError on the card line and field 'ref', and so is a dof that two cards
/// give two values (on the second card's field, naming the first card's line).
void dirichlet_from_cards(const Mesh& mesh, const Datafile& datafile, std::vector<int>& dofs,
                          Eigen::VectorXd& values);
/// The first DIRICHLET card of `datafile` that holds `dof` (d node + component), or nullptr:
/// the card a later stage names when it cannot honour that condition.
const Card* dirichlet_card_of(const Mesh& mesh, const Datafile& datafile, int dof);

/// Everything from the mesh, the MILI table and the DIRICHLET, TRACTION, PRESSURE, BODYFORCE
/// and MOVINGLOAD cards. With `owned` (per dof, a rank's rows: stages/rank_rows.hpp) the
/// matrices hold those rows only, assembled on the cells that reach them (the others empty; the
/// values those of the whole assembly, bit for bit), the vectors stay the whole body's.
LinearSystem assemble_system(const Mesh& mesh, const MaterialTable& table, const Datafile& datafile,
                             const std::vector<char>* owned = nullptr);

/// DS "TAE": ndof; K_rowptr, K_col (1-based CSR of the full symmetric matrix), K_val; M_val
/// (same pattern, only if M is not empty); M_lumped; f; dirichlet_dof (1-based);
/// dirichlet_value; time_assemble (seconds); with moving loads: moving_load (F, psi, c, x0 per
/// load), moving_points (points per load), moving_node (nodes a, b per point, 1-based),
/// moving_x1 and moving_weight (weight_a, weight_b per point) (assembly/time_loads.hpp); with
/// ramped loads: f_rate (ndof); with a kelvin-voigt law: V_val (same pattern), memory_beta
/// (terms) and memory_val {terms, nnz} (same pattern).
void write_tae(const std::filesystem::path& path, const LinearSystem& system,
               const std::string& title);
LinearSystem read_tae(const std::filesystem::path& path);
/// The part of a TAE that one rank of a distributed solve or march holds: of K, the entries of
/// the rows `owned` marks (ndof flags; K stays ndof x ndof, its other rows zero: explicit zeros
/// where the transposed entries of the held rows lie, so that the pattern is symmetric), streamed
/// off the file so that the whole K is never in memory; f on those rows (zero elsewhere); every
/// Dirichlet condition. With `march`, also the same rows of M, V and the memory terms (streamed
/// as K, on K's pattern as the file has them) and of M_lumped, and the time loads whole (their
/// change is a vector of the whole body, cheap beside the matrices); without it no mass,
/// viscosity or time loads (the static solve has none). Symmetry is checked where a rank sees
/// both entries (rows and columns it owns).
LinearSystem read_tae_rows(const std::filesystem::path& path, const std::vector<char>& owned,
                           bool march = false);

} // namespace sig
