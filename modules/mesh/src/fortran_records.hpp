#pragma once
// Fortran unformatted sequential files, the container of NOPO (MODULEF.md section 4.1): records
// [marker][payload][marker] where the marker is the payload length in bytes, written in 4 or 8
// bytes, little- or big-endian. Private to the NOPO reader and writer.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace sig {

/// Integers and reals of a given byte size and byte order.
struct WordCodec {
  bool big_endian = false;

  std::int64_t get_int(const char* p, int bytes) const;
  double get_real(const char* p, int bytes) const; ///< 4 = float, 8 = double
  void put_int(std::string& out, std::int64_t value, int bytes) const;
  void put_real(std::string& out, double value, int bytes) const;
};

struct FortranRecords {
  int marker_bytes = 8;
  bool big_endian = false;
  std::vector<std::string_view> payloads; ///< views into the file bytes
};

/// Find the marker width and byte order for which the records tile `bytes` exactly (8 then 4
/// bytes, little then big endian). Throws sig::Error naming `file` if none does.
FortranRecords split_fortran_records(std::string_view bytes, const std::string& file);

/// The fingerprint of a NOPO file (mesh/nopo.hpp): FNV-1a 64 of every record payload but the
/// second (NOP0, the text).
std::uint64_t nopo_fingerprint(const FortranRecords& records);

/// Append one record holding `payload`.
void append_fortran_record(std::string& out, const std::string& payload, int marker_bytes,
                           const WordCodec& codec);

} // namespace sig
