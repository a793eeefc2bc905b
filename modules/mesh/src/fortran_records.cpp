#include "fortran_records.hpp"

#include "core/ds.hpp"
#include "core/error.hpp"

#include <bit>
#include <optional>

namespace sig {
namespace {

std::uint64_t get_unsigned(const char* p, int bytes, bool big_endian) {
  std::uint64_t value = 0;
  for (int k = 0; k < bytes; ++k) {
    const auto byte = static_cast<std::uint8_t>(p[big_endian ? k : bytes - 1 - k]);
    value = (value << 8) | byte;
  }
  return value;
}

void put_unsigned(std::string& out, std::uint64_t value, int bytes, bool big_endian) {
  char buffer[8];
  for (int k = 0; k < bytes; ++k) {
    buffer[big_endian ? bytes - 1 - k : k] = static_cast<char>(value & 0xff);
    value >>= 8;
  }
  out.append(buffer, bytes);
}

/// The records if markers of this width and order tile the file, else the reason why not.
std::optional<std::vector<std::string_view>> try_split(std::string_view bytes, int marker,
                                                       bool big_endian, std::string& why) {
  const WordCodec codec{big_endian};
  std::vector<std::string_view> payloads;
  std::size_t pos = 0;
  while (pos < bytes.size()) {
    if (bytes.size() - pos < static_cast<std::size_t>(marker)) {
      why = "truncated marker at byte " + std::to_string(pos);
      return std::nullopt;
    }
    const std::int64_t length = codec.get_int(bytes.data() + pos, marker);
    if (length < 0 || static_cast<std::uint64_t>(length) > bytes.size() - pos - marker ||
        bytes.size() - pos - marker - length < static_cast<std::size_t>(marker)) {
      why = "record length " + std::to_string(length) + " at byte " + std::to_string(pos) +
            " runs past the end of the file";
      return std::nullopt;
    }
    const std::int64_t tail = codec.get_int(bytes.data() + pos + marker + length, marker);
    if (tail != length) {
      why = "head and tail markers differ at byte " + std::to_string(pos);
      return std::nullopt;
    }
    payloads.push_back(bytes.substr(pos + marker, length));
    pos += 2 * marker + length;
  }
  if (payloads.empty()) {
    why = "empty file";
    return std::nullopt;
  }
  return payloads;
}

} // namespace

std::int64_t WordCodec::get_int(const char* p, int bytes) const {
  const std::uint64_t u = get_unsigned(p, bytes, big_endian);
  if (bytes == 4) return static_cast<std::int32_t>(static_cast<std::uint32_t>(u));
  return static_cast<std::int64_t>(u);
}

double WordCodec::get_real(const char* p, int bytes) const {
  const std::uint64_t u = get_unsigned(p, bytes, big_endian);
  if (bytes == 4) return std::bit_cast<float>(static_cast<std::uint32_t>(u));
  return std::bit_cast<double>(u);
}

void WordCodec::put_int(std::string& out, std::int64_t value, int bytes) const {
  put_unsigned(out, static_cast<std::uint64_t>(value), bytes, big_endian);
}

void WordCodec::put_real(std::string& out, double value, int bytes) const {
  if (bytes == 4) {
    put_unsigned(out, std::bit_cast<std::uint32_t>(static_cast<float>(value)), 4, big_endian);
  } else {
    put_unsigned(out, std::bit_cast<std::uint64_t>(value), 8, big_endian);
  }
}

FortranRecords split_fortran_records(std::string_view bytes, const std::string& file) {
  std::string reasons;
  for (bool big_endian : {false, true}) {
    for (int marker : {8, 4}) {
      std::string why;
      if (auto payloads = try_split(bytes, marker, big_endian, why)) {
        return FortranRecords{marker, big_endian, std::move(*payloads)};
      }
      reasons += std::string(reasons.empty() ? "" : "; ") + (big_endian ? "big" : "little") +
                 "-endian " + std::to_string(marker) + "-byte markers: " + why;
    }
  }
  throw Error(file + ": not a Fortran sequential file (truncated or not NOPO?): " + reasons);
}

std::uint64_t nopo_fingerprint(const FortranRecords& records) {
  std::uint64_t hash = fnv1a64(nullptr, 0);
  for (std::size_t k = 0; k < records.payloads.size(); ++k)
    if (k != 1) hash = fnv1a64(records.payloads[k].data(), records.payloads[k].size(), hash);
  return hash;
}

void append_fortran_record(std::string& out, const std::string& payload, int marker_bytes,
                           const WordCodec& codec) {
  codec.put_int(out, static_cast<std::int64_t>(payload.size()), marker_bytes);
  out += payload;
  codec.put_int(out, static_cast<std::int64_t>(payload.size()), marker_bytes);
}

} // namespace sig
