#pragma once
// What the integrator's marches take, built from the other stages' data: the problems on the
// free dofs of the Dirichlet-reduced system (assembly/dirichlet.hpp), the mass of the TIME card
// and the contact boundary of the CONT elements. The integrator sees none of the mesh, the
// assembly or the contact elements: these are its only doors to them.
#include "integrator/dynamic_contact.hpp"
#include "integrator/elastodynamics.hpp"
#include "integrator/linear_contact_march.hpp"
#include "integrator/viscoelastic_problem.hpp"

#include "contact/contact_elements.hpp"

#include <Eigen/SparseCore>

#include <string>
#include <vector>

namespace sig {

class Card;
struct LinearSystem;
struct Mesh;
struct ReducedSystem;

/// The loads of a reduced system, f_f(t) - K_fd u_d (ReducedSystem::load_at); with ramped loads
/// alone, f + t rate on the free dofs without a full-size pass a step.
LoadHistory reduced_load(const ReducedSystem& reduced);

/// The full-size mass of `choice`: system.M, diag(system.M_lumped), or the EMM built from the
/// consistent mass with the 0-based nodes of Gamma3 `contact_nodes` (ignored for the other
/// choices). sig::Error if the system has no mass (every density 0).
Eigen::SparseMatrix<double> mass_matrix(const LinearSystem& system, MassChoice choice,
                                        const Mesh& mesh,
                                        const std::vector<int>& contact_nodes = {});

/// The reduced problem: K_ff, M_ff of the full-size `mass`, the loads reduced_load(reduced).
Elastodynamics reduced_elastodynamics(const ReducedSystem& reduced,
                                      const Eigen::SparseMatrix<double>& mass);

/// The reduced problem of the marches in velocity: K_ff, the viscosity V and the memory terms of
/// `system` restricted to the free dofs, M_ff of the full-size `mass` (empty: none) and the
/// loads reduced_load(reduced); rank rows where the system holds them (an mpirun job, with the
/// load of reduce_on_ranks, stages/rank_rows.hpp).
ViscoelasticProblem viscoelastic_problem(const LinearSystem& system, const ReducedSystem& reduced,
                                         const Eigen::SparseMatrix<double>& mass = {});

/// The boundary on the free dofs of `reduced`, its normal and tangential operators (d - 1
/// tangential rows a node), gaps, laws and weights as the CONT file has them; sig::Error if a
/// contact node has a Dirichlet dof or is not a node of the mesh.
ContactBoundary contact_boundary(const ContactElements& elements, const Mesh& mesh,
                                 const ReducedSystem& reduced);

/// The CONT elements of a linear march split by SOLVER candidate_gap= (stages/static_solve.hpp's
/// candidates): `condensed` those of initial gap at most it, `watched` the others (no force,
/// ContactBoundary::watched); without the field (solver null or without it) every element is
/// condensed. InputError on the SOLVER card's line for candidate_gap= in a hyperelastic march,
/// for laws that act apart from the obstacle (candidate_zone_problem), or a zone without nodes.
struct MarchContactZone {
  ContactElements condensed;
  ContactElements watched;
};
MarchContactZone march_contact_zone(ContactElements elements, const LinearSystem& system,
                                    const Card* solver, bool hyperelastic);

/// contact_boundary of the zone's condensed elements, with its watched ones' normal rows and gaps.
ContactBoundary contact_boundary(const MarchContactZone& zone, const Mesh& mesh,
                                 const ReducedSystem& reduced);

/// The contact elements of a CONT on the free dofs of `reduced`; sig::Error naming the node if
/// one of them has a Dirichlet component.
VelocityContact velocity_contact(const ContactElements& elements, const ReducedSystem& reduced);

} // namespace sig
