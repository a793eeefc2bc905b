#pragma once
// MODULEF's mesh data structure NOPO on file (MODULEF.md sections 3-5): a Fortran unformatted
// sequential file holding a descriptor record and the arrays NOP0 (header), NOP2 (mesh
// description), NOP4 (vertex coordinates) and NOP5 (elements with their references).
//
// The reader detects the record-marker width (8 or 4 bytes), the byte order, the integer word
// (4 or 8 bytes) and the real word of NOP4 (float or double). Triangles keep their NOP5 order
// and node order (made counter-clockwise if they are not); quadrilaterals are split into
// (1,2,3) + (3,4,1); the references on local edge j (vertex j to j+1) become Facet in
// the direction of the triangle, domain on the left, an interface edge seen from both sides
// being kept once; vertex references become vertex_ref; NDSDE becomes the sub-domain.
//
// The writer follows FreeFem's Write_nopo (MODULEF.md section 5.2): with the same text fields
// and NDSR = 0 it reproduces a FreeFem file byte for byte. By default it writes the true
// largest reference in NDSR (FreeFem always writes 0, and ignores it on reading).
//
// Integrity. The fingerprint of a NOPO file is the 64-bit FNV-1a hash of its records but NOP0
// (descriptor, NOP1..NOP5: every word of the mesh, none of the text). sig-mesh writes case.nopo
// with the fingerprint in NOP0's creator field ("sig-mesh" + 16 hex digits, the layout
// unchanged, so other MODULEF readers still read it); the reader recomputes it and refuses a file
// that no longer matches (a node moved, bytes damaged). Inside a stage the reader registers the
// mesh as an input of the case (core/provenance.hpp) with the provenance sig-mesh wrote beside it
// (case.nopo.prov: the MESH card it was made from; the NOPO layout has no room for it): every DS
// built from it records its fingerprint and its MESH card, a DS of another mesh is refused, and
// so is a case.nopo made from another MESH card than the deck's.
#include "mesh/mesh.hpp"

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace sig {

/// Word sizes on file: record marker, integer word, NOP4 real word (in bytes).
enum class NopoVariant {
  ff64, ///< 8, 8, 4: FreeFem on 64-bit Linux/macOS
  i4r4, ///< 4, 4, 4: classic 32-bit MODULEF/Simail, gfortran defaults
  i8r8  ///< 4, 8, 8: double-precision coordinates, our pipeline file case.nopo
};

struct NopoLayout {
  int marker_bytes = 8;
  int int_bytes = 8;
  int real_bytes = 4;
  bool big_endian = false;
};
NopoLayout nopo_layout(NopoVariant variant);

/// The text fields of NOP0, without their blank padding.
struct NopoText {
  std::string title;   ///< 80 characters on file
  std::string date;    ///< 8 characters on file
  std::string creator; ///< 24 characters on file
};

struct NopoFile {
  Mesh mesh;
  NopoText text;
  NopoLayout layout;
  std::uint64_t fingerprint = 0;       ///< of the records but NOP0 (see above)
  std::array<std::int64_t, 27> nop2{}; ///< NDIM, NDSR, NDSD, NCOPNP, NE, ... as on file
};

/// Read and check a NOPO file. Errors (sig::Error) name the file and the record or array.
NopoFile read_nopo_file(const std::filesystem::path& path);
/// The same from the bytes of a file called `name` (tests, fuzzing); registers no input.
NopoFile parse_nopo_file(const std::string& name, const std::string& bytes);
/// The mesh of a NOPO file, checked with check_mesh.
Mesh read_nopo(const std::filesystem::path& path);

struct NopoWriteOptions {
  NopoText text; ///< written as given (date blank if empty)
  bool big_endian = false;
  std::optional<std::int64_t> ndsr; ///< NOP2 word 2; default: the largest reference
  /// Write the fingerprint after the first 8 characters of text.creator (see above).
  bool stamp_fingerprint = false;
  MeshCheck check = MeshCheck::run; ///< mesh/mesh.hpp: skip only for a mesh checked already
};

/// The bytes of the NOPO file of `mesh`.
std::string encode_nopo(const Mesh& mesh, NopoVariant variant, const NopoWriteOptions& options);

/// Write `mesh` atomically (temporary file + rename) with today's date and its fingerprint after
/// `creator` (its first 8 characters): the case.nopo of a stage. Inside a stage, its provenance
/// (the cards of the stage and what its inputs record) goes beside it to PATH.prov
/// (core/provenance.hpp).
void write_nopo(const std::filesystem::path& path, const Mesh& mesh, NopoVariant variant,
                const std::string& title, const std::string& creator,
                MeshCheck check = MeshCheck::run);
void write_nopo(const std::filesystem::path& path, const Mesh& mesh, NopoVariant variant,
                const NopoWriteOptions& options);

} // namespace sig
