#pragma once
// The mesh every stage shares: P1 simplices in R^d, d = 2 or 3 (NOPO's NDIM, a property of the
// mesh): triangles in 2D, tetrahedra in 3D, a sub-domain number per cell, MODULEF reference
// numbers on facets (edges in 2D, triangles in 3D) and on vertices. Indices are 0-based in
// memory; files are 1-based (NOPO, gmsh).
//
// One representation for both dimensions, so that a routine generic in d is one code path: a
// node is a Point of d components, a cell a Simplex of d + 1 nodes, a facet one of d nodes, all
// held in place (fixed capacity) so that a 2D mesh costs what it did.
#include <Eigen/Core>
#include <array>
#include <cassert>
#include <initializer_list>
#include <string>
#include <vector>

namespace sig {

/// The most nodes a mesh may have (generators and readers check it before allocating): beyond,
/// a 2D P1 problem no longer fits in the memory of the machines this code runs on.
inline constexpr double max_mesh_nodes = 1e8;

/// A point of R^d, d = 2 or 3: Eigen's vector of the mesh's dimension, at most three components
/// held in place. 2D code reads it as an Eigen::Vector2d, 3D code as a Vector3d, a routine
/// generic in d as Eigen::Matrix<double, d, 1>.
class Point : public Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 3, 1> {
public:
  using Base = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 3, 1>;
  Point() = default;
  Point(double x, double y) : Base(2) { *this << x, y; }
  Point(double x, double y, double z) : Base(3) { *this << x, y, z; }
  template <typename Derived> Point(const Eigen::MatrixBase<Derived>& other) : Base(other) {}
  template <typename Derived> Point& operator=(const Eigen::MatrixBase<Derived>& other) {
    Base::operator=(other);
    return *this;
  }
};

/// The nodes of a P1 simplex: a cell (a triangle in 2D, a tetrahedron in 3D: d + 1 nodes) or a
/// facet (an edge in 2D, a triangle in 3D: d nodes). Unused places hold 0, so that two simplices
/// compare equal when their nodes do.
class Simplex {
public:
  Simplex() = default;
  Simplex(std::initializer_list<int> nodes) : size_(static_cast<int>(nodes.size())) {
    assert(nodes.size() >= 1 && nodes.size() <= 4);
    int j = 0;
    for (int v : nodes)
      node_[j++] = v;
  }
  template <std::size_t N> Simplex(const std::array<int, N>& nodes) : size_(static_cast<int>(N)) {
    static_assert(N >= 1 && N <= 4);
    for (std::size_t j = 0; j < N; ++j)
      node_[j] = nodes[j];
  }
  int size() const { return size_; }
  int& operator[](int j) { return node_[j]; }
  int operator[](int j) const { return node_[j]; }
  int* begin() { return node_.data(); }
  int* end() { return node_.data() + size_; }
  const int* begin() const { return node_.data(); }
  const int* end() const { return node_.data() + size_; }
  bool operator==(const Simplex&) const = default;

private:
  std::array<int, 4> node_{};
  int size_ = 0;
};

/// A referenced facet: an edge in 2D (directed, domain on the left), a triangle in 3D (outward
/// normal by the right-hand rule: (x1 - x0) x (x2 - x0) points out of the domain).
struct Facet {
  Simplex node; ///< node indices
  int ref;      ///< reference number (> 0)
};

struct Mesh {
  int dim = 2;                 ///< NOPO's NDIM: 2 or 3
  std::vector<Point> nodes;    ///< dim components each
  std::vector<Simplex> cells;  ///< dim + 1 nodes, positively oriented (counter-clockwise in 2D)
  std::vector<int> subdomain;  ///< per cell, >= 1
  std::vector<Facet> facets;   ///< referenced facets (boundary or interface)
  std::vector<int> vertex_ref; ///< per node, 0 = none

  int num_nodes() const { return static_cast<int>(nodes.size()); }
  int num_cells() const { return static_cast<int>(cells.size()); }
  /// What a cell is called in messages: "triangle" or "tetrahedron".
  const char* cell_name() const { return dim == 3 ? "tetrahedron" : "triangle"; }
  /// What a facet is called in messages: "edge" or "face".
  const char* facet_name() const { return dim == 3 ? "face" : "edge"; }

  /// Nodes carrying `ref`: the nodes of facets with that reference and the vertices whose own
  /// reference is `ref`; sorted, without repetition.
  std::vector<int> nodes_with_ref(int ref) const;
  /// Facets with reference `ref`, in storage order.
  std::vector<Facet> facets_with_ref(int ref) const;
  /// Every reference number used on facets or vertices, sorted.
  std::vector<int> references() const;
  /// Every sub-domain number, sorted.
  std::vector<int> subdomains() const;
};

/// Twice the signed area of triangle t of a 2D mesh (positive when counter-clockwise).
double signed_double_area(const Mesh& mesh, int t);

/// d! times the signed measure of cell c (twice the area of a triangle, six times the volume of a
/// tetrahedron): the determinant of its edge vectors from its first node, positive when the cell
/// is positively oriented.
double signed_cell_determinant(const Mesh& mesh, int c);

/// The diagonal of the mesh's bounding box: the length its other lengths are measured against
/// (core/ranges.hpp: gaps, weights, displacements).
double diameter(const Mesh& mesh);

/// Throw sig::Error naming `source` and the offending item if a cell is inverted or degenerate,
/// a node is used by no cell, an index is out of range, or a sub-domain < 1.
void check_mesh(const Mesh& mesh, const std::string& source);

/// Whether a reader or a writer runs check_mesh (a second or a third of a second per million
/// cells). `skip` is the caller's word that the mesh is checked elsewhere: it ran check_mesh on
/// this very mesh (sig-mesh writing mesh_from_card's), or runs it on what it makes of it (a
/// generator, after moving gmsh's nodes).
enum class MeshCheck { run, skip };

/// The nodes of a 2D mesh as plane vectors, for the libraries that take positions and never see a
/// mesh (tests/layering).
inline std::vector<Eigen::Vector2d> plane_positions(const Mesh& mesh) {
  assert(mesh.dim == 2);
  return {mesh.nodes.begin(), mesh.nodes.end()};
}

/// The nodes of a mesh of either dimension as the rows of a num_nodes x dim matrix, for the
/// libraries that take positions and never see a mesh (the integrator's equivalent mass matrix).
inline Eigen::MatrixXd node_positions(const Mesh& mesh) {
  Eigen::MatrixXd x(mesh.num_nodes(), mesh.dim);
  for (int i = 0; i < mesh.num_nodes(); ++i)
    x.row(i) = mesh.nodes[static_cast<std::size_t>(i)].transpose();
  return x;
}

/// "(x, y)" or "(x, y, z)", in the stream's default precision: a point or vector in messages.
std::string coordinates(const Point& x);

/// Throw sig::Error naming `stage` and `what` (the card or the part of the model) when `mesh` is
/// not 2D: the parts of the code that are 2D-only say so rather than misread a 3D mesh.
void require_2d(const Mesh& mesh, const std::string& stage, const std::string& what);

} // namespace sig
