#pragma once
// The rigid motions that the held dofs of a 2D body leave free, part by part. A part is a set of
// triangles joined by their sides: their P1 stiffness moves them as one rigid body when it does
// not strain them, (a, b) + c (-(y - yc), x - xc) / L. Parts meet at single nodes (hinges), where
// their motions must agree; a held dof stops the motion of every part at its node. The motions
// left are the null space of the stiffness: a static problem without contact has no solution
// then (K_ff is singular), and the linear solver's "not positive definite" tells the user
// nothing. This names the parts (nodes, sub-domains, references) and their free motions.
#include "mesh/mesh.hpp"

#include <string>
#include <vector>

namespace sig {

struct FreePart {
  bool whole_body = false;
  std::vector<int> nodes;      ///< 0-based, sorted
  std::vector<int> subdomains; ///< sorted
  std::vector<int> references; ///< of its edges and vertices, sorted
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  /// "the translation along x1 and the rotation about (0, 10)"
  std::string motions;
};

/// A node's displacement held along a direction: a Dirichlet dof along its axis, a contact node
/// along its obstacle's normal (and its tangent too, with friction).
struct Hold {
  int node = 0; ///< 0-based
  Eigen::Vector2d along = Eigen::Vector2d::UnitX();
};

/// What a solve holds while it factorizes, and what holds it in words.
struct Holds {
  std::vector<Hold> holds;
  std::string holders = "no imposed dof"; ///< "3 imposed dofs and 17 contact nodes"
};

/// A static solve's: the Dirichlet dofs (0-based, 2 per node: x then y), and the contact nodes
/// (0-based) along their normals, or wholly with friction, where it condenses the body onto
/// them: the rest of the body is factorized with those held.
Holds holds_of(const std::vector<int>& dirichlet_dofs, const std::vector<int>& contact_nodes = {},
               const std::vector<Eigen::Vector2d>& contact_normals = {}, bool friction = false);

/// The parts whose motions the holds leave free; empty if they hold the body. A mesh of more than
/// 200 parts (triangles joined by single nodes throughout) is not analysed: empty.
std::vector<FreePart> free_parts(const Mesh& mesh, const std::vector<Hold>& holds);

/// "the body is free to move: nothing holds the translation along x1, ..." for the whole body;
/// "the part of sub-domain 2 (4 nodes: 5, 6, 7, 8, around (2.5, 0.5); references on its
/// boundary: none) is free to move: nothing holds the ..." for a part of it.
std::string describe(const FreePart& part);

/// Throw sig::InputError naming `deck`, the first free part and what held the body if the holds
/// leave any part free.
void verify_rigid_motions_held(const Mesh& mesh, const Holds& held, const std::string& deck);

/// The same for a 3D body held by `dirichlet_dofs` (dof = 3 node + component) and by the contact
/// nodes along their obstacle normals (where a static solve condenses onto them), and with
/// `friction` along their tangent planes too: its six rigid motions, the body taken whole
/// (rigid_motion_3d.cpp).
void verify_rigid_motions_held_3d(const Mesh& mesh, const std::vector<int>& dirichlet_dofs,
                                  const std::string& deck,
                                  const std::vector<int>& contact_nodes = {},
                                  const std::vector<Point>& contact_normals = {},
                                  bool friction = false);

} // namespace sig
