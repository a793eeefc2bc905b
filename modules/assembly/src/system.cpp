#include "assembly/system.hpp"

#include "assembly/cards.hpp"
#include "assembly/loads.hpp"
#include "assembly/p1.hpp"
#include "assembly/p1_simplex.hpp"
#include "core/datafile.hpp"
#include "core/log.hpp"
#include "material/mili.hpp"
#include "mesh/mesh.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <optional>
#include <sstream>

namespace sig {

namespace {

/// The Voigt matrix of `law` (Hooke, Viscosity) on a body of dimension d: D (2D, the plane mode
/// of the law) or D3.
template <typename Law> Eigen::MatrixXd voigt_matrix(const Law& law, int d) {
  if (d == 3) return law.D3();
  return law.D();
}

/// What an operator gives a sub-domain: its Voigt matrix in the body's dimension, or none (the
/// sub-domain is left out).
using OperatorOf = std::function<std::optional<Eigen::MatrixXd>(const SubdomainMaterial&, int)>;

/// The P1 stiffness of the operator `tensor` gives each sub-domain (sigma = D eps) on the
/// simplices of a mesh of dimension d, the sub-domains where it gives none left out.
template <int d>
Eigen::SparseMatrix<double> assemble_operator(const Mesh& mesh, const MaterialTable& table,
                                              const SparsityPattern& pattern,
                                              const OperatorOf& tensor) {
  std::map<int, std::optional<VoigtMatrix<d>>> of; // once per sub-domain, not per cell
  for (int subdomain : mesh.subdomains())
    if (const std::optional<Eigen::MatrixXd> D = tensor(table.of(subdomain), d))
      of.emplace(subdomain, VoigtMatrix<d>(*D));
    else
      of.emplace(subdomain, std::nullopt);
  Eigen::SparseMatrix<double> K = pattern.zero_matrix();
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const std::optional<VoigtMatrix<d>>& D = of.at(mesh.subdomain[t]);
    if (!D) continue;
    // A 2D body is a plate of the law's thickness; a 3D one has none.
    const double thickness = d == 2 ? table.of(mesh.subdomain[t]).thickness : 1.0;
    pattern.add(K, t, p1_simplex_stiffness<d>(simplex_vertices<d>(mesh, t), *D, thickness));
  }
  return K;
}

Eigen::SparseMatrix<double> assemble_operator(const Mesh& mesh, const MaterialTable& table,
                                              const SparsityPattern& pattern,
                                              const OperatorOf& tensor) {
  return with_dimension(mesh.dim, [&]<int d>(std::integral_constant<int, d>) {
    return assemble_operator<d>(mesh, table, pattern, tensor);
  });
}

} // namespace

Eigen::SparseMatrix<double> assemble_stiffness(const Mesh& mesh, const MaterialTable& table,
                                               const SparsityPattern& pattern) {
  return assemble_operator(mesh, table, pattern, [](const SubdomainMaterial& m, int d) {
    return std::optional<Eigen::MatrixXd>(voigt_matrix(m.hooke, d));
  });
}

Eigen::SparseMatrix<double> assemble_viscosity(const Mesh& mesh, const MaterialTable& table,
                                               const SparsityPattern& pattern) {
  return assemble_operator(mesh, table, pattern,
                           [](const SubdomainMaterial& m, int d) -> std::optional<Eigen::MatrixXd> {
                             if (!m.kelvin_voigt) return std::nullopt;
                             return voigt_matrix(m.kelvin_voigt->viscosity, d);
                           });
}

std::vector<MemoryStiffness> assemble_memory(const Mesh& mesh, const MaterialTable& table,
                                             const SparsityPattern& pattern) {
  // One matrix per distinct decay rate: a step then updates one history per rate.
  std::vector<double> rates;
  for (const auto& [subdomain, term] : table.memory_terms())
    if (std::find(rates.begin(), rates.end(), term.beta) == rates.end()) rates.push_back(term.beta);
  std::vector<MemoryStiffness> memory;
  for (double beta : rates) {
    const auto tensor = [beta](const SubdomainMaterial& m,
                               int d) -> std::optional<Eigen::MatrixXd> {
      if (!m.kelvin_voigt) return std::nullopt;
      Eigen::MatrixXd D = Eigen::MatrixXd::Zero(voigt_size(d), voigt_size(d));
      bool any = false;
      for (const MemoryTerm& term : m.kelvin_voigt->memory)
        if (term.beta == beta) {
          D += voigt_matrix(term.modulus, d);
          any = true;
        }
      return any ? std::optional<Eigen::MatrixXd>(D) : std::nullopt;
    };
    memory.push_back({beta, assemble_operator(mesh, table, pattern, tensor)});
  }
  return memory;
}

Eigen::SparseMatrix<double> assemble_mass(const Mesh& mesh, const MaterialTable& table,
                                          const SparsityPattern& pattern) {
  Eigen::SparseMatrix<double> M = pattern.zero_matrix();
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const SubdomainMaterial& material = table.of(mesh.subdomain[t]);
    if (mesh.dim == 3) {
      pattern.add(M, t,
                  p1_simplex_consistent_mass<3>(p1_measure<3>(simplex_vertices<3>(mesh, t)),
                                                material.density, 1.0));
      continue;
    }
    pattern.add(M, t,
                p1_consistent_mass(p1_area(triangle_vertices(mesh, t)), material.density,
                                   material.thickness));
  }
  return M;
}

Eigen::VectorXd assemble_lumped_mass(const Mesh& mesh, const MaterialTable& table) {
  if (mesh.dim == 3) {
    Eigen::VectorXd m = Eigen::VectorXd::Zero(3 * mesh.num_nodes());
    for (int t = 0; t < mesh.num_cells(); ++t) {
      const SimplexVector<3> me = p1_simplex_lumped_mass<3>(
          p1_measure<3>(simplex_vertices<3>(mesh, t)), table.of(mesh.subdomain[t]).density, 1.0);
      for (int i = 0; i < 4; ++i)
        m.segment<3>(3 * mesh.cells[t][i]) += me.segment<3>(3 * i);
    }
    return m;
  }
  Eigen::VectorXd m = Eigen::VectorXd::Zero(2 * mesh.num_nodes());
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const SubdomainMaterial& material = table.of(mesh.subdomain[t]);
    const Vector6d me =
        p1_lumped_mass(p1_area(triangle_vertices(mesh, t)), material.density, material.thickness);
    for (int i = 0; i < 3; ++i)
      m.segment<2>(2 * mesh.cells[t][i]) += me.segment<2>(2 * i);
  }
  return m;
}

void dirichlet_from_cards(const Mesh& mesh, const Datafile& datafile, std::vector<int>& dofs,
                          Eigen::VectorXd& values) {
  // Each dof's value and the card that gave it: two cards giving one dof two values (where
  // their references meet) contradict each other, and neither may silently win.
  std::map<int, std::pair<double, const Card*>> imposed;
  for (const Card* card : datafile.all("DIRICHLET")) {
    const int d = mesh.dim;
    const char* fields[3] = {"ux", "uy", "uz"};
    if (d == 2 && card->has("uz"))
      card->fail("uz", "the mesh is 2D: a displacement has the components ux and uy");
    const std::vector<int> refs = card_references(*card, mesh, RefSupport::edges_or_vertices);
    if (!card->has("ux") && !card->has("uy") && !card->has("uz"))
      card->fail("ux", d == 3 ? "give ux=, uy=, uz= or some of them" : "give ux=, uy= or both");
    for (int c = 0; c < d; ++c) {
      if (!card->has(fields[c])) continue;
      const double value = card->real(fields[c]);
      for (int ref : refs)
        for (int node : mesh.nodes_with_ref(ref)) {
          const auto [it, fresh] = imposed.try_emplace(d * node + c, value, card);
          if (fresh || it->second.first == value) continue;
          std::ostringstream what;
          what << "gives node " << node + 1 << " (at (" << mesh.nodes[node].x() << ", "
               << mesh.nodes[node].y()
               << (d == 3 ? ", " + std::to_string(mesh.nodes[node].z()) : "") << "), reference "
               << ref << ") " << fields[c] << " = " << value << ", but the DIRICHLET card of line "
               << it->second.second->line << " gives it " << it->second.first
               << ": one displacement cannot take two values (give the node one of them)";
          card->fail(fields[c], what.str());
        }
    }
  }
  dofs.clear();
  values.resize(static_cast<Eigen::Index>(imposed.size()));
  for (const auto& [dof, value] : imposed) {
    values(static_cast<Eigen::Index>(dofs.size())) = value.first;
    dofs.push_back(dof);
  }
}

const Card* dirichlet_card_of(const Mesh& mesh, const Datafile& datafile, int dof) {
  const int node = dof / mesh.dim, component = dof % mesh.dim;
  const char* fields[3] = {"ux", "uy", "uz"};
  for (const Card* card : datafile.all("DIRICHLET")) {
    if (!card->has(fields[component])) continue;
    for (int ref : card_references(*card, mesh, RefSupport::edges_or_vertices)) {
      const std::vector<int> nodes = mesh.nodes_with_ref(ref);
      if (std::find(nodes.begin(), nodes.end(), node) != nodes.end()) return card;
    }
  }
  return nullptr;
}

Eigen::VectorXd LinearSystem::load_at(double t) const {
  if (time_loads.empty()) return f;
  return f + time_loads.change(t, num_dofs());
}

namespace {

/// The cells with a node of the rows `owned` marks, in the mesh's order (the nodes all kept):
/// every cell that adds to those rows, so that each of their entries sums the same terms in the
/// same order as on the whole mesh.
Mesh cells_of_rows(const Mesh& mesh, const std::vector<char>& owned) {
  Mesh part;
  part.dim = mesh.dim;
  part.nodes = mesh.nodes;
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const Simplex& cell = mesh.cells[static_cast<std::size_t>(t)];
    if (std::none_of(cell.begin(), cell.end(), [&](int node) {
          return owned[static_cast<std::size_t>(mesh.dim * node)] != 0;
        }))
      continue;
    part.cells.push_back(cell);
    part.subdomain.push_back(mesh.subdomain[static_cast<std::size_t>(t)]);
  }
  return part;
}

/// The rows `owned` marks of A with every entry its pattern gives them (explicit zeros kept),
/// the other rows empty.
Eigen::SparseMatrix<double> rows_only(const Eigen::SparseMatrix<double>& A,
                                      const std::vector<char>& owned) {
  if (A.size() == 0) return A;
  Eigen::SparseMatrix<double, Eigen::RowMajor> rows = A;
  rows.prune([&](Eigen::Index row, Eigen::Index, double) {
    return owned[static_cast<std::size_t>(row)] != 0;
  });
  return Eigen::SparseMatrix<double>(rows);
}

} // namespace

LinearSystem assemble_system(const Mesh& mesh, const MaterialTable& table, const Datafile& datafile,
                             const std::vector<char>* owned) {
  const Stopwatch clock;
  LinearSystem system;
  // The matrices of the rows held on the cells that reach them; the vectors of the whole body.
  const Mesh part = owned != nullptr ? cells_of_rows(mesh, *owned) : Mesh{};
  const Mesh& cells = owned != nullptr ? part : mesh;
  const SparsityPattern pattern(cells);
  system.K = assemble_stiffness(cells, table, pattern);
  if (table.has_mass()) system.M = assemble_mass(cells, table, pattern);
  system.M_lumped = assemble_lumped_mass(mesh, table);
  if (table.has_viscosity()) {
    system.V = assemble_viscosity(cells, table, pattern);
    system.memory = assemble_memory(cells, table, pattern);
  }
  if (owned != nullptr) {
    system.K = rows_only(system.K, *owned);
    system.M = rows_only(system.M, *owned);
    system.V = rows_only(system.V, *owned);
    for (MemoryStiffness& term : system.memory)
      term.K = rows_only(term.K, *owned);
  }
  system.f = mesh.dim == 3 ? assemble_loads_3d(mesh, datafile, &system.time_loads)
                           : assemble_loads(mesh, table, datafile, &system.time_loads);
  dirichlet_from_cards(mesh, datafile, system.dirichlet_dofs, system.dirichlet_values);
  system.assemble_seconds = clock.seconds();
  return system;
}

} // namespace sig
