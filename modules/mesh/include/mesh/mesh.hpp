#pragma once
// The mesh every stage shares: P1 triangles in 2D with MODULEF reference numbers on boundary
// edges and vertices, and a sub-domain number per triangle. Indices are 0-based in memory; files
// are 1-based (NOPO, gmsh).
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

namespace sig {

/// The most nodes a mesh may have (generators and readers check it before allocating): beyond,
/// a 2D P1 problem no longer fits in the memory of the machines this code runs on.
inline constexpr double max_mesh_nodes = 1e8;

struct BoundaryEdge {
  int a, b; ///< node indices, in the direction of the boundary (domain on the left)
  int ref;  ///< reference number (> 0)
};

struct Mesh {
  std::vector<Eigen::Vector2d> nodes;
  std::vector<std::array<int, 3>> triangles; ///< counter-clockwise
  std::vector<int> subdomain;                ///< per triangle, >= 1
  std::vector<BoundaryEdge> edges;           ///< referenced edges (boundary or interface)
  std::vector<int> vertex_ref;               ///< per node, 0 = none

  int num_nodes() const { return static_cast<int>(nodes.size()); }
  int num_triangles() const { return static_cast<int>(triangles.size()); }

  /// Nodes carrying `ref`: the end points of edges with that reference and the vertices whose
  /// own reference is `ref`; sorted, without repetition.
  std::vector<int> nodes_with_ref(int ref) const;
  /// Edges with reference `ref`, in storage order.
  std::vector<BoundaryEdge> edges_with_ref(int ref) const;
  /// Every reference number used on edges or vertices, sorted.
  std::vector<int> references() const;
  /// Every sub-domain number, sorted.
  std::vector<int> subdomains() const;
};

/// Twice the signed area of triangle t (positive when counter-clockwise).
double signed_double_area(const Mesh& mesh, int t);

/// The diagonal of the mesh's bounding box: the length its other lengths are measured against
/// (core/ranges.hpp: gaps, weights, displacements).
double diameter(const Mesh& mesh);

/// Throw sig::Error naming `source` and the offending item if a triangle is inverted or
/// degenerate, a node is used by no triangle, an index is out of range, or a sub-domain < 1.
void check_mesh(const Mesh& mesh, const std::string& source);

} // namespace sig
