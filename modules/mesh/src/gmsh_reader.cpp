#include "mesh/gmsh.hpp"

#include "core/error.hpp"
#include "mesh/topology.hpp"
#include "token_reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <sstream>
#include <unordered_map>
#include <utility>

namespace sig {
namespace {

enum GmshType { Line = 1, Triangle = 2, Tetrahedron = 4, PointElement = 15 };

struct GmshElement {
  int type;
  long physical; ///< 0 = none
  std::array<long, 4> nodes;
  int line; ///< in the file, for messages
};

/// What a .msh file holds, before renumbering.
struct GmshContent {
  std::unordered_map<long, int> node_index; ///< gmsh node tag -> position in nodes
  std::vector<Eigen::Vector3d> nodes;
  std::vector<long> node_tags; ///< per position, for messages
  std::vector<int> node_lines; ///< per position, for messages
  std::vector<GmshElement> elements;
  bool has_volume() const {
    return std::any_of(elements.begin(), elements.end(),
                       [](const GmshElement& e) { return e.type == Tetrahedron; });
  }
};

// P1 is the model: the elements of another kind are named, so that the user can remesh.
int nodes_per_element(TokenReader& in, long type) {
  switch (type) {
  case Line:
    return 2;
  case Triangle:
    return 3;
  case Tetrahedron:
    return 4;
  case PointElement:
    return 1;
  case 3:
  case 10:
  case 16:
    in.fail("element type " + std::to_string(type) +
            " is a quadrangle: the model is P1 triangles (mesh with triangles, or "
            "Mesh.SubdivisionAlgorithm = 1 to split them)");
  case 5:
  case 6:
  case 7:
    in.fail("element type " + std::to_string(type) +
            " is a hexahedron, prism or pyramid: the model is P1 tetrahedra (mesh the volume "
            "with tetrahedra, without Recombine)");
  case 8:
  case 9:
  case 11:
  case 20:
  case 21:
  case 22:
  case 23:
  case 24:
  case 25:
  case 29:
    in.fail("element type " + std::to_string(type) +
            " is of second or higher order: the model is P1 (mesh with Mesh.ElementOrder = 1)");
  default:
    in.fail("element type " + std::to_string(type) +
            " is not read: a P1 mesh holds points (15), lines (1), triangles (2) and tetrahedra "
            "(4) only");
  }
}

void add_node(TokenReader& in, GmshContent& content, long tag, double x, double y, double z) {
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
    in.fail("node tag " + std::to_string(tag) + " has a non-finite coordinate");
  const auto [it, fresh] = content.node_index.emplace(tag, static_cast<int>(content.nodes.size()));
  if (!fresh) in.fail("node tag " + std::to_string(tag) + " appears twice");
  content.nodes.emplace_back(x, y, z);
  content.node_tags.push_back(tag);
  content.node_lines.push_back(in.line());
}

/// Reads the numbers of a section as text or as binary words (format file-type 1): int is 4
/// bytes, size_t the header's data size (8), double 8, all little-endian.
class Numbers {
public:
  Numbers(TokenReader& in, bool binary) : in_(in), binary_(binary) {}
  bool binary() const { return binary_; }
  long integer(const char* what) {
    return binary_ ? static_cast<long>(in_.binary<std::int32_t>(what)) : in_.integer();
  }
  long size(const char* what) {
    if (!binary_) return in_.integer();
    const auto n = in_.binary<std::uint64_t>(what);
    if (n > static_cast<std::uint64_t>(std::numeric_limits<long>::max()))
      in_.fail(std::string("binary ") + what + " " + std::to_string(n) + " is out of range");
    return static_cast<long>(n);
  }
  double real(const char* what) {
    if (!binary_) return in_.real();
    const double x = in_.binary<double>(what);
    if (!std::isfinite(x)) in_.fail(std::string("binary ") + what + " is not finite");
    return x;
  }
  /// A count of items taking `text_bytes` (as text) or `binary_bytes` each, checked against
  /// the rest of the file before anything is allocated.
  long count(const std::string& what, std::uint64_t text_bytes, std::uint64_t binary_bytes) {
    if (!binary_) return in_.count(what, text_bytes);
    const long n = size(what.c_str());
    if (n < 0) in_.fail("negative number of " + what);
    return in_.checked_count(static_cast<std::uint64_t>(n), what, binary_bytes);
  }
  /// A count written as text even in a binary file (format 2.2), followed by binary data.
  long text_count(const std::string& what, std::uint64_t text_bytes, std::uint64_t binary_bytes) {
    const long n = in_.count(what, binary_ ? binary_bytes : text_bytes);
    if (binary_) in_.end_of_line();
    return n;
  }
  /// The end of binary data: a line end before $EndSection.
  void end_section(std::string_view end) {
    if (binary_) in_.end_of_line();
    in_.expect(end);
  }

private:
  TokenReader& in_;
  bool binary_;
};

// ---- format 2.2 ---------------------------------------------------------------------------

void read_nodes_v2(TokenReader& in, Numbers& num, GmshContent& content) {
  const long n = num.text_count("nodes", 8, 28); // "t x y z\n" / int + 3 doubles
  for (long i = 0; i < n; ++i) {
    const long tag = num.integer("node tag");
    const double x = num.real("x"), y = num.real("y"), z = num.real("z");
    add_node(in, content, tag, x, y, z);
  }
  num.end_section("$EndNodes");
}

void read_elements_v2(TokenReader& in, Numbers& num, GmshContent& content) {
  const long n = num.text_count("elements", 8, 12);
  if (!num.binary()) {
    for (long i = 0; i < n; ++i) {
      in.integer(); // element tag
      GmshElement element{static_cast<int>(in.integer()), 0, {0, 0, 0, 0}, in.line()};
      const long ntags = in.count("tags", 2);
      for (long k = 0; k < ntags; ++k) {
        const long tag = in.integer();
        if (k == 0) element.physical = tag; // then the elementary entity, partitions ...
      }
      const int nv = nodes_per_element(in, element.type);
      for (int k = 0; k < nv; ++k)
        element.nodes[k] = in.integer();
      content.elements.push_back(element);
    }
  } else {
    // Groups: type, number of elements following, number of tags; then per element its number,
    // its tags and its nodes, all 4-byte ints.
    for (long read = 0; read < n;) {
      const long type = num.integer("element type");
      const long following = num.integer("element count");
      const long ntags = num.integer("tag count");
      const int nv = nodes_per_element(in, type);
      if (following < 1 || following > n - read || ntags < 0 || ntags > 64)
        in.fail("binary element group: " + std::to_string(following) + " elements with " +
                std::to_string(ntags) + " tags, where " + std::to_string(n - read) + " remain");
      in.checked_count(static_cast<std::uint64_t>(following), "elements",
                       static_cast<std::uint64_t>(4 * (1 + ntags + nv)));
      for (long i = 0; i < following; ++i, ++read) {
        num.integer("element number");
        GmshElement element{static_cast<int>(type), 0, {0, 0, 0, 0}, in.line()};
        for (long k = 0; k < ntags; ++k) {
          const long tag = num.integer("element tag");
          if (k == 0) element.physical = tag;
        }
        for (int k = 0; k < nv; ++k)
          element.nodes[k] = num.integer("element node");
        content.elements.push_back(element);
      }
    }
  }
  num.end_section("$EndElements");
}

// ---- format 4.1 ---------------------------------------------------------------------------

using EntityPhysical = std::map<std::pair<long, long>, long>; ///< (dim, tag) -> first physical

void read_entities_v4(Numbers& num, EntityPhysical& physical) {
  std::array<long, 4> counts{};
  for (long& c : counts)
    c = num.count("entities", 8, 36); // a point: tag, x y z, no physical tag
  for (int dim = 0; dim < 4; ++dim) {
    for (long e = 0; e < counts[dim]; ++e) {
      const long tag = num.integer("entity tag");
      for (int k = 0; k < (dim == 0 ? 3 : 6); ++k)
        num.real("entity coordinate"); // point, or bounding box
      const long nphys = num.count("physical tags", 2, 4);
      for (long k = 0; k < nphys; ++k) {
        const long p = num.integer("physical tag");
        if (k == 0) physical[{dim, tag}] = p;
      }
      if (dim > 0) {
        const long nbound = num.count("bounding entities", 2, 4);
        for (long k = 0; k < nbound; ++k)
          num.integer("bounding entity");
      }
    }
  }
  num.end_section("$EndEntities");
}

void read_nodes_v4(TokenReader& in, Numbers& num, GmshContent& content) {
  const long nblocks = num.count("node blocks", 8, 20);
  num.size("total number of nodes");
  num.size("min node tag");
  num.size("max node tag");
  for (long b = 0; b < nblocks; ++b) {
    const long dim = num.integer("entity dimension");
    num.integer("entity tag");
    const long parametric = num.integer("parametric flag");
    if (dim < 0 || dim > 3 || (parametric != 0 && parametric != 1))
      in.fail("node block with dimension " + std::to_string(dim) + " and parametric flag " +
              std::to_string(parametric));
    const long n = num.count("nodes", 8, 32); // tag + x y z
    std::vector<long> tags(static_cast<std::size_t>(n));
    for (long& t : tags)
      t = num.size("node tag");
    for (long i = 0; i < n; ++i) {
      const double x = num.real("x"), y = num.real("y"), z = num.real("z");
      for (long k = 0; k < (parametric ? dim : 0); ++k)
        num.real("parametric coordinate");
      add_node(in, content, tags[i], x, y, z);
    }
  }
  num.end_section("$EndNodes");
}

void read_elements_v4(TokenReader& in, Numbers& num, const EntityPhysical& physical,
                      GmshContent& content) {
  const long nblocks = num.count("element blocks", 8, 20);
  num.size("total number of elements");
  num.size("min element tag");
  num.size("max element tag");
  for (long b = 0; b < nblocks; ++b) {
    const long dim = num.integer("entity dimension");
    const long entity = num.integer("entity tag");
    const long type = num.integer("element type");
    const int nv = nodes_per_element(in, type);
    const long n = num.count("elements", 2 * (1 + nv), 8 * (1 + nv));
    const auto it = physical.find({dim, entity});
    const long phys = it == physical.end() ? 0 : it->second;
    for (long i = 0; i < n; ++i) {
      num.size("element tag");
      GmshElement element{static_cast<int>(type), phys, {0, 0, 0, 0}, in.line()};
      for (int k = 0; k < nv; ++k)
        element.nodes[k] = num.size("element node");
      content.elements.push_back(element);
    }
  }
  num.end_section("$EndElements");
}

// ---- both formats -------------------------------------------------------------------------

GmshContent read_content(TokenReader& in) {
  in.expect("$MeshFormat");
  const std::string version(in.word());
  const long file_type = in.integer();
  const long data_size = in.integer();
  if (file_type != 0 && file_type != 1)
    in.fail("file-type " + std::to_string(file_type) + " is neither 0 (ASCII) nor 1 (binary)");
  const bool binary = file_type == 1;
  if (binary) {
    if (data_size != 8) in.fail("binary data size " + std::to_string(data_size) + " is not 8");
    in.end_of_line();
    if (in.binary<std::int32_t>("endianness word") != 1)
      in.fail("binary .msh written on a big-endian machine (the word after the format line is "
              "not 1): save it as ASCII");
  }
  const bool v2 = version == "2.2" || version == "2.1" || version == "2.0" || version == "2";
  if (!v2 && version != "4.1")
    in.fail("unsupported .msh version " + version + " (2.2 and 4.1 are read)");
  in.expect("$EndMeshFormat");

  GmshContent content;
  EntityPhysical physical;
  Numbers num(in, binary);
  while (!in.at_end()) {
    const std::string section(in.word());
    if (section.empty() || section[0] != '$')
      in.fail("expected a $Section, found '" + section + "'");
    // Format 4.1 binary: the numbers of these sections start on the next line, in binary.
    if (binary && !v2 && (section == "$Nodes" || section == "$Elements" || section == "$Entities"))
      in.end_of_line();
    if (section == "$Nodes") {
      v2 ? read_nodes_v2(in, num, content) : read_nodes_v4(in, num, content);
    } else if (section == "$Elements") {
      v2 ? read_elements_v2(in, num, content) : read_elements_v4(in, num, physical, content);
    } else if (section == "$Entities" && !v2) {
      read_entities_v4(num, physical);
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

// A tag that becomes a reference or a sub-domain number.
int reference_of(TokenReader& in, const GmshElement& element) {
  if (element.physical < 0 || element.physical > std::numeric_limits<int>::max())
    throw InputError(in.file(), element.line, "",
                     "physical tag " + std::to_string(element.physical) + " is out of range");
  return static_cast<int>(element.physical);
}

/// The dimension of the mesh a file holds: 3 if it has tetrahedra; else 2, and then every node
/// must lie in the plane z = 0 (dropping z would solve another body than the file's).
int dimension_of(const TokenReader& in, const GmshContent& content) {
  if (content.has_volume()) return 3;
  for (std::size_t i = 0; i < content.nodes.size(); ++i) {
    const double z = content.nodes[i].z();
    if (z == 0) continue;
    std::ostringstream what;
    what << "node tag " << content.node_tags[i] << " has z = " << z
         << " and the file has no tetrahedra: a surface in space with no volume is no body (a 2D "
            "mesh lies in the plane z = 0, a 3D one is made of tetrahedra; a mesh out of that "
            "plane is refused, not flattened)";
    throw InputError(in.file(), content.node_lines[i], "", what.str());
  }
  return 2;
}

Mesh read_mesh(TokenReader& in, MeshCheck check) {
  const GmshContent content = read_content(in);

  // Cells are the elements of the mesh's dimension (triangles in 2D, tetrahedra in 3D), facets
  // those one dimension below with a physical tag (lines in 2D, triangles in 3D), vertices the
  // points with one; in 3D, lines carry no reference (a reference goes on faces or vertices).
  Mesh mesh;
  mesh.dim = dimension_of(in, content);
  const int cell_type = mesh.dim == 3 ? Tetrahedron : Triangle;
  const int facet_type = mesh.dim == 3 ? Triangle : Line;
  for (const Eigen::Vector3d& x : content.nodes)
    mesh.nodes.push_back(mesh.dim == 3 ? Point(x) : Point(x.x(), x.y()));
  mesh.vertex_ref.assign(mesh.nodes.size(), 0);
  std::vector<int> edge_lines, triangle_lines; // file line of each facet and cell, for messages
  for (const GmshElement& element : content.elements) {
    const int physical = reference_of(in, element);
    if (element.type == cell_type) {
      triangle_lines.push_back(element.line);
      Simplex nodes =
          mesh.dim == 3
              ? Simplex{node_of(in, content, element, 0), node_of(in, content, element, 1),
                        node_of(in, content, element, 2), node_of(in, content, element, 3)}
              : Simplex{node_of(in, content, element, 0), node_of(in, content, element, 1),
                        node_of(in, content, element, 2)};
      mesh.cells.push_back(nodes);
      mesh.subdomain.push_back(physical >= 1 ? physical : 1);
    } else if (element.type == facet_type && physical > 0) {
      mesh.facets.push_back(
          {mesh.dim == 3
               ? Simplex{node_of(in, content, element, 0), node_of(in, content, element, 1),
                         node_of(in, content, element, 2)}
               : Simplex{node_of(in, content, element, 0), node_of(in, content, element, 1)},
           physical});
      edge_lines.push_back(element.line);
    } else if (element.type == PointElement && physical > 0) {
      const int node = node_of(in, content, element, 0);
      int& ref = mesh.vertex_ref[node];
      if (ref != 0 && ref != physical)
        throw InputError(in.file(), element.line, "",
                         "node tag " + std::to_string(content.node_tags[node]) +
                             " carries references " + std::to_string(ref) + " and " +
                             std::to_string(physical) +
                             ": a vertex carries one reference (put its point in one physical "
                             "group)");
      ref = physical;
    }
  }
  if (mesh.cells.empty())
    throw InputError(in.file(), 0, "",
                     "no triangles (gmsh saves only the elements of physical groups when there "
                     "are any: is the surface in a Physical Surface?)");

  orient_cells_of_file(mesh, in.file(), triangle_lines);
  if (const auto [first, second] = side_with_two_references(mesh); second >= 0) {
    if (mesh.dim == 2)
      throw InputError(
          in.file(), edge_lines[second], "",
          "the side from node tag " +
              std::to_string(content.node_tags[mesh.facets[second].node[0]]) + " to node tag " +
              std::to_string(content.node_tags[mesh.facets[second].node[1]]) +
              " carries references " + std::to_string(mesh.facets[first].ref) + " (line " +
              std::to_string(edge_lines[first]) + ") and " +
              std::to_string(mesh.facets[second].ref) +
              ": a side carries one reference (put its line element in one physical group)");
    throw InputError(in.file(), edge_lines[second], "",
                     "the face of this triangle carries references " +
                         std::to_string(mesh.facets[first].ref) + " (line " +
                         std::to_string(edge_lines[first]) + ") and " +
                         std::to_string(mesh.facets[second].ref) +
                         ": a face carries one reference (put its surface in one physical group)");
  }
  if (const int bad = orient_facets(mesh); bad >= 0)
    throw InputError(
        in.file(), edge_lines[bad], "",
        mesh.dim == 2 ? "line element with physical tag " + std::to_string(mesh.facets[bad].ref) +
                            " is not a side of any triangle"
                      : "triangle with physical tag " + std::to_string(mesh.facets[bad].ref) +
                            " is not a face of any tetrahedron: mixed dimensions (a "
                            "surface beside the volume) are not a body; put only "
                            "the volume's boundary in physical surfaces");
  const std::vector<int> renumber = drop_unused_nodes(mesh);
  std::vector<long> dropped;
  for (std::size_t i = 0; i < renumber.size(); ++i)
    if (renumber[i] < 0) dropped.push_back(content.node_tags[i]);
  warn_entities(in.file(), std::string("node(s) that no ") + mesh.cell_name() + " uses (node tags)",
                dropped, "dropped");
  if (check == MeshCheck::run) check_mesh(mesh, in.file());
  return mesh;
}

} // namespace

Mesh read_gmsh(const std::filesystem::path& path, MeshCheck check) {
  TokenReader in(path);
  return read_mesh(in, check);
}

Mesh parse_gmsh(const std::string& name, std::string contents) {
  TokenReader in(name, std::move(contents));
  return read_mesh(in, MeshCheck::run);
}

} // namespace sig
