#pragma once
// The INITIAL cards (repeatable; each sets only the fields it gives):
//
//   INITIAL [u=ux,uy] [v=vx,vy] [region=...]
//
// In a dynamic deck (sig-march) the initial displacement and velocity; in a static contact deck
// (sig-solve) u is the first iterate of the contact Newton, e.g. the small rigid shift a body
// held by contact alone may need to start from several contact nodes (v is refused there).
#include <Eigen/Core>

namespace sig {

class Datafile;
struct Mesh;

/// Full-size (2 per node, interleaved) initial displacement and velocity of the INITIAL cards:
/// the uniform u and v of each card on the nodes of the triangles of its sub-domains (a card
/// sets only the fields it gives; a later card wins on shared nodes). Zero without INITIAL card;
/// an InputError for a vector without two components or an unknown region.
struct InitialFields {
  Eigen::VectorXd u;
  Eigen::VectorXd v;
};
InitialFields initial_fields(const Datafile& datafile, const Mesh& mesh);

} // namespace sig
