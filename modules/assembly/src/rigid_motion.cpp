#include "assembly/rigid_motion.hpp"

#include "core/error.hpp"
#include "mesh/topology.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>
#include <unordered_map>

namespace sig {

namespace {

// The null space is dense in 3 unknowns per part: beyond this many parts (triangles joined by
// single nodes throughout, no mesh of a scene) the analysis is not worth its cost.
constexpr int kMaxParts = 200;
// A motion is free when the held dofs stop it by less than this, relative to the largest hold:
// round-off, far below the weakest true hold (the clamped end of a strip 1e6 times as long as
// it is thick stops its rotation by 1e-12).
constexpr double kNullTolerance = 1e-14;

struct Part {
  std::vector<int> cells, nodes;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double size = 0;
};

int root(std::vector<int>& parent, int i) {
  while (parent[i] != i)
    i = parent[i] = parent[parent[i]];
  return i;
}

/// The parts of the mesh: its triangles joined by their sides.
std::vector<Part> parts_of(const Mesh& mesh) {
  std::vector<int> parent(mesh.num_cells());
  std::iota(parent.begin(), parent.end(), 0);
  std::unordered_map<std::uint64_t, int> first;
  for (int t = 0; t < mesh.num_cells(); ++t)
    for (int j = 0; j < 3; ++j) {
      const auto [it, fresh] =
          first.try_emplace(edge_key(mesh.cells[t][j], mesh.cells[t][(j + 1) % 3]), t);
      if (!fresh) parent[root(parent, t)] = root(parent, it->second);
    }
  std::map<int, int> index;
  std::vector<Part> parts;
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const auto [it, fresh] = index.try_emplace(root(parent, t), static_cast<int>(parts.size()));
    if (fresh) parts.emplace_back();
    parts[it->second].cells.push_back(t);
  }
  for (Part& part : parts) {
    for (int t : part.cells)
      part.nodes.insert(part.nodes.end(), mesh.cells[t].begin(), mesh.cells[t].end());
    std::sort(part.nodes.begin(), part.nodes.end());
    part.nodes.erase(std::unique(part.nodes.begin(), part.nodes.end()), part.nodes.end());
    Eigen::Vector2d low = mesh.nodes[part.nodes.front()], high = low;
    for (int n : part.nodes) {
      part.centre += mesh.nodes[n];
      low = low.cwiseMin(mesh.nodes[n]);
      high = high.cwiseMax(mesh.nodes[n]);
    }
    part.centre /= static_cast<double>(part.nodes.size());
    part.size = std::max((high - low).norm(), 1e-300);
  }
  return parts;
}

/// Displacement component k (0: x1, 1: x2) at x of the part's rigid motion (a, b, c), as a row
/// over (a, b, c): the rotation is scaled by the part's size, so the three are comparable.
Eigen::RowVector3d motion_row(const Part& part, const Eigen::Vector2d& x, int k) {
  const Eigen::Vector2d d = (x - part.centre) / part.size;
  return k == 0 ? Eigen::RowVector3d(1, 0, -d.y()) : Eigen::RowVector3d(0, 1, d.x());
}

std::string point(const Eigen::Vector2d& x) {
  std::ostringstream out;
  out.precision(6);
  out << "(" << x.x() << ", " << x.y() << ")";
  return out.str();
}

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (std::size_t k = 0; k < items.size(); ++k)
    text += (k == 0 ? "" : k + 1 == items.size() ? " and " : ", ") + items[k];
  return text;
}

/// The free motions of a part in words, from an orthonormal basis U (3 x r) of the motions
/// (a, b, c) that nothing holds; `hinges` are the nodes it shares with other parts.
std::string motions_in_words(const Mesh& mesh, const Part& part, const Eigen::MatrixXd& U,
                             const std::vector<int>& hinges) {
  std::vector<std::string> words;
  // The translations: the free motions with c = 0.
  const Eigen::RowVectorXd c = U.row(2);
  Eigen::MatrixXd T = U;
  if (c.norm() > 1e-6) {
    const Eigen::MatrixXd w = Eigen::FullPivLU<Eigen::MatrixXd>(c).kernel();
    T = w.cols() > 0 && w.norm() > 0 ? Eigen::MatrixXd(U * w) : Eigen::MatrixXd(3, 0);
  }
  if (T.cols() >= 2) {
    words = {"the translation along x1", "the translation along x2"};
  } else if (T.cols() == 1) {
    const Eigen::Vector2d t = T.col(0).head<2>().normalized();
    if (std::abs(t.y()) < 1e-6)
      words.push_back("the translation along x1");
    else if (std::abs(t.x()) < 1e-6)
      words.push_back("the translation along x2");
    else
      words.push_back("the translation along " + point(t));
  }
  if (c.norm() > 1e-6) {
    // The free motion nearest to a pure rotation, U U^T e3: its centre is the point it leaves
    // where it is.
    const Eigen::Vector3d v = U * c.transpose();
    Eigen::Vector2d pivot = part.centre + part.size * Eigen::Vector2d(-v.y(), v.x()) / v.z();
    for (double& x : pivot) // round-off, not "(0, -1.1e-16)"
      if (std::abs(x) < 1e-12 * part.size) x = 0;
    std::string rotation = "the rotation about " + point(pivot);
    for (int n : hinges)
      if ((mesh.nodes[n] - pivot).norm() <= 1e-6 * part.size)
        rotation += ", the one node where it meets the rest of the body";
    words.push_back(rotation);
  }
  return joined(words);
}

std::string list(const std::vector<int>& numbers, std::size_t most) {
  std::string text;
  for (std::size_t k = 0; k < numbers.size() && k < most; ++k)
    text += (k ? ", " : "") + std::to_string(numbers[k]);
  if (numbers.size() > most) text += ", ...";
  return text.empty() ? "none" : text;
}

} // namespace

std::vector<FreePart> free_parts(const Mesh& mesh, const std::vector<Hold>& holds) {
  const std::vector<Part> parts = parts_of(mesh);
  const int count = static_cast<int>(parts.size());
  if (count > kMaxParts) return {};
  std::vector<std::vector<int>> parts_at(mesh.nodes.size());
  for (int p = 0; p < count; ++p)
    for (int n : parts[p].nodes)
      parts_at[n].push_back(p);

  // The constraints on the motions (a, b, c) of every part, as A^T A: a hold stops the parts at
  // its node along its direction, a node shared by parts makes their motions there agree.
  Eigen::MatrixXd AtA = Eigen::MatrixXd::Zero(3 * count, 3 * count);
  for (const Hold& hold : holds)
    for (int p : parts_at[hold.node]) {
      const Eigen::Vector2d& x = mesh.nodes[hold.node];
      const Eigen::RowVector3d r =
          hold.along.x() * motion_row(parts[p], x, 0) + hold.along.y() * motion_row(parts[p], x, 1);
      AtA.block<3, 3>(3 * p, 3 * p) += r.transpose() * r;
    }
  std::vector<int> hinges;
  for (std::size_t n = 0; n < parts_at.size(); ++n) {
    if (parts_at[n].size() < 2) continue;
    hinges.push_back(static_cast<int>(n));
    const int p = parts_at[n].front();
    for (std::size_t i = 1; i < parts_at[n].size(); ++i)
      for (int k = 0; k < 2; ++k) {
        const int q = parts_at[n][i];
        const Eigen::RowVector3d rp = motion_row(parts[p], mesh.nodes[n], k);
        const Eigen::RowVector3d rq = motion_row(parts[q], mesh.nodes[n], k);
        AtA.block<3, 3>(3 * p, 3 * p) += rp.transpose() * rp;
        AtA.block<3, 3>(3 * q, 3 * q) += rq.transpose() * rq;
        AtA.block<3, 3>(3 * p, 3 * q) -= rp.transpose() * rq;
        AtA.block<3, 3>(3 * q, 3 * p) -= rq.transpose() * rp;
      }
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(AtA);
  const double tolerance = kNullTolerance * std::max(1.0, eigen.eigenvalues().maxCoeff());
  std::vector<int> null;
  for (int k = 0; k < 3 * count; ++k)
    if (eigen.eigenvalues()(k) <= tolerance) null.push_back(k);
  if (null.empty()) return {};
  Eigen::MatrixXd N(3 * count, static_cast<Eigen::Index>(null.size()));
  for (std::size_t k = 0; k < null.size(); ++k)
    N.col(static_cast<Eigen::Index>(k)) = eigen.eigenvectors().col(null[k]);

  std::vector<FreePart> result;
  for (int p = 0; p < count; ++p) {
    // The part's share of the free motions: its own motions that nothing holds.
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(N.middleRows(3 * p, 3), Eigen::ComputeThinU);
    Eigen::Index rank = 0;
    while (rank < svd.singularValues().size() && svd.singularValues()(rank) > 1e-6)
      ++rank;
    if (rank == 0) continue;
    const Part& part = parts[p];
    FreePart free;
    free.whole_body = count == 1;
    free.nodes = part.nodes;
    free.centre = part.centre;
    for (int t : part.cells)
      free.subdomains.push_back(mesh.subdomain[t]);
    for (const Facet& e : mesh.facets)
      if (std::binary_search(part.nodes.begin(), part.nodes.end(), e.node[0]) &&
          std::binary_search(part.nodes.begin(), part.nodes.end(), e.node[1]))
        free.references.push_back(e.ref);
    for (int n : part.nodes)
      if (mesh.vertex_ref[n] != 0) free.references.push_back(mesh.vertex_ref[n]);
    for (std::vector<int>* v : {&free.subdomains, &free.references}) {
      std::sort(v->begin(), v->end());
      v->erase(std::unique(v->begin(), v->end()), v->end());
    }
    free.motions = motions_in_words(mesh, part, svd.matrixU().leftCols(rank), hinges);
    result.push_back(std::move(free));
  }
  return result;
}

std::string describe(const FreePart& part) {
  if (part.whole_body) return "the body is free to move: nothing holds " + part.motions;
  std::vector<int> nodes;
  for (int n : part.nodes)
    nodes.push_back(n + 1);
  return "the part of sub-domain" + std::string(part.subdomains.size() > 1 ? "s " : " ") +
         list(part.subdomains, 10) + " (" + std::to_string(part.nodes.size()) +
         " nodes: " + list(nodes, 8) + ", around " + point(part.centre) +
         "; references on it: " + list(part.references, 10) + ") is free to move: nothing holds " +
         part.motions;
}

Holds holds_of(const std::vector<int>& dirichlet_dofs, const std::vector<int>& contact_nodes,
               const std::vector<Eigen::Vector2d>& contact_normals, bool friction) {
  Holds held;
  for (int dof : dirichlet_dofs)
    held.holds.push_back({dof / 2, Eigen::Vector2d::Unit(dof % 2)});
  for (std::size_t p = 0; p < contact_nodes.size(); ++p) {
    const Eigen::Vector2d n = contact_normals[p];
    held.holds.push_back({contact_nodes[p], n});
    if (friction) held.holds.push_back({contact_nodes[p], Eigen::Vector2d(n.y(), -n.x())});
  }
  held.holders = std::to_string(dirichlet_dofs.size()) + " imposed dofs";
  held.holders += contact_nodes.empty()
                      ? ", no CONTACT card"
                      : " and " + std::to_string(contact_nodes.size()) + " contact nodes" +
                            (friction ? "" : ", frictionless: along their normals");
  return held;
}

void verify_rigid_motions_held(const Mesh& mesh, const Holds& held, const std::string& deck) {
  const std::vector<FreePart> parts = free_parts(mesh, held.holds);
  if (parts.empty()) return;
  std::string what = describe(parts.front()) + " (" + held.holders +
                     "), so the static problem has no unique solution; add DIRICHLET cards "
                     "(ux=, uy=) on references that hold " +
                     (parts.front().whole_body ? "the body" : "that part");
  if (parts.size() > 1) what += " (" + std::to_string(parts.size()) + " parts are free)";
  throw InputError(deck, 0, "", what);
}

} // namespace sig
