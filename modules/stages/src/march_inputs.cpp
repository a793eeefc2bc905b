#include "stages/march_inputs.hpp"

#include "assembly/dirichlet.hpp"
#include "assembly/system.hpp"
#include "contact/contact_elements.hpp"
#include "core/datafile.hpp"
#include "core/error.hpp"
#include "integrator/emm.hpp"
#include "mesh/mesh.hpp"
#include "stages/static_solve.hpp"

#include <cmath>

#include <memory>
#include <utility>

namespace sig {

LoadHistory reduced_load(const ReducedSystem& reduced) {
  const TimeLoads& loads = reduced.time_loads;
  if (loads.empty()) return constant_load(reduced.f);
  if (loads.moving.empty())
    return [f = reduced.f, rate = reduced.restrict(loads.rate)](double t) {
      return Eigen::VectorXd(f + t * rate);
    };
  // What ReducedSystem::load_at reads, without the stiffness.
  auto moving = std::make_shared<ReducedSystem>();
  moving->f = reduced.f;
  moving->free_dofs = reduced.free_dofs;
  moving->reduced_index = reduced.reduced_index;
  moving->time_loads = loads;
  return [moving](double t) { return moving->load_at(t); };
}

Eigen::SparseMatrix<double> mass_matrix(const LinearSystem& system, MassChoice choice,
                                        const Mesh& mesh, const std::vector<int>& contact_nodes) {
  SIG_VERIFY(system.M.rows() == system.num_dofs() && system.M.nonZeros() > 0,
             "the system has no mass: give the MATERIAL cards a density rho > 0");
  switch (choice) {
  case MassChoice::consistent:
    return system.M;
  case MassChoice::lumped:
    return diagonal_mass(system.M_lumped);
  case MassChoice::emm:
    // Without contact nodes the EMM would be the consistent mass under another name.
    SIG_VERIFY(!contact_nodes.empty(), "mass=emm needs the contact nodes (a CONTACT card)");
    // The integrator sees positions, not the mesh (tests/layering).
    return equivalent_mass_matrix(system.M, node_positions(mesh), contact_nodes);
  }
  return system.M;
}

Elastodynamics reduced_elastodynamics(const ReducedSystem& reduced,
                                      const Eigen::SparseMatrix<double>& mass) {
  Elastodynamics problem;
  problem.K = reduced.K;
  problem.M = reduced.restrict_matrix(mass);
  problem.load = reduced_load(reduced);
  return problem;
}

ViscoelasticProblem viscoelastic_problem(const LinearSystem& system, const ReducedSystem& reduced,
                                         const Eigen::SparseMatrix<double>& mass) {
  ViscoelasticProblem problem;
  problem.K = reduced.K;
  if (system.V.size() > 0) problem.C = reduced.restrict_matrix(system.V);
  for (const MemoryStiffness& term : system.memory)
    problem.memory.push_back({term.beta, reduced.restrict_matrix(term.K)});
  if (mass.size() > 0) problem.M = reduced.restrict_matrix(mass);
  problem.load = reduced_load(reduced);
  problem.rank_rows = system.rank_rows;
  return problem;
}

ContactBoundary contact_boundary(const ContactElements& elements, const Mesh& mesh,
                                 const ReducedSystem& reduced) {
  ContactBoundary b;
  b.nodes = elements.node;
  b.setting = {elements.law, elements.weight};
  b.geometric_gap = elements.gap;
  const int p = elements.size();
  for (int i = 0; i < p; ++i)
    SIG_VERIFY(elements.node[i] >= 0 && elements.node[i] < mesh.num_nodes(),
               "contact element " << i + 1 << ": node " << elements.node[i] + 1
                                  << " is not a node of the mesh");
  // Row i: u_n,i = -n_i . u_i; rows (d - 1) i + k: the tangential displacements t_k,i . u_i
  // along the tangents of the node's contact frame (its first d - 1 columns: t_i in 2D, t1_i and
  // t2_i in 3D), on the node's d free dofs.
  const int d = mesh.dim;
  std::vector<Eigen::Triplet<double>> normal, tangential;
  for (int i = 0; i < p; ++i) {
    const int first = reduced.contact_node_first_dof(elements.node[i], d);
    const ContactFrame frame = elements.frame(i);
    b.first_dof.push_back(first);
    b.frame.push_back(frame);
    for (int component = 0; component < d; ++component) {
      normal.emplace_back(i, first + component, -elements.normal[i][component]);
      for (int k = 0; k < d - 1; ++k)
        tangential.emplace_back((d - 1) * i + k, first + component, frame(component, k));
    }
  }
  b.B.resize(p, reduced.num_free());
  b.B.setFromTriplets(normal.begin(), normal.end());
  b.tangential.resize((d - 1) * p, reduced.num_free());
  b.tangential.setFromTriplets(tangential.begin(), tangential.end());
  return b;
}

MarchContactZone march_contact_zone(ContactElements elements, const LinearSystem& system,
                                    const Card* solver, bool hyperelastic) {
  MarchContactZone zone;
  if (solver == nullptr || !solver->has("candidate_gap")) {
    zone.condensed = std::move(elements);
    zone.watched = zone.condensed.subset({});
    return zone;
  }
  const double bound = solver->real("candidate_gap"); // > 0: core/ranges.hpp
  if (hyperelastic)
    solver->fail("candidate_gap", "the hyperelastic march takes every contact node into its "
                                  "Newton matrix; candidate_gap= serves the linear march only");
  if (const std::string problem = candidate_zone_problem(elements); !problem.empty())
    solver->fail("candidate_gap", "condenses only the nodes near the obstacle, but " + problem);
  const std::vector<int> inside = candidates(system, elements, bound);
  if (inside.empty())
    solver->fail("candidate_gap", "no contact node has an initial gap at most " +
                                      solver->text("candidate_gap") + " (the least is " +
                                      std::to_string(elements.gap.minCoeff()) + ")");
  std::vector<int> outside;
  for (int i = 0, k = 0; i < elements.size(); ++i) {
    if (k < std::ssize(inside) && inside[static_cast<std::size_t>(k)] == i)
      ++k;
    else
      outside.push_back(i);
  }
  zone.condensed = elements.subset(inside);
  zone.watched = elements.subset(outside);
  return zone;
}

ContactBoundary contact_boundary(const MarchContactZone& zone, const Mesh& mesh,
                                 const ReducedSystem& reduced) {
  ContactBoundary b = contact_boundary(zone.condensed, mesh, reduced);
  const ContactBoundary watched = contact_boundary(zone.watched, mesh, reduced);
  b.watched = watched.B;
  b.watched_gap = watched.geometric_gap;
  b.watched_nodes = watched.nodes;
  return b;
}

VelocityContact velocity_contact(const ContactElements& elements, const ReducedSystem& reduced) {
  VelocityContact c;
  for (int p = 0; p < elements.size(); ++p) {
    c.first_dof.push_back(reduced.contact_node_first_dof(elements.node[p], elements.dim));
    c.normal.emplace_back(elements.normal[p]);
  }
  c.setting = {elements.law, elements.weight};
  return c;
}

} // namespace sig
