#pragma once
// Helpers shared by the mesh tests: the reference files, and an independent
// raw parse of FreeFem .msh files (so NOPO is compared with what FreeFem wrote, not with our
// own .msh reader).
#include "core/error.hpp"
#include "mesh/mesh.hpp"
#include "mesh/topology.hpp"
#include "scratch_folder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>

namespace sig::testing {

inline std::filesystem::path shared_nopo(const std::string& name) {
  return std::filesystem::path(SIG_SHARED_DIR) / "reference" / "nopo" / name;
}
inline std::filesystem::path legacy_mesh(const std::string& name) {
  return std::filesystem::path(SIG_SOURCE_DIR) / "meshes" / "legacy" / name;
}

/// The message of the sig::Error that `read` throws; a test failure if it throws none.
inline std::string error_of(const std::function<void()>& read) {
  try {
    read();
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted";
  return "";
}

/// The sum of the cells' signed measures: the area or the volume of the meshed body.
inline double measure_of(const Mesh& mesh) {
  double sum = 0;
  for (int c = 0; c < mesh.num_cells(); ++c)
    sum += signed_cell_determinant(mesh, c) / (mesh.dim == 3 ? 6 : 2);
  return sum;
}

/// gmsh runs the half_disc and disc generators; their tests are skipped without it.
inline bool have_gmsh() {
  const char* binary = std::getenv("SIG_GMSH");
  const std::string command =
      std::string("command -v ") + (binary ? binary : "gmsh") + " > /dev/null 2>&1";
  return std::system(command.c_str()) == 0;
}

/// What a FreeFem .msh says, 1-based as written.
struct RawFreeFemMsh {
  std::vector<double> x, y;
  std::vector<long> vertex_label;
  std::vector<std::array<long, 3>> cells;
  std::vector<long> region;
  std::map<std::uint64_t, long> edge_label; ///< unordered 0-based pair -> |label|, label != 0
  long nbe = 0;
};

inline RawFreeFemMsh read_raw_freefem(const std::filesystem::path& path) {
  std::ifstream in(path);
  long nv = 0, nt = 0;
  RawFreeFemMsh raw;
  in >> nv >> nt >> raw.nbe;
  for (long i = 0; i < nv; ++i) {
    double x, y;
    long label;
    in >> x >> y >> label;
    raw.x.push_back(x);
    raw.y.push_back(y);
    raw.vertex_label.push_back(label);
  }
  for (long t = 0; t < nt; ++t) {
    std::array<long, 3> tri;
    long region;
    in >> tri[0] >> tri[1] >> tri[2] >> region;
    raw.cells.push_back(tri);
    raw.region.push_back(region);
  }
  for (long e = 0; e < raw.nbe; ++e) {
    long a, b, label;
    in >> a >> b >> label;
    if (label != 0) raw.edge_label[edge_key(a - 1, b - 1)] = std::labs(label);
  }
  EXPECT_TRUE(in) << path;
  return raw;
}

/// The NOPO/.msh correspondence of MODULEF.md section 5.3, for the mesh read from NOPO.
inline void expect_mesh_matches_freefem(const Mesh& mesh, const RawFreeFemMsh& raw,
                                        double tolerance) {
  ASSERT_EQ(mesh.num_nodes(), static_cast<int>(raw.x.size()));
  ASSERT_EQ(mesh.num_cells(), static_cast<int>(raw.cells.size()));
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    EXPECT_NEAR(mesh.nodes[i].x(), raw.x[i], tolerance) << "node " << i + 1;
    EXPECT_NEAR(mesh.nodes[i].y(), raw.y[i], tolerance) << "node " << i + 1;
    EXPECT_EQ(mesh.vertex_ref[i], std::labs(raw.vertex_label[i])) << "node " << i + 1;
  }
  for (int t = 0; t < mesh.num_cells(); ++t) {
    for (int j = 0; j < 3; ++j)
      EXPECT_EQ(mesh.cells[t][j] + 1, raw.cells[t][j]) << "triangle " << t + 1;
    EXPECT_EQ(mesh.subdomain[t], std::max(raw.region[t], 1L)) << "triangle " << t + 1;
  }
  std::map<std::uint64_t, long> edges;
  for (const auto& e : mesh.facets) {
    EXPECT_TRUE(edges.emplace(edge_key(e.node[0], e.node[1]), e.ref).second) << "edge kept twice";
  }
  EXPECT_EQ(edges, raw.edge_label);
}

} // namespace sig::testing
