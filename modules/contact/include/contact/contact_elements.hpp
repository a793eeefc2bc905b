#pragma once
// Node-to-rigid contact elements (thesis Remark 3.1): one Gamma3 node plus one Lagrange node
// each, the node carrying the normal and (with friction) the tangential multiplier. This is the
// geometry half of contact (STYLE.md 1): mesh + obstacle + laws in, the normals and tangents
// (the rows of B_N and B_T, which the solvers apply as nodal frames), the gaps and the laws out,
// once, before any solver; solvers see only these and never the mesh.
//
// Per element i (node X_i), in the mesh's dimension d = 2 or 3:
//   normal n_i = n(proj(X_i)) of the obstacle (pointing to the body's side), tangent
//   t_i = (n_i2, -n_i1) in 2D (for the foundation x2 <= 0 with n = (0, 1): t = (1, 0), so slip
//   towards +x1 is positive, the S+ of the thesis); in 3D the tangents t1_i, t2_i of
//   contact_frame(n_i) (contact/contact_law.hpp), `tangent` holding t1_i;
//   normal displacement u_n,i = -n_i . u_i (positive towards the obstacle), slip u_t,i = t_i . u_i;
//   gap d_i = d(X_i) >= 0, the distance to the obstacle surface: the penetration is
//   q_n,i = u_n,i - d_i, and the laws (contact_law.hpp) are written in q_n, with the wall at
//   q_n = g_i (the law's depth);
//   weight w_i, the tributary length (area in 3D: a third of each adjacent Gamma3 face, the
//   exact nodal load of a uniform pressure on P1 faces): nodal force = pressure x w_i.
// Gaps, one name for one meaning each (the CONTACT card and the CONT file use the same):
//   gap    d_i, from the mesh and the obstacle (never set by hand)
//   g      the depth of the rigid wall beyond the obstacle surface (card field g=, the old
//          spelling gap= still read): signorini's extra gap, compliance-unilateral's layer, IPM's
//          allowed penetration; the unilateral bound is u_n,i <= d_i + g_i.
#include "contact/contact_law.hpp"
#include "contact/obstacle.hpp"
#include "mesh/mesh.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sig {

class Card;
class Datafile;

struct ContactElements {
  int dim = 2;           ///< the mesh's dimension: dofs d node + component
  int num_nodes = 0;     ///< mesh node count; Lagrange nodes are numbered after the mesh nodes
  int ref = 0;           ///< mesh reference of Gamma3
  double thickness = 1;  ///< out-of-plane thickness the weights include
  std::vector<int> node; ///< mesh node, 0-based, in boundary order (see below)
  std::vector<int> lagrange_node; ///< num_nodes + i, 0-based
  std::vector<Point> normal;  ///< outward unit normal of the obstacle at proj(X_i), d components
  std::vector<Point> tangent; ///< the first column of contact_frame(normal[i])
  Eigen::VectorXd gap;        ///< d_i >= 0: distance to the obstacle surface
  /// tributary length (2D: half of each adjacent Gamma3 edge, x thickness) or area (3D: a third
  /// of each adjacent Gamma3 face)
  Eigen::VectorXd weight;
  std::vector<ContactLaw> law;
  ObstacleDescription obstacle;

  int size() const { return static_cast<int>(node.size()); }
  /// True if some element has a friction law.
  bool has_friction() const;
  /// The unilateral bound of element i on u_n: d_i + g_i (infinite without a wall).
  double bound(int i) const;
  /// The size of the contact boundary: its length (2D) or the square root of its area (3D).
  double extent() const { return dim == 3 ? std::sqrt(weight.sum()) : weight.sum() / thickness; }
  /// contact_frame(normal[i]): the tangents and -n as columns.
  ContactFrame frame(int i) const { return contact_frame(normal[i]); }
  /// The frames of every element.
  std::vector<ContactFrame> frames() const;
  /// The elements `zone` (indices, sorted), the rest (mesh, obstacle, thickness) the same.
  ContactElements subset(const std::vector<int>& zone) const;
};

/// Contact elements on the nodes of the facets (edges in 2D, faces in 3D) with reference `ref`.
/// Order in 2D: along the boundary, in the direction of the stored edges (domain on the left, i.e.
/// counter-clockwise on an outer boundary), so that element order is arc-length order and
/// pressure plots need no sorting. Separate chains follow each other by their smallest node
/// number; a closed chain starts at its smallest node; where the edges do not form simple chains
/// (a node on three or more of them) the order falls back to node numbers, as it always does in
/// 3D. The obstacle's dimension must be the mesh's (sig::Error).
/// A node inside the obstacle (gap < 0 beyond roundoff, 1e-9 of the shortest Gamma3 edge) is a
/// sig::Error; roundoff-negative gaps of nodes lying on the obstacle are set to 0. Every element
/// gets `law` (sig::Error if law_problem finds it inadmissible). The nodes of `excluded` (0-based)
/// get no element (the weights of the others are unchanged): the ends of Gamma3 that are clamped
/// nodes of Gamma1, whose reaction is the Dirichlet condition's.
ContactElements build_contact_elements(const Mesh& mesh, int ref, const Obstacle& obstacle,
                                       const ContactLaw& law = {}, double thickness = 1,
                                       const std::vector<int>& excluded = {});

/// The elements (indices) whose obstacle normal points along the body's outward normal at their
/// node (the sum of its Gamma3 facets' area-weighted normals): the obstacle faces the body from the
/// inside there, so the node cannot reach it. A few such nodes belong to a curved Gamma3 (its upper
/// part); most of them mean an obstacle normal given the wrong way round.
std::vector<int> nodes_facing_away(const Mesh& mesh, const ContactElements& elements);

/// B_N (size() x ndof, dof = d node + component): (B_N u)_i = u_n,i = -n_i . u_i.
Eigen::SparseMatrix<double> normal_operator(const ContactElements& elements, int ndof);

/// Gap at a current position x (large deformation: g = d(X_i + u_i)).
inline double gap_at(const Obstacle& obstacle, const Point& x) {
  return obstacle.signed_distance(x);
}

/// The CONTACT card of a datafile (and its FRICTION card), or nothing if there is none:
///   CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 law=signorini g=0
///   CONTACT ref=3 obstacle=disc centre=0,0 radius=1 law=compliance cn=10 c3=1e8
///   CONTACT ref=3 ... law=compliance-unilateral cn=10 g=0.5
///   CONTACT ref=3 ... law=damped cn=10 | law=damped-unilateral cn=10 g=0.01   (in velocity)
///   CONTACT ref=3 ... exclude=1,4      no element on the nodes that also carry reference 1 or 4
///   FRICTION ref=3 law=coulomb mu=0.3          (or law=tresca threshold=2, law=none)
///   FRICTION ref=3 law=nonmonotone a=2 b=0.02 alpha=1 of=slip bound=compliance
/// In 3D every vector has three components (point=x,y,z normal=nx,ny,nz) and the round obstacle
///   is obstacle=sphere centre=x,y,z radius=R; friction in 3D is law=tresca or law=coulomb (the
///   others are refused for now, issue 26).
/// ref must carry facets on the mesh; law defaults to signorini, g to 0 (gap= is its old
/// spelling; compliance-unilateral must give it); a field the law does not use is an error, as is a
/// FRICTION card whose ref has no CONTACT card. Thickness 1 (plane strain). Errors are
/// sig::InputError naming the file, line and field.
std::optional<ContactElements> contact_from_cards(const Datafile& datafile, const Mesh& mesh);

/// The FRICTION card with a friction law other than none, or null: the stages that do not model
/// friction refuse it on its own line.
const Card* friction_card_with_law(const Datafile& datafile);

/// The CONTACT card's wall depth g= (or its old spelling gap=), 0 when absent; both given is an
/// InputError.
double wall_depth(const Card& contact);

/// DS kind "CONT": node, lagrange_node (1-based), normal and tangent (m x d), gap (d_i), weight;
/// the laws per element: law (normal law id, contact_law.hpp), cn, c3 (0 = no truncation),
/// depth (g), friction_law (id), mu, threshold, friction_bound (0 normal, 1 compliance),
/// friction_a, friction_b, friction_alpha, friction_of (0 slip, 1 slip-rate); obstacle_kind,
/// obstacle_point, obstacle_normal (d each), obstacle_radius, num_nodes, ref, thickness; d is the
/// mesh's.
void write_cont(const std::filesystem::path& path, const ContactElements& elements,
                const std::string& title = "contact elements",
                const std::string& creator = "sig-contact");
/// Read and check a CONT file of `mesh` (sizes, numbering, unit normals, laws, the gaps and the
/// weights in their ranges, core/ranges.hpp); errors name the file and the array.
ContactElements read_cont(const std::filesystem::path& path, const Mesh& mesh);

} // namespace sig
