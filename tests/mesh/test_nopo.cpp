// NOPO reader and writer against FreeFem's files (MODULEF.md section 5.3).
#include "core/ds.hpp"
#include "core/error.hpp"
#include "mesh/freefem.hpp"
#include "mesh/generators.hpp"
#include "mesh/nopo.hpp"
#include "mesh_testing.hpp"

#include <bit>
#include <cstring>
#include <set>

namespace sig {
namespace {

using testing::legacy_mesh;
using testing::ScratchFolder;
using testing::shared_nopo;
using testing::slurp;

struct Sample {
  const char* name;
  int nv, nt, nbe, l5, nef, ndsd, max_label;
};
// MODULEF.md section 5.3, "Expected values".
const Sample samples[] = {{"square3", 16, 18, 12, 220, 16, 1, 4},
                          {"disc", 10, 10, 8, 134, 10, 1, 7},
                          {"tworeg", 15, 16, 14, 200, 16, 20, 9}};

/// Both the shared reference and, where it exists, the committed copy in meshes/legacy.
std::vector<std::filesystem::path> copies(const std::string& file) {
  std::vector<std::filesystem::path> paths = {shared_nopo(file)};
  if (std::filesystem::exists(legacy_mesh(file))) paths.push_back(legacy_mesh(file));
  return paths;
}

/// Directed sides of the triangles: (a, b) -> number of triangles having it.
std::map<std::pair<int, int>, int> directed_sides(const Mesh& mesh) {
  std::map<std::pair<int, int>, int> sides;
  for (const auto& t : mesh.cells) {
    for (int j = 0; j < 3; ++j)
      ++sides[{t[j], t[(j + 1) % 3]}];
  }
  return sides;
}

TEST(NopoSamples, ReadEqualToTheirFreeFemMsh) {
  for (const Sample& s : samples) {
    for (const auto& path : copies(std::string(s.name) + ".nopo")) {
      SCOPED_TRACE(path.string());
      const NopoFile file = read_nopo_file(path);
      EXPECT_EQ(file.layout.marker_bytes, 8);
      EXPECT_EQ(file.layout.int_bytes, 8);
      EXPECT_EQ(file.layout.real_bytes, 4);
      EXPECT_FALSE(file.layout.big_endian);
      EXPECT_EQ(file.nop2[21], s.nv);  // NP
      EXPECT_EQ(file.nop2[14], s.nv);  // NOE
      EXPECT_EQ(file.nop2[4], s.nt);   // NE
      EXPECT_EQ(file.nop2[7], s.nt);   // NTRI
      EXPECT_EQ(file.nop2[3], 1);      // NCOPNP
      EXPECT_EQ(file.nop2[25], s.l5);  // LNOP5
      EXPECT_EQ(file.nop2[13], s.nef); // NEF
      EXPECT_EQ(file.nop2[2], s.ndsd); // NDSD
      EXPECT_EQ(file.text.creator, "created with BAMG");
      EXPECT_EQ(file.text.date.size(), 8u);

      auto msh = path;
      const auto raw = testing::read_raw_freefem(msh.replace_extension(".msh"));
      testing::expect_mesh_matches_freefem(file.mesh, raw, 1e-6);
      EXPECT_EQ(static_cast<long>(file.mesh.facets.size()), raw.nbe);

      // Boundary edges (one triangle) point as in their counter-clockwise triangle; interface
      // edges (two triangles) are kept once.
      const auto sides = directed_sides(file.mesh);
      for (const auto& e : file.mesh.facets) {
        const int forward =
            sides.count({e.node[0], e.node[1]}) ? sides.at({e.node[0], e.node[1]}) : 0;
        const int backward =
            sides.count({e.node[1], e.node[0]}) ? sides.at({e.node[1], e.node[0]}) : 0;
        EXPECT_EQ(forward, 1) << "edge " << e.node[0] + 1 << "-" << e.node[1] + 1;
        EXPECT_LE(backward, 1);
      }
      const auto refs = file.mesh.references();
      EXPECT_EQ(refs.back(), s.max_label);
    }
  }
}

TEST(NopoSamples, InterfaceEdgesOfTworegKeptOnce) {
  const Mesh mesh = read_nopo(shared_nopo("tworeg.nopo"));
  const auto interface = mesh.facets_with_ref(9);
  EXPECT_EQ(interface.size(), 2u); // bmid(2): two segments on x = 1
  for (const auto& e : interface) {
    EXPECT_DOUBLE_EQ(mesh.nodes[e.node[0]].x(), 1.0);
    EXPECT_DOUBLE_EQ(mesh.nodes[e.node[1]].x(), 1.0);
  }
  EXPECT_EQ(mesh.subdomains(), (std::vector<int>{10, 20}));
}

TEST(NopoSamples, RewriteIsByteIdenticalToFreeFem) {
  for (const Sample& s : samples) {
    for (const auto& path : copies(std::string(s.name) + ".nopo")) {
      SCOPED_TRACE(path.string());
      const NopoFile file = read_nopo_file(path);
      NopoWriteOptions options;
      options.text = file.text;
      options.ndsr = 0; // FreeFem's bug (MODULEF.md section 6)
      EXPECT_EQ(file.nop2[1], 0);
      const std::string bytes = encode_nopo(file.mesh, NopoVariant::ff64, options);
      EXPECT_TRUE(bytes == slurp(path)) << "re-encoded file differs";
    }
  }
}

TEST(NopoSamples, I4r4SampleDecodesToTheSameMesh) {
  for (const auto& path : copies("square3_i4r4.nopo")) {
    SCOPED_TRACE(path.string());
    const NopoFile classic = read_nopo_file(path);
    EXPECT_EQ(classic.layout.marker_bytes, 4);
    EXPECT_EQ(classic.layout.int_bytes, 4);
    EXPECT_EQ(classic.layout.real_bytes, 4);
    EXPECT_EQ(classic.text.title, "from square3.msh");
    EXPECT_EQ(classic.text.creator, "nopo_decode.py");
    EXPECT_EQ(classic.text.date, "");
    EXPECT_EQ(classic.nop2[1], 4); // NDSR = true largest label
    const Mesh freefem = read_nopo(shared_nopo("square3.nopo"));
    ASSERT_EQ(classic.mesh.num_nodes(), freefem.num_nodes());
    for (int i = 0; i < freefem.num_nodes(); ++i)
      EXPECT_LT((classic.mesh.nodes[i] - freefem.nodes[i]).norm(), 1e-6);
    EXPECT_EQ(classic.mesh.cells, freefem.cells);
    EXPECT_EQ(classic.mesh.subdomain, freefem.subdomain);
    EXPECT_EQ(classic.mesh.vertex_ref, freefem.vertex_ref);
    ASSERT_EQ(classic.mesh.facets.size(), freefem.facets.size());
    for (std::size_t e = 0; e < freefem.facets.size(); ++e) {
      EXPECT_EQ(classic.mesh.facets[e].node[0], freefem.facets[e].node[0]);
      EXPECT_EQ(classic.mesh.facets[e].node[1], freefem.facets[e].node[1]);
      EXPECT_EQ(classic.mesh.facets[e].ref, freefem.facets[e].ref);
    }
  }
}

TEST(NopoSamples, I4r4WriterReproducesTheLegacyFileFromTheMsh) {
  // The sample was written from square3.msh with this title, creator, a blank date and
  // NDSR = 4 (MODULEF.md section 5.3).
  const Mesh mesh = read_freefem_msh(shared_nopo("square3.msh"));
  NopoWriteOptions options;
  options.text = {"from square3.msh", "", "nopo_decode.py"};
  const std::string bytes = encode_nopo(mesh, NopoVariant::i4r4, options);
  EXPECT_TRUE(bytes == slurp(shared_nopo("square3_i4r4.nopo")));
}

/// A rectangle cut into two sub-domains with a labelled interface, at coordinates that no
/// float represents.
Mesh two_region_mesh() {
  Mesh mesh = rectangle(10.0 / 3, std::acos(-1.0) / 7, 6, 5, {3, 4, 2, 1});
  for (int t = 0; t < mesh.num_cells(); ++t) {
    double cx = 0;
    for (int v : mesh.cells[t])
      cx += mesh.nodes[v].x() / 3;
    mesh.subdomain[t] = cx < 5.0 / 3 ? 1 : 2;
  }
  for (int j = 0; j < 5; ++j)
    mesh.facets.push_back({{j * 7 + 3, (j + 1) * 7 + 3}, 9});
  check_mesh(mesh, "two_region_mesh");
  return mesh;
}

void expect_same_mesh(const Mesh& a, const Mesh& b, bool exact_coordinates) {
  ASSERT_EQ(a.num_nodes(), b.num_nodes());
  for (int i = 0; i < a.num_nodes(); ++i) {
    if (exact_coordinates) {
      EXPECT_EQ(std::bit_cast<std::uint64_t>(a.nodes[i].x()),
                std::bit_cast<std::uint64_t>(b.nodes[i].x()));
      EXPECT_EQ(std::bit_cast<std::uint64_t>(a.nodes[i].y()),
                std::bit_cast<std::uint64_t>(b.nodes[i].y()));
    } else {
      EXPECT_LT((a.nodes[i] - b.nodes[i]).norm(), 1e-6 * a.nodes[i].norm() + 1e-12);
    }
  }
  EXPECT_EQ(a.cells, b.cells);
  EXPECT_EQ(a.subdomain, b.subdomain);
  EXPECT_EQ(a.vertex_ref, b.vertex_ref);
  std::set<std::tuple<int, int, int>> ea, eb;
  for (const auto& e : a.facets)
    ea.insert({e.node[0], e.node[1], e.ref});
  for (const auto& e : b.facets)
    eb.insert({e.node[0], e.node[1], e.ref});
  EXPECT_EQ(ea, eb);
  EXPECT_EQ(a.facets.size(), b.facets.size());
}

TEST(Nopo, I8r8RoundTripKeepsDoublesExactly) {
  const ScratchFolder dir;
  const Mesh mesh = two_region_mesh();
  write_nopo(dir / "case.nopo", mesh, NopoVariant::i8r8, "a round trip", "sig-mesh");
  const NopoFile back = read_nopo_file(dir / "case.nopo");
  EXPECT_EQ(back.layout.marker_bytes, 4);
  EXPECT_EQ(back.layout.int_bytes, 8);
  EXPECT_EQ(back.layout.real_bytes, 8);
  EXPECT_EQ(back.text.title, "a round trip");
  // The creator, then the fingerprint of the mesh records (the integrity check of case.nopo).
  EXPECT_EQ(back.text.creator, "sig-mesh" + fingerprint_text(back.fingerprint));
  EXPECT_EQ(back.text.date.size(), 8u);
  EXPECT_EQ(back.nop2[1], 9); // NDSR: the largest reference
  EXPECT_EQ(back.nop2[2], 2); // NDSD
  expect_same_mesh(mesh, back.mesh, true);
  EXPECT_EQ(back.mesh.facets_with_ref(9).size(), 5u); // interface kept once
}

TEST(Nopo, EveryVariantAndByteOrderRoundTrips) {
  const ScratchFolder dir;
  const Mesh mesh = two_region_mesh();
  for (NopoVariant variant : {NopoVariant::ff64, NopoVariant::i4r4, NopoVariant::i8r8}) {
    for (bool big_endian : {false, true}) {
      NopoWriteOptions options;
      options.text = {"variant test", "26/11/22", "test"};
      options.big_endian = big_endian;
      const auto path = dir / "v.nopo";
      write_nopo(path, mesh, variant, options);
      const NopoFile back = read_nopo_file(path);
      const NopoLayout expected = nopo_layout(variant);
      EXPECT_EQ(back.layout.marker_bytes, expected.marker_bytes);
      EXPECT_EQ(back.layout.int_bytes, expected.int_bytes);
      EXPECT_EQ(back.layout.real_bytes, expected.real_bytes);
      EXPECT_EQ(back.layout.big_endian, big_endian);
      EXPECT_EQ(back.text.date, "26/11/22");
      expect_same_mesh(mesh, back.mesh, variant == NopoVariant::i8r8);
      // Size check of MODULEF.md section 4.4 for the two documented layouts.
      const auto size = std::filesystem::file_size(path);
      const auto nv = static_cast<std::uintmax_t>(mesh.num_nodes());
      const auto l5 = static_cast<std::uintmax_t>(back.nop2[25]);
      if (variant == NopoVariant::ff64) {
        EXPECT_EQ(size, 696 + 8 * nv + 8 * l5);
      }
      if (variant == NopoVariant::i4r4) {
        EXPECT_EQ(size, 348 + 8 * nv + 4 * l5);
      }
    }
  }
}

/// Records of a little-endian file with 4-byte markers.
std::vector<std::string> split_records4(const std::string& bytes) {
  std::vector<std::string> records;
  for (std::size_t pos = 0; pos < bytes.size();) {
    std::uint32_t n;
    std::memcpy(&n, bytes.data() + pos, 4);
    records.push_back(bytes.substr(pos + 4, n));
    pos += 8 + n;
  }
  return records;
}

std::string join_records4(const std::vector<std::string>& records) {
  std::string bytes;
  for (const auto& r : records) {
    const auto n = static_cast<std::uint32_t>(r.size());
    bytes.append(reinterpret_cast<const char*>(&n), 4)
        .append(r)
        .append(reinterpret_cast<const char*>(&n), 4);
  }
  return bytes;
}

TEST(Nopo, ArraySplitOverTwoRecordsIsJoined) {
  const ScratchFolder dir;
  const std::string bytes = slurp(shared_nopo("square3_i4r4.nopo"));
  auto records = split_records4(bytes);
  ASSERT_EQ(records.size(), 5u);
  // NOP5 = [220][220 words] becomes [100][100 words] + [120][120 words] (Simail style).
  const std::string nop5 = records[4];
  auto with_count = [](std::uint32_t count, const std::string& words) {
    return std::string(reinterpret_cast<const char*>(&count), 4) + words;
  };
  records[4] = with_count(100, nop5.substr(4, 400));
  records.push_back(with_count(120, nop5.substr(404)));
  testing::spit(dir / "split.nopo", join_records4(records));
  expect_same_mesh(read_nopo(shared_nopo("square3_i4r4.nopo")), read_nopo(dir / "split.nopo"),
                   true);
}

/// Run `read` on a damaged file and return the message, which must name the file.
std::string error_of(const std::filesystem::path& path) {
  try {
    read_nopo(path);
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    return message;
  }
  ADD_FAILURE() << path << " was accepted";
  return "";
}

TEST(Nopo, DamagedFilesAreRejectedWithAMessage) {
  const ScratchFolder dir;
  const std::string bytes = slurp(shared_nopo("square3.nopo"));
  const auto path = dir / "bad.nopo";

  testing::spit(path, bytes.substr(0, bytes.size() - 10)); // cut inside NOP5
  EXPECT_NE(error_of(path).find("not a Fortran sequential file"), std::string::npos);

  testing::spit(path, bytes.substr(0, 800)); // cut after NOP4: NOP5 missing
  EXPECT_NE(error_of(path).find("NOP5"), std::string::npos);

  std::string wrong_ne = bytes; // NOP2 word 5 (NE) = 17 instead of 18 (byte map, 4.4)
  wrong_ne[424 + 4 * 8] = 17;
  testing::spit(path, wrong_ne);
  EXPECT_NE(error_of(path).find("NOP5"), std::string::npos);

  std::string huge_ne = bytes; // NE = 2^60: refused before a vector is reserved for it
  const std::uint64_t huge = std::uint64_t{1} << 60;
  std::memcpy(huge_ne.data() + 424 + 4 * 8, &huge, 8);
  testing::spit(path, huge_ne);
  EXPECT_NE(error_of(path).find("NE = 1152921504606846976 elements cannot fit in NOP5"),
            std::string::npos);

  std::string wrong_type = bytes; // NOP0 word 29 'NOPO' -> 'XOPO'
  wrong_type[368] = 'X';
  testing::spit(path, wrong_type);
  EXPECT_NE(error_of(path).find("'NOPO'"), std::string::npos);
}

// A NOPO not stamped by sig-mesh (FreeFem's, MODULEF's, one edited by hand) has its geometry
// checked on every read: only our own, unchanged since check_mesh passed it in write_nopo, is not.
TEST(Nopo, AnUnstampedFileWithADegenerateTriangleIsRefused) {
  const ScratchFolder dir;
  std::string bytes = slurp(shared_nopo("square3.nopo"));
  const auto path = dir / "moved.nopo";
  // square3.nopo: NOP4's 32 four-byte reals after its count word at 656; node 1 put on node 2.
  std::memcpy(bytes.data() + 664, bytes.data() + 672, 8);
  testing::spit(path, bytes);
  const std::string error = error_of(path);
  EXPECT_NE(error.find("degenerate"), std::string::npos) << error;
}

// A count word near 2^61 times the word size wraps to the record's true size: the fuzzer found
// that overflow (CI, fuzz_nopo), which read past NOP5. The reader now divides instead.
TEST(Nopo, HugeCountWordsAreRefusedNotMultiplied) {
  const ScratchFolder dir;
  const std::string bytes = slurp(shared_nopo("square3.nopo"));
  const auto path = dir / "huge.nopo";
  // square3.nopo: 8-byte markers and words; descriptor L4 at byte 56, L5 at 64; NOP4's count word
  // at 656 (32 reals), NOP5's at 808 (220 words).
  const auto put = [](std::string& file, std::size_t at, std::uint64_t value) {
    std::memcpy(file.data() + at, &value, 8);
  };
  std::string nop5 = bytes;
  const std::uint64_t wraps_to_220_words = (std::uint64_t{1} << 61) + 220;
  put(nop5, 64, wraps_to_220_words);
  put(nop5, 808, wraps_to_220_words);
  testing::spit(path, nop5);
  std::string error = error_of(path);
  EXPECT_NE(error.find("(NOP5): 1760 bytes for 2305843009213694172 words"), std::string::npos)
      << error;

  std::string nop4 = bytes;
  const std::uint64_t wraps_to_32_reals = (std::uint64_t{1} << 62) + 32;
  put(nop4, 56, wraps_to_32_reals);
  put(nop4, 656, wraps_to_32_reals);
  testing::spit(path, nop4);
  error = error_of(path);
  EXPECT_NE(error.find("(NOP4): 128 bytes for"), std::string::npos) << error;
}

// case.nopo carries the fingerprint of its mesh records: a node moved or a byte damaged after
// sig-mesh wrote it is refused, while the text fields (not the mesh) may change.
TEST(Nopo, FingerprintRefusesAMovedNodeOrDamagedBytes) {
  const ScratchFolder dir;
  const auto path = dir / "case.nopo";
  write_nopo(path, two_region_mesh(), NopoVariant::i8r8, "integrity", "sig-mesh");
  const std::string bytes = slurp(path);
  const std::uint64_t fingerprint = read_nopo_file(path).fingerprint;

  // i8r8: descriptor record 4 + 112 + 4, NOP0 4 + 8 + 32 * 8 + 4, NOP2 4 + 8 + 27 * 8 + 4, then
  // NOP4's marker and count word: x of node 1 at byte 636.
  std::string moved = bytes;
  double x = 0;
  std::memcpy(&x, moved.data() + 636, 8);
  x += 0.5;
  std::memcpy(moved.data() + 636, &x, 8);
  testing::spit(path, moved);
  const std::string error = error_of(path);
  EXPECT_NE(error.find("does not match the fingerprint " + fingerprint_text(fingerprint)),
            std::string::npos)
      << error;

  std::string damaged = bytes; // a byte in the middle of NOP5
  damaged[bytes.size() - 100] ^= 0x10;
  testing::spit(path, damaged);
  EXPECT_NE(error_of(path).find("does not match the fingerprint"), std::string::npos);

  std::string retitled = bytes; // NOP0's title is not the mesh
  retitled[4 + 112 + 4 + 4 + 8] = 'X';
  testing::spit(path, retitled);
  EXPECT_EQ(read_nopo_file(path).fingerprint, fingerprint);
}

} // namespace
} // namespace sig
