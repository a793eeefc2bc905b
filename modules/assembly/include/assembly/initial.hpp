#pragma once
// The INITIAL cards (repeatable; each sets only the fields it gives):
//
//   INITIAL [u=ux,uy] [v=vx,vy] [omega= centre=x,y] [region=...]
//   INITIAL [u=ux,uy,uz] [v=vx,vy,vz] [omega=wx,wy,wz centre=x,y,z] [region=...]   (3D mesh)
//
// omega adds a rigid rotation about `centre` to the velocity, v + omega e3 x (X - centre) in 2D,
// v + omega x (X - centre) in 3D, at the reference position X of each node (a throw with spin;
// with omega alone the body spins in place). Every vector has the mesh's d components.
// In a dynamic deck (sig-march) the initial displacement and velocity; in a static contact deck
// (sig-solve) u is the first iterate of the contact Newton, e.g. the small rigid shift a body
// held by contact alone may need to start from several contact nodes (v is refused there).
#include <Eigen/Core>

namespace sig {

class Datafile;
struct Mesh;

/// Full-size (d per node, interleaved) initial displacement and velocity of the INITIAL cards:
/// the uniform u and the velocity v (+ the rotation) of each card on the nodes of the triangles
/// of its sub-domains (a card sets only the fields it gives; a later card wins on shared nodes).
/// Zero without INITIAL card; an InputError for a vector without d components, an unknown
/// region, or omega without centre (and the reverse).
struct InitialFields {
  Eigen::VectorXd u;
  Eigen::VectorXd v;
};
InitialFields initial_fields(const Datafile& datafile, const Mesh& mesh);

} // namespace sig
