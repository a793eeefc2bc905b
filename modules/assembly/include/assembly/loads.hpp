#pragma once
// The load vector of the linear problem: surface tractions on referenced edges and body forces
// on sub-domains, each the integral of the load against the P1 basis (exact for the constant
// loads of the cards), times the thickness of the sub-domain that carries it.
//
//   TRACTION  ref=R f=fx,fy   constant traction g on the edges of reference R
//   PRESSURE  ref=R p=P       normal traction g = -P n, n the outward unit normal (P > 0 pushes)
//   BODYFORCE [region=S] f=fx,fy   force per unit volume on sub-domains S (default all)
//   MOVINGLOAD ref=R F= psi= c= [x0=]   a load that moves (assembly/time_loads.hpp): in the
//                             load vector at t = 0, its change in time apart
// Each of TRACTION, PRESSURE and BODYFORCE also takes `ramp=t1` (> 0): the load then grows
// linearly in time, g(t) = g t / t1 (the thesis's f2 = (0, -10 t) of chapter 5 is
// `f=0,-10 ramp=1`), zero at t = 0, its rate g / t1 in TimeLoads::rate; without ramp= it is
// constant. Only a march in time (sig-march) has a t: a static deck refuses ramp=.
#include <Eigen/Core>

namespace sig {

class Card;
class Datafile;
struct Mesh;
struct MaterialTable;
struct Facet;
struct TimeLoads;

/// Outward unit normal of a boundary edge: pointing away from the triangle that owns it (so an
/// edge stored in either direction gets the same normal); for an edge shared by two triangles
/// (an interface), the right-hand normal of a -> b, i.e. the outward normal of the side on its
/// left. Builds the edge-to-triangle map of the whole mesh on each call: meant for tests and
/// one-off queries, not for loops over edges.
Eigen::Vector2d edge_outward_normal(const Mesh& mesh, const Facet& edge);

/// f at t = 0 from the TRACTION, PRESSURE, BODYFORCE and MOVINGLOAD cards (size 2 * nodes);
/// the change of the time-dependent ones (moving, ramped) in `*time_loads` when it is given.
/// References and regions are checked (assembly/cards.hpp), MOVINGLOAD's psi > 0 and ramp > 0.
Eigen::VectorXd assemble_loads(const Mesh& mesh, const MaterialTable& table,
                               const Datafile& datafile, TimeLoads* time_loads = nullptr);

/// f of a 3D body (size 3 * nodes) from the TRACTION (f=fx,fy,fz), PRESSURE and BODYFORCE
/// (f=fx,fy,fz) cards, on referenced faces and sub-domains (assembly/src/loads_3d.cpp); the
/// ramped ones' rate in `*time_loads` when it is given, as assemble_loads. MOVINGLOAD is refused
/// on its card: 2D only for now (issue 26).
Eigen::VectorXd assemble_loads_3d(const Mesh& mesh, const Datafile& datafile,
                                  TimeLoads* time_loads = nullptr);

/// Where a load card's nodal forces go, in either dimension: `f` with scale 1 (a constant load),
/// or the rate of the ramped loads with scale 1 / ramp (ramp= given; the load reaches its value
/// at t = ramp). sig::InputError on the card's line unless ramp > 0.
struct LoadTarget {
  Eigen::VectorXd& into;
  double scale;
};
LoadTarget load_target(const Card& card, Eigen::VectorXd& f, Eigen::VectorXd& rate);

/// The first load card of `datafile` with a ramp= field, or null: the stages without time refuse
/// it on its own line.
const Card* ramped_load_card(const Datafile& datafile);

} // namespace sig
