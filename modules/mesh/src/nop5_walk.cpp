#include "nop5_walk.hpp"

#include "core/error.hpp"
#include "core/log.hpp"
#include "mesh/topology.hpp"

#include <cstdlib>
#include <limits>
#include <ostream>
#include <sstream>
#include <unordered_map>

namespace sig {
namespace {

/// Where an element of NOP5 starts, for messages: "FILE: NOP5 element E (word K)", written only
/// when a message is (a string per element costs more than the whole walk).
struct ElementAt {
  const std::string& file;
  std::int64_t element;
  std::size_t word;
};

std::ostream& operator<<(std::ostream& out, const ElementAt& at) {
  return out << at.file << ": NOP5 element " << at.element << " (word " << at.word << ")";
}

std::string text(const ElementAt& at) {
  std::ostringstream out;
  out << at;
  return out.str();
}

struct ElementShape {
  const char* name;
  int vertices, edges, faces;
};

ElementShape shape_of(std::int64_t ncge, int ndim, const ElementAt& where) {
  if (ndim == 3) {
    if (ncge == 5) return {"tetrahedron", 4, 6, 4};
    throw Error(text(where) + ": element type NCGE = " + std::to_string(ncge) +
                " is not read in a 3D mesh (NDIM = 3): the model is P1 tetrahedra (NCGE = 5)");
  }
  switch (ncge) {
  case 1:
    return {"point", 1, 0, 0};
  case 2:
    return {"segment", 2, 1, 0};
  case 3:
    return {"triangle", 3, 3, 0};
  case 4:
    return {"quadrilateral", 4, 4, 0};
  default:
    throw Error(text(where) + ": element type NCGE = " + std::to_string(ncge) +
                " is not a 2D element (1 point, 2 segment, 3 triangle, 4 quadrilateral)");
  }
}

/// A reference word: its absolute value, which must be an int.
int reference(std::int64_t ref, const ElementAt& where) {
  SIG_VERIFY(ref >= -std::numeric_limits<int>::max() && ref <= std::numeric_limits<int>::max(),
             where << ": reference " << ref << " is out of range");
  return static_cast<int>(ref < 0 ? -ref : ref);
}

/// Builds the Mesh while NOP5 is walked: references checked for consistency, edges kept once.
class MeshBuilder {
public:
  MeshBuilder(std::vector<double> coordinates, int np, int ndim, std::int64_t elements) {
    mesh.dim = ndim;
    mesh.nodes.reserve(np);
    mesh.cells.reserve(elements);
    mesh.subdomain.reserve(elements);
    for (int i = 0; i < np; ++i)
      mesh.nodes.push_back(
          ndim == 3 ? Point(coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2])
                    : Point(coordinates[2 * i], coordinates[2 * i + 1]));
    mesh.vertex_ref.assign(np, 0);
  }

  void vertex_ref(int v, std::int64_t ref, const ElementAt& where) {
    const int r = reference(ref, where);
    if (r == 0) return;
    SIG_VERIFY(mesh.vertex_ref[v] == 0 || mesh.vertex_ref[v] == r,
               where << ": vertex " << v + 1 << " has reference " << r << " here but "
                     << mesh.vertex_ref[v] << " in an earlier element");
    mesh.vertex_ref[v] = r;
  }

  /// Edge (a, b) with reference `ref`, in this direction, kept once.
  void edge_ref(int a, int b, std::int64_t ref, const ElementAt& where) {
    const int r = reference(ref, where);
    if (r == 0) return;
    const auto [it, fresh] = edge_refs_.emplace(edge_key(a, b), r);
    SIG_VERIFY(it->second == r, where << ": edge " << a + 1 << "-" << b + 1 << " has reference "
                                      << r << " here but " << it->second
                                      << " in an earlier element");
    if (fresh) mesh.facets.push_back({{a, b}, r});
  }

  /// Triangle with the references of its sides (v0,v1), (v1,v2), (v2,v0); made
  /// counter-clockwise, the sides keeping the direction they have in it.
  void triangle(std::array<int, 3> v, std::array<std::int64_t, 3> side_ref, int subdomain,
                long element, const ElementAt& where) {
    mesh.cells.push_back(v);
    mesh.subdomain.push_back(subdomain);
    const bool clockwise = signed_double_area(mesh, mesh.num_cells() - 1) < 0;
    if (clockwise) {
      std::swap(mesh.cells.back()[1], mesh.cells.back()[2]);
      flipped.push_back(element);
    }
    for (int j = 0; j < 3; ++j) {
      const int a = v[j], b = v[(j + 1) % 3];
      clockwise ? edge_ref(b, a, side_ref[j], where) : edge_ref(a, b, side_ref[j], where);
    }
  }

  /// Tetrahedron with the references of its faces in MODULEF's local numbering
  /// (outward_facets, topology.cpp), made positively oriented; the faces are oriented outward
  /// once every tetrahedron is known (orient_facets).
  void tetrahedron(const Simplex& v, const std::array<std::int64_t, 4>& face_ref, int subdomain,
                   long element, const ElementAt& where) {
    const OutwardFacets faces = outward_facet_array(v);
    for (int j = 0; j < 4; ++j) {
      const int r = reference(face_ref[j], where);
      if (r == 0) continue;
      const auto [it, fresh] = face_refs_.emplace(facet_key(faces.facet[j]), r);
      SIG_VERIFY(it->second == r, where << ": face " << j + 1 << " has reference " << r
                                        << " here but " << it->second << " in an earlier element");
      if (fresh) mesh.facets.push_back({faces.facet[j], r});
    }
    mesh.cells.push_back(v);
    mesh.subdomain.push_back(subdomain);
    if (signed_cell_determinant(mesh, mesh.num_cells() - 1) < 0) {
      std::swap(mesh.cells.back()[2], mesh.cells.back()[3]);
      flipped.push_back(element);
    }
  }

  Mesh mesh;
  std::vector<long> flipped; ///< NOP5 elements that were clockwise (left-handed in 3D)

private:
  std::unordered_map<std::uint64_t, int> edge_refs_;
  std::unordered_map<FacetKey, int, FacetKeyHash> face_refs_;
};

} // namespace

/// Walk NOP5 (MODULEF.md section 3.3): NCGE NMAE NDSDE NNO nodes [NPO points] [INING refs].
Mesh walk_nop5(const std::vector<std::int64_t>& nop5, const std::array<std::int64_t, 27>& nop2,
               std::vector<double> coordinates, const std::string& file) {
  const int np = static_cast<int>(nop2[word::NP]);
  const int ndim = static_cast<int>(nop2[word::NDIM]);
  // An element takes at least 7 words of NOP5 (4 of header, 3 vertices): a larger NE is damage,
  // refused before anything is reserved for it.
  SIG_VERIFY(nop2[word::NE] <= static_cast<std::int64_t>(nop5.size() / 7),
             file << ": NOP2: NE = " << nop2[word::NE] << " elements cannot fit in NOP5's "
                  << nop5.size() << " words (at least 7 per element)");
  MeshBuilder build(std::move(coordinates), np, ndim, nop2[word::NE]);
  std::size_t k = 0;
  std::int64_t triangles = 0, quadrilaterals = 0, tetrahedra = 0, edge_refs_dropped = 0;
  std::vector<std::int64_t> vertices; // of one element, reused
  for (std::int64_t e = 1; e <= nop2[word::NE]; ++e) {
    const ElementAt where{file, e, k + 1};
    auto next = [&]() {
      SIG_VERIFY(k < nop5.size(),
                 where << " runs past the end of NOP5 (" << nop5.size() << " words)");
      return nop5[k++];
    };
    const std::int64_t ncge = next(), nmae = next(), ndsde = next(), nno = next();
    const ElementShape shape = shape_of(ncge, ndim, where);
    SIG_VERIFY(nno >= shape.vertices, where << ": " << nno << " nodes for a " << shape.name);
    vertices.clear();
    for (std::int64_t j = 0; j < nno; ++j)
      vertices.push_back(next());
    if (nop2[word::NCOPNP] == 0) { // nodes are not the vertices: the point list follows
      const std::int64_t npo = next();
      SIG_VERIFY(npo == shape.vertices, where << ": " << npo << " points for a " << shape.name);
      vertices.clear();
      for (std::int64_t j = 0; j < npo; ++j)
        vertices.push_back(next());
    }
    vertices.resize(shape.vertices);
    std::array<int, 4> v{};
    for (int j = 0; j < shape.vertices; ++j) {
      SIG_VERIFY(vertices[j] >= 1 && vertices[j] <= np,
                 where << ": vertex " << vertices[j] << " out of range 1.." << np);
      v[j] = static_cast<int>(vertices[j] - 1);
    }
    std::array<std::int64_t, 4> edge{}; // references of local edges j -> j+1
    std::array<std::int64_t, 4> face{}; // references of local faces (tetrahedra)
    if (nmae > 0) {
      const std::int64_t ining = next();
      const int expected = ining == 1   ? shape.faces + shape.edges + shape.vertices
                           : ining == 2 ? shape.edges + shape.vertices
                                        : shape.vertices;
      SIG_VERIFY(ining == 2 || ining == 3 || (ining == 1 && ndim == 3),
                 where << ": INING = " << ining
                       << " is not supported (1 = face, edge and vertex references in 3D, 2 = "
                          "edge and vertex references, 3 = vertex)");
      SIG_VERIFY(nmae == 1 + expected, where << ": NMAE = " << nmae << " but INING = " << ining
                                             << " needs " << 1 + expected);
      if (ining == 1) {
        for (int j = 0; j < shape.faces; ++j)
          face[j] = next();
      }
      if (ining <= 2 && ndim == 3) {
        // A 3D mesh carries references on faces and vertices: an edge's is not kept.
        for (int j = 0; j < shape.edges; ++j)
          edge_refs_dropped += next() != 0;
      } else if (ining == 2) {
        for (int j = 0; j < shape.edges; ++j)
          edge[j] = next();
      }
      for (int j = 0; j < shape.vertices; ++j)
        build.vertex_ref(v[j], next(), where);
    }
    SIG_VERIFY((ndsde >= 1 || ncge < 3) && ndsde <= std::numeric_limits<int>::max(),
               where << ": sub-domain NDSDE = " << ndsde << " (must be >= 1)");
    const int subdomain = static_cast<int>(ndsde);
    if (ncge == 5) {
      build.tetrahedron({v[0], v[1], v[2], v[3]}, face, subdomain, e, where);
      ++tetrahedra;
    } else if (ncge == 3) {
      build.triangle({v[0], v[1], v[2]}, {edge[0], edge[1], edge[2]}, subdomain, e, where);
      ++triangles;
    } else if (ncge == 4) { // split as FreeFem does: (1,2,3) + (3,4,1)
      build.triangle({v[0], v[1], v[2]}, {edge[0], edge[1], 0}, subdomain, e, where);
      build.triangle({v[2], v[3], v[0]}, {edge[2], edge[3], 0}, subdomain, e, where);
      ++quadrilaterals;
    } else if (ncge == 2) {
      build.edge_ref(v[0], v[1], edge[0], where); // oriented below, once the triangles exist
    }
  }
  SIG_VERIFY(k == nop5.size(), file << ": NOP5: the " << nop2[word::NE] << " elements use " << k
                                    << " of its " << nop5.size() << " words");
  SIG_VERIFY(triangles == nop2[word::NTRI] && quadrilaterals == nop2[word::NQUA],
             file << ": NOP2 announces " << nop2[word::NTRI] << " triangles and "
                  << nop2[word::NQUA] << " quadrilaterals, NOP5 holds " << triangles << " and "
                  << quadrilaterals);
  SIG_VERIFY(tetrahedra == nop2[word::NTET], file << ": NOP2 announces " << nop2[word::NTET]
                                                  << " tetrahedra, NOP5 holds " << tetrahedra);
  if (edge_refs_dropped > 0)
    log_warning(file + ": dropped " + std::to_string(edge_refs_dropped) +
                " edge reference(s) of tetrahedra (a 3D mesh keeps face and vertex ones)");
  warn_entities(file, "clockwise NOP5 element(s) (element numbers)", build.flipped, "reoriented");
  Mesh mesh = std::move(build.mesh);
  SIG_VERIFY(orient_facets(mesh) < 0,
             file << ": NOP5: a referenced segment is not a side of any triangle");
  if (ndim == 3 && mesh.cells.empty())
    throw Error(file + ": NOP5 holds no tetrahedron: a 3D mesh (NDIM = 3) is made of them");
  return mesh;
}

} // namespace sig
