#pragma once
// Node-to-rigid contact elements (thesis Remark 3.1): one Gamma3 node plus one Lagrange-multiplier
// node each. This is the geometry half of contact (STYLE.md 1): mesh + obstacle in, the normal
// operator B_N and the gaps g out; solvers see only (K, f, B_N, g) and never the mesh.
//
// Per element i (node X_i): gap g_i = d(X_i) + extra gap >= 0, normal n_i = n(proj(X_i)) of the
// obstacle, normal displacement u_n,i = -n_i . u_i (positive towards the obstacle), Signorini
// (1.22): u_n,i <= g_i, lambda_i >= 0, lambda_i (u_n,i - g_i) = 0, with lambda_i the nodal
// contact force pushing the body along +n_i (pressure = lambda_i / weight_i).
#include "contact/obstacle.hpp"
#include "mesh/mesh.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sig {

class Datafile;

/// Law identifiers stored per element (CONT array "law").
inline constexpr int kLawSignorini = 1;
/// "signorini" for kLawSignorini; throws sig::Error for an unknown id.
std::string contact_law_name(int law);

struct ContactElements {
  int num_nodes = 0;     ///< mesh node count; Lagrange nodes are numbered after the mesh nodes
  int ref = 0;           ///< mesh reference of Gamma3
  double thickness = 1;  ///< out-of-plane thickness the weights include
  std::vector<int> node; ///< mesh node, 0-based, in boundary order (see below)
  std::vector<int> lagrange_node;      ///< num_nodes + i, 0-based
  std::vector<Eigen::Vector2d> normal; ///< outward unit normal of the obstacle at proj(X_i)
  Eigen::VectorXd gap;                 ///< initial gap g_i >= 0
  Eigen::VectorXd weight; ///< tributary length: half of each adjacent Gamma3 edge, x thickness
  std::vector<int> law;   ///< kLawSignorini
  ObstacleDescription obstacle;

  int size() const { return static_cast<int>(node.size()); }
};

/// Contact elements on the nodes of the edges with reference `ref`.
/// Order: along the boundary, in the direction of the stored edges (domain on the left, i.e.
/// counter-clockwise on an outer boundary), so that element order is arc-length order and
/// pressure plots need no sorting. Separate chains follow each other by their smallest node
/// number; a closed chain starts at its smallest node; where the edges do not form simple chains
/// (a node on three or more of them) the order falls back to node numbers.
/// A node inside the obstacle (gap < 0 beyond roundoff, 1e-9 of the shortest Gamma3 edge) is a
/// sig::Error; roundoff-negative gaps of nodes lying on the obstacle are set to 0.
ContactElements build_contact_elements(const Mesh& mesh, int ref, const Obstacle& obstacle,
                                       double extra_gap = 0, double thickness = 1);

/// B_N (size() x ndof, dof = 2 node + component): (B_N u)_i = u_n,i = -n_i . u_i.
Eigen::SparseMatrix<double> normal_operator(const ContactElements& elements, int ndof);

/// Gap at a current position x (large deformation: g = d(X_i + u_i)).
inline double gap_at(const Obstacle& obstacle, const Eigen::Vector2d& x) {
  return obstacle.signed_distance(x);
}

/// The CONTACT card of a datafile, or nothing if there is none:
///   CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 law=signorini gap=0
///   CONTACT ref=3 obstacle=disc centre=0,0 radius=1 law=signorini
/// ref must carry edges on the mesh; law defaults to signorini (the only one for now); gap is an
/// extra initial gap added to the geometric one (default 0). Thickness 1 (plane strain).
/// Errors are sig::InputError naming the file, line and field.
std::optional<ContactElements> contact_from_cards(const Datafile& datafile, const Mesh& mesh);

/// DS kind "CONT": node, lagrange_node (1-based), normal (m x 2), gap, weight, law,
/// obstacle_kind, obstacle_point, obstacle_normal, obstacle_radius, num_nodes, ref, thickness.
void write_cont(const std::filesystem::path& path, const ContactElements& elements,
                const std::string& title = "contact elements",
                const std::string& creator = "sig-contact");
/// Read and check a CONT file (sizes, numbering, unit normals, laws); errors name the file.
ContactElements read_cont(const std::filesystem::path& path);

} // namespace sig
