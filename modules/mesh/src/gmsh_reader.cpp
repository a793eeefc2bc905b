#include "mesh/gmsh.hpp"

#include "core/error.hpp"
#include "mesh/topology.hpp"
#include "token_reader.hpp"

#include <array>
#include <map>
#include <unordered_map>
#include <utility>

namespace sig {
namespace {

enum GmshType { Line = 1, Triangle = 2, Point = 15 };

struct GmshElement {
  int type;
  long physical; ///< 0 = none
  std::array<long, 3> nodes;
  int line; ///< in the file, for messages
};

/// What a .msh file holds, before renumbering.
struct GmshContent {
  std::unordered_map<long, int> node_index; ///< gmsh node tag -> position in nodes
  std::vector<Eigen::Vector2d> nodes;
  std::vector<GmshElement> elements;
};

int nodes_per_element(TokenReader& in, long type) {
  switch (type) {
  case Line:
    return 2;
  case Triangle:
    return 3;
  case Point:
    return 1;
  default:
    in.fail("element type " + std::to_string(type) +
            " is not supported: P1 meshes hold points (15), lines (1) and triangles (2) only");
  }
}

void add_node(TokenReader& in, GmshContent& content, long tag, double x, double y) {
  const auto [it, fresh] = content.node_index.emplace(tag, static_cast<int>(content.nodes.size()));
  if (!fresh) in.fail("node tag " + std::to_string(tag) + " appears twice");
  content.nodes.emplace_back(x, y);
}

long count(TokenReader& in, const char* what) {
  const long n = in.integer();
  if (n < 0) in.fail(std::string("negative number of ") + what);
  return n;
}

// ---- format 2.2 ---------------------------------------------------------------------------

void read_nodes_v2(TokenReader& in, GmshContent& content) {
  const long n = count(in, "nodes");
  for (long i = 0; i < n; ++i) {
    const long tag = in.integer();
    const double x = in.real(), y = in.real();
    in.real(); // z
    add_node(in, content, tag, x, y);
  }
  in.expect("$EndNodes");
}

void read_elements_v2(TokenReader& in, GmshContent& content) {
  const long n = count(in, "elements");
  for (long i = 0; i < n; ++i) {
    in.integer(); // element tag
    GmshElement element{static_cast<int>(in.integer()), 0, {0, 0, 0}, in.line()};
    const long ntags = count(in, "tags");
    for (long k = 0; k < ntags; ++k) {
      const long tag = in.integer();
      if (k == 0) element.physical = tag; // then the elementary entity, partitions ...
    }
    const int nv = nodes_per_element(in, element.type);
    for (int k = 0; k < nv; ++k)
      element.nodes[k] = in.integer();
    content.elements.push_back(element);
  }
  in.expect("$EndElements");
}

// ---- format 4.1 ---------------------------------------------------------------------------

using EntityPhysical = std::map<std::pair<long, long>, long>; ///< (dim, tag) -> first physical

void read_entities_v4(TokenReader& in, EntityPhysical& physical) {
  std::array<long, 4> counts{};
  for (long& c : counts)
    c = count(in, "entities");
  for (int dim = 0; dim < 4; ++dim) {
    for (long e = 0; e < counts[dim]; ++e) {
      const long tag = in.integer();
      for (int k = 0; k < (dim == 0 ? 3 : 6); ++k)
        in.real(); // point, or bounding box
      const long nphys = count(in, "physical tags");
      for (long k = 0; k < nphys; ++k) {
        const long p = in.integer();
        if (k == 0) physical[{dim, tag}] = p;
      }
      if (dim > 0) {
        const long nbound = count(in, "bounding entities");
        for (long k = 0; k < nbound; ++k)
          in.integer();
      }
    }
  }
  in.expect("$EndEntities");
}

void read_nodes_v4(TokenReader& in, GmshContent& content) {
  const long nblocks = count(in, "node blocks");
  in.integer(); // total number of nodes
  in.integer(); // min tag
  in.integer(); // max tag
  for (long b = 0; b < nblocks; ++b) {
    const long dim = in.integer();
    in.integer(); // entity tag
    const long parametric = in.integer();
    const long n = count(in, "nodes");
    std::vector<long> tags(n);
    for (long& t : tags)
      t = in.integer();
    for (long i = 0; i < n; ++i) {
      const double x = in.real(), y = in.real();
      in.real(); // z
      for (long k = 0; k < (parametric ? dim : 0); ++k)
        in.real();
      add_node(in, content, tags[i], x, y);
    }
  }
  in.expect("$EndNodes");
}

void read_elements_v4(TokenReader& in, const EntityPhysical& physical, GmshContent& content) {
  const long nblocks = count(in, "element blocks");
  in.integer(); // total number of elements
  in.integer(); // min tag
  in.integer(); // max tag
  for (long b = 0; b < nblocks; ++b) {
    const long dim = in.integer();
    const long entity = in.integer();
    const long type = in.integer();
    const int nv = nodes_per_element(in, type);
    const long n = count(in, "elements");
    const auto it = physical.find({dim, entity});
    const long phys = it == physical.end() ? 0 : it->second;
    for (long i = 0; i < n; ++i) {
      in.integer(); // element tag
      GmshElement element{static_cast<int>(type), phys, {0, 0, 0}, in.line()};
      for (int k = 0; k < nv; ++k)
        element.nodes[k] = in.integer();
      content.elements.push_back(element);
    }
  }
  in.expect("$EndElements");
}

// ---- both formats -------------------------------------------------------------------------

GmshContent read_content(TokenReader& in) {
  in.expect("$MeshFormat");
  const std::string version(in.word());
  const long file_type = in.integer();
  in.integer(); // data size
  if (file_type != 0) in.fail("binary .msh files are not supported: save them as ASCII");
  const bool v2 = version.rfind("2.", 0) == 0;
  if (!v2 && version != "4.1")
    in.fail("unsupported .msh version " + version + " (2.2 and 4.1 are read)");
  in.expect("$EndMeshFormat");

  GmshContent content;
  EntityPhysical physical;
  while (!in.at_end()) {
    const std::string section(in.word());
    if (section.empty() || section[0] != '$')
      in.fail("expected a $Section, found '" + section + "'");
    if (section == "$Nodes") {
      v2 ? read_nodes_v2(in, content) : read_nodes_v4(in, content);
    } else if (section == "$Elements") {
      v2 ? read_elements_v2(in, content) : read_elements_v4(in, physical, content);
    } else if (section == "$Entities" && !v2) {
      read_entities_v4(in, physical);
    } else {
      in.skip_past("$End" + section.substr(1)); // $PhysicalNames, $Periodic, ...
    }
  }
  return content;
}

int node_of(TokenReader& in, const GmshContent& content, const GmshElement& element, int k) {
  const auto it = content.node_index.find(element.nodes[k]);
  if (it == content.node_index.end())
    throw InputError(in.file(), element.line, "",
                     "node tag " + std::to_string(element.nodes[k]) + " is not in $Nodes");
  return it->second;
}

} // namespace

Mesh read_gmsh(const std::filesystem::path& path) {
  TokenReader in(path);
  const GmshContent content = read_content(in);

  Mesh mesh;
  mesh.nodes = content.nodes;
  mesh.vertex_ref.assign(mesh.nodes.size(), 0);
  std::vector<int> edge_lines, triangle_lines; // file line of each, for messages
  for (const GmshElement& element : content.elements) {
    if (element.type == Triangle) {
      triangle_lines.push_back(element.line);
      mesh.triangles.push_back({node_of(in, content, element, 0), node_of(in, content, element, 1),
                                node_of(in, content, element, 2)});
      mesh.subdomain.push_back(element.physical >= 1 ? static_cast<int>(element.physical) : 1);
    } else if (element.type == Line && element.physical > 0) {
      mesh.edges.push_back({node_of(in, content, element, 0), node_of(in, content, element, 1),
                            static_cast<int>(element.physical)});
      edge_lines.push_back(element.line);
    } else if (element.type == Point && element.physical > 0) {
      int& ref = mesh.vertex_ref[node_of(in, content, element, 0)];
      if (ref == 0) ref = static_cast<int>(element.physical);
    }
  }
  if (mesh.triangles.empty())
    throw InputError(in.file(), 0, "",
                     "no triangles (gmsh saves only the elements of physical groups when there "
                     "are any: is the surface in a Physical Surface?)");

  if (const int flat = orient_counter_clockwise(mesh); flat >= 0)
    throw InputError(in.file(), triangle_lines[flat], "",
                     "triangle " + std::to_string(flat + 1) +
                         " (1-based) is degenerate: its three nodes are aligned (zero area)");
  if (const int bad = orient_boundary_edges(mesh); bad >= 0)
    throw InputError(in.file(), edge_lines[bad], "",
                     "line element with physical tag " + std::to_string(mesh.edges[bad].ref) +
                         " is not a side of any triangle");
  drop_unused_nodes(mesh);
  check_mesh(mesh, in.file());
  return mesh;
}

} // namespace sig
