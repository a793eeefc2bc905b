#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/phase_times.hpp"
#include "core/provenance.hpp"
#include "core/stage.hpp"
#include "fortran_records.hpp"
#include "mesh/nopo.hpp"
#include "mesh/topology.hpp"

#include <algorithm>
#include <bit>
#include <cstdlib>
#include <limits>
#include <type_traits>
#include <unordered_map>

namespace sig {
namespace {

/// NOP5 as FreeFem's Write_nop5 builds it (MODULEF.md section 5.2), and the counts NOP2 needs.
struct Nop5 {
  std::vector<std::int64_t> words;
  std::int64_t elements_with_refs = 0; // NEF
  std::int64_t largest_span = 0;       // LPGDN = max(max - min node) + 1
  std::int64_t largest_ref = 0;        // NDSR
};

Nop5 build_nop5(const Mesh& mesh) {
  std::unordered_map<std::uint64_t, int> edge_ref;
  for (const auto& e : mesh.facets)
    edge_ref.emplace(edge_key(e.node[0], e.node[1]), std::abs(e.ref));
  const std::vector<char> on = nodes_on_facets(mesh); // a side off them has no reference
  Nop5 nop5;
  nop5.words.reserve(8 * mesh.cells.size());
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const auto& tri = mesh.cells[t];
    std::array<std::int64_t, 3> e{}, v{};
    for (int j = 0; j < 3; ++j) {
      const int a = tri[j], b = tri[(j + 1) % 3];
      const auto it = on[a] && on[b] ? edge_ref.find(edge_key(a, b)) : edge_ref.end();
      e[j] = it == edge_ref.end() ? 0 : it->second;
      v[j] = std::abs(mesh.vertex_ref[tri[j]]);
    }
    const bool edges = e[0] || e[1] || e[2];
    const bool vertices = v[0] || v[1] || v[2];
    const std::int64_t nmae = edges ? 7 : vertices ? 4 : 0;
    nop5.words.insert(nop5.words.end(), {3, nmae, std::max(mesh.subdomain[t], 1), 3, tri[0] + 1,
                                         tri[1] + 1, tri[2] + 1});
    if (edges) {
      nop5.words.insert(nop5.words.end(), {2, e[0], e[1], e[2]});
      nop5.largest_ref = std::max({nop5.largest_ref, e[0], e[1], e[2]});
    } else if (vertices) {
      nop5.words.push_back(3);
    }
    if (nmae > 0) {
      nop5.words.insert(nop5.words.end(), v.begin(), v.end());
      nop5.largest_ref = std::max({nop5.largest_ref, v[0], v[1], v[2]});
      ++nop5.elements_with_refs;
    }
    const auto [lo, hi] = std::minmax({tri[0], tri[1], tri[2]});
    nop5.largest_span = std::max<std::int64_t>(nop5.largest_span, hi - lo + 1);
  }
  return nop5;
}

/// NOP5 of a tetrahedral mesh (NCGE = 5). The references of a tetrahedron follow MODULEF's
/// INING (MODULEF.md section 3.3): INING = 1 with its 4 face references in MODULEF's local face
/// numbering (outward_facets, topology.cpp), its 6 edge references (0: edges carry none here)
/// and its 4 vertex references; INING = 3 with the vertex references alone when no face of it
/// carries one; nothing when none does.
Nop5 build_nop5_tetrahedra(const Mesh& mesh) {
  std::unordered_map<FacetKey, int, FacetKeyHash> face_ref;
  for (const auto& f : mesh.facets)
    face_ref.emplace(facet_key(f.node), std::abs(f.ref));
  const std::vector<char> on = nodes_on_facets(mesh); // a face off them has no reference
  Nop5 nop5;
  nop5.words.reserve(9 * mesh.cells.size());
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const auto& tet = mesh.cells[t];
    std::array<std::int64_t, 4> f{}, v{};
    const OutwardFacets faces = outward_facet_array(tet);
    for (int j = 0; j < 4; ++j) {
      const auto it = all_marked(on, faces.facet[j]) ? face_ref.find(facet_key(faces.facet[j]))
                                                     : face_ref.end();
      f[j] = it == face_ref.end() ? 0 : it->second;
      v[j] = std::abs(mesh.vertex_ref[tet[j]]);
    }
    const bool faced = f[0] || f[1] || f[2] || f[3];
    const bool vertices = v[0] || v[1] || v[2] || v[3];
    const std::int64_t nmae = faced ? 15 : vertices ? 5 : 0;
    nop5.words.insert(nop5.words.end(), {5, nmae, std::max(mesh.subdomain[t], 1), 4, tet[0] + 1,
                                         tet[1] + 1, tet[2] + 1, tet[3] + 1});
    if (faced) {
      nop5.words.push_back(1);
      nop5.words.insert(nop5.words.end(), f.begin(), f.end());
      nop5.words.insert(nop5.words.end(), 6, 0);
      nop5.largest_ref = std::max({nop5.largest_ref, f[0], f[1], f[2], f[3]});
    } else if (vertices) {
      nop5.words.push_back(3);
    }
    if (nmae > 0) {
      nop5.words.insert(nop5.words.end(), v.begin(), v.end());
      nop5.largest_ref = std::max({nop5.largest_ref, v[0], v[1], v[2], v[3]});
      ++nop5.elements_with_refs;
    }
    const auto [lo, hi] = std::minmax({tet[0], tet[1], tet[2], tet[3]});
    nop5.largest_span = std::max<std::int64_t>(nop5.largest_span, hi - lo + 1);
  }
  return nop5;
}

/// Append `values` as words of `bytes` bytes: on a little-endian host the 8-byte little-endian
/// words of our case.nopo are the values' own bytes.
template <class T>
void put_words(std::string& out, const std::vector<T>& values, int bytes, const WordCodec& codec) {
  if constexpr (sizeof(T) == 8) {
    if (!codec.big_endian && bytes == 8 && std::endian::native == std::endian::little) {
      out.append(reinterpret_cast<const char*>(values.data()), values.size() * 8);
      return;
    }
  }
  out.reserve(out.size() + values.size() * bytes);
  for (const T x : values) {
    if constexpr (std::is_floating_point_v<T>)
      codec.put_real(out, x, bytes);
    else
      codec.put_int(out, x, bytes);
  }
}

/// Text packed 4 characters per integer word, in the first 4 bytes of the word in file order
/// (FreeFem's union of char[4] and long), blank padded to `words` words.
void put_text(std::string& out, const std::string& text, int words, int int_bytes) {
  std::string padded = text.substr(0, 4 * words);
  padded.resize(4 * words, ' ');
  for (int k = 0; k < words; ++k) {
    out.append(padded, 4 * k, 4);
    out.append(int_bytes - 4, '\0');
  }
}

} // namespace

NopoLayout nopo_layout(NopoVariant variant) {
  switch (variant) {
  case NopoVariant::ff64:
    return {8, 8, 4, false};
  case NopoVariant::i4r4:
    return {4, 4, 4, false};
  case NopoVariant::i8r8:
    return {4, 8, 8, false};
  }
  return {};
}

namespace {

/// The bytes of a NOPO file and its fingerprint (mesh/nopo.hpp).
struct EncodedNopo {
  std::string bytes;
  std::uint64_t fingerprint = 0;
};

EncodedNopo encode(const Mesh& mesh, NopoVariant variant, const NopoWriteOptions& options) {
  if (options.check == MeshCheck::run) check_mesh(mesh, "NOPO writer");
  const NopoLayout layout = nopo_layout(variant);
  const int wi = layout.int_bytes;
  const WordCodec codec{options.big_endian};
  const bool tetrahedra = mesh.dim == 3;
  const Nop5 nop5 = tetrahedra ? build_nop5_tetrahedra(mesh) : build_nop5(mesh);
  const std::int64_t nv = mesh.num_nodes(), nt = mesh.num_cells();
  const std::int64_t ntri = tetrahedra ? 0 : nt, ntet = tetrahedra ? nt : 0;
  const std::int64_t l4 = mesh.dim * nv, l5 = static_cast<std::int64_t>(nop5.words.size());
  SIG_VERIFY(wi == 8 || l5 <= std::numeric_limits<std::int32_t>::max(),
             "NOPO: the mesh is too large for 4-byte words");
  const int subdomain_max =
      mesh.subdomain.empty() ? 1 : *std::max_element(mesh.subdomain.begin(), mesh.subdomain.end());

  const std::int64_t ndsr = options.ndsr.value_or(nop5.largest_ref);
  const std::int64_t ndsd = std::max(1, subdomain_max);
  // NOP2 (MODULEF.md section 3.2), the values FreeFem writes for 2D triangle meshes; in 3D
  // NDIM = 3 and the elements counted as tetrahedra (NTET) instead of triangles (NTRI).
  const std::array<std::int64_t, 27> nop2 = {mesh.dim, ndsr,
                                             ndsd,     1,
                                             nt,       0,
                                             0,        ntri,
                                             0,        ntet,
                                             0,        0,
                                             0,        nop5.elements_with_refs,
                                             nv,       0,
                                             0,        0,
                                             0,        0,
                                             0,        nv,
                                             2,        nop5.largest_span,
                                             0,        l5,
                                             1};
  auto words = [&](std::int64_t count, const auto& values) {
    std::string payload;
    codec.put_int(payload, count, wi);
    put_words(payload, std::vector<std::int64_t>(values.begin(), values.end()), wi, codec);
    return payload;
  };

  std::string file;
  const std::array<std::int64_t, 14> descriptor = {13, 6, 32, 0, 27, 0, l4, l5, 1, 1, 1, 1, 2, 1};
  std::string payload;
  for (std::int64_t x : descriptor)
    codec.put_int(payload, x, wi);
  append_fortran_record(file, payload, layout.marker_bytes, codec);

  payload.clear(); // NOP0: title, date, creator, type, NIVEAU = 0, ETAT = 1, NTACM = 0
  codec.put_int(payload, 32, wi);
  put_text(payload, options.text.title, 20, wi);
  put_text(payload, options.text.date, 2, wi);
  // Where the creator's 6 words lie in the file: the fingerprint is written there once known.
  const std::size_t creator_at = file.size() + layout.marker_bytes + payload.size();
  put_text(payload, options.text.creator, 6, wi);
  put_text(payload, "NOPO", 1, wi);
  for (std::int64_t x : {0, 1, 0})
    codec.put_int(payload, x, wi);
  append_fortran_record(file, payload, layout.marker_bytes, codec);

  append_fortran_record(file, words(27, nop2), layout.marker_bytes, codec);

  payload.clear(); // NOP4: the count is an integer word, the coordinates reals
  codec.put_int(payload, l4, wi);
  std::vector<double> coordinates;
  coordinates.reserve(static_cast<std::size_t>(l4));
  for (const auto& x : mesh.nodes) {
    for (const double c : x)
      coordinates.push_back(c);
  }
  put_words(payload, coordinates, layout.real_bytes, codec);
  append_fortran_record(file, payload, layout.marker_bytes, codec);

  payload.clear();
  codec.put_int(payload, l5, wi);
  put_words(payload, nop5.words, wi, codec);
  append_fortran_record(file, payload, layout.marker_bytes, codec);

  // The fingerprint leaves NOP0 out: it is the same before and after the creator is stamped.
  const std::uint64_t fingerprint = nopo_fingerprint(split_fortran_records(file, "NOPO writer"));
  if (options.stamp_fingerprint) {
    std::string creator = options.text.creator.substr(0, 8);
    creator.resize(8, ' ');
    std::string stamped;
    put_text(stamped, creator + fingerprint_text(fingerprint), 6, wi);
    file.replace(creator_at, stamped.size(), stamped);
  }
  return {std::move(file), fingerprint};
}

} // namespace

std::string encode_nopo(const Mesh& mesh, NopoVariant variant, const NopoWriteOptions& options) {
  return encode(mesh, variant, options).bytes;
}

void write_nopo(const std::filesystem::path& path, const Mesh& mesh, NopoVariant variant,
                const NopoWriteOptions& options) {
  const PhaseTimer timer("write");
  write_file_atomically(path, encode_nopo(mesh, variant, options));
}

void write_nopo(const std::filesystem::path& path, const Mesh& mesh, NopoVariant variant,
                const std::string& title, const std::string& creator, MeshCheck check) {
  const PhaseTimer timer("write");
  NopoWriteOptions options;
  options.text = {title, ds_date(), creator};
  options.stamp_fingerprint = true;
  options.check = check;
  const EncodedNopo file = encode(mesh, variant, options);
  write_file_atomically(path, file.bytes);
  // Written after the mesh: a stage killed between the two leaves a record of another mesh,
  // which the next stage refuses.
  write_provenance_beside(path, "NOPO", file.fingerprint, title, creator);
}

} // namespace sig
