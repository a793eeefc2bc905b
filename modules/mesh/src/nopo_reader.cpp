#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/phase_times.hpp"
#include "core/provenance.hpp"
#include "fortran_records.hpp"
#include "mesh/nopo.hpp"
#include "nop5_walk.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <string_view>

namespace sig {
namespace {

/// Reads the arrays of a NOPO file one after the other; an array may span several records
/// (Simail), each record starting with an integer count word.
class ArrayReader {
public:
  ArrayReader(const FortranRecords& records, int int_bytes, std::string file)
      : records_(records), codec_{records.big_endian}, int_bytes_(int_bytes),
        file_(std::move(file)) {}

  /// `n` integers; with `keep_raw`, raw() then holds their bytes (for the text words of NOP0).
  std::vector<std::int64_t> ints(const std::string& name, std::int64_t n, bool keep_raw = false) {
    std::vector<std::int64_t> values;
    values.reserve(
        static_cast<std::size_t>(std::min<std::int64_t>(n, records_left_bytes() / int_bytes_)));
    raw_.clear();
    while (static_cast<std::int64_t>(values.size()) < n) {
      const auto [count, body] = next_record(name, n - static_cast<std::int64_t>(values.size()));
      // Divide, never multiply: a count read from the file may be near 2^63.
      SIG_VERIFY(body.size() % int_bytes_ == 0 &&
                     body.size() / int_bytes_ == static_cast<std::size_t>(count),
                 where(name) << ": " << body.size() << " bytes for " << count << " words of "
                             << int_bytes_ << " bytes");
      append_words(values, body, count, int_bytes_,
                   [&](const char* w) { return codec_.get_int(w, int_bytes_); });
      if (keep_raw) raw_.append(body);
    }
    return values;
  }

  /// `n` reals in words of 4 or 8 bytes, whichever the payload size says.
  std::vector<double> reals(const std::string& name, std::int64_t n, int& real_bytes) {
    std::vector<double> values;
    while (static_cast<std::int64_t>(values.size()) < n) {
      const auto [count, body] = next_record(name, n - static_cast<std::int64_t>(values.size()));
      const auto size = static_cast<std::int64_t>(body.size());
      SIG_VERIFY(size % count == 0 && (size / count == 4 || size / count == 8),
                 where(name) << ": " << size << " bytes for " << count
                             << " reals (neither float nor double)");
      real_bytes = static_cast<int>(size / count);
      append_words(values, body, count, real_bytes,
                   [&](const char* w) { return codec_.get_real(w, real_bytes); });
    }
    return values;
  }

  void skip_records(std::int64_t n, const std::string& name) {
    SIG_VERIFY(n >= 0 && static_cast<std::size_t>(n) <= records_left(),
               file_ << ": the file ends before the " << n << " records of " << name);
    next_ += n;
  }
  std::size_t records_left() const { return records_.payloads.size() - next_; }
  /// The payload bytes of the records left: no count from the file reserves more than that.
  std::int64_t records_left_bytes() const {
    std::int64_t bytes = 0;
    for (std::size_t r = next_; r < records_.payloads.size(); ++r)
      bytes += static_cast<std::int64_t>(records_.payloads[r].size());
    return bytes;
  }
  const std::string& raw() const { return raw_; }
  std::string where(const std::string& name) const {
    return file_ + ": record " + std::to_string(next_) + " (" + name + ")";
  }

private:
  /// The `count` words of `bytes` bytes each in `body` appended to `values`, decoded one by one,
  /// or copied as they lie when they are already the host's: our case.nopo's 8-byte
  /// little-endian words on a little-endian host.
  template <class T, class Decode>
  void append_words(std::vector<T>& values, std::string_view body, std::int64_t count, int bytes,
                    Decode decode) const {
    if (!codec_.big_endian && bytes == sizeof(T) && std::endian::native == std::endian::little) {
      const std::size_t done = values.size();
      values.resize(done + static_cast<std::size_t>(count));
      std::memcpy(values.data() + done, body.data(), body.size());
      return;
    }
    for (std::int64_t k = 0; k < count; ++k)
      values.push_back(decode(body.data() + k * bytes));
  }

  std::pair<std::int64_t, std::string_view> next_record(const std::string& name,
                                                        std::int64_t wanted) {
    SIG_VERIFY(next_ < records_.payloads.size(),
               file_ << ": the file ends before array " << name << " (truncated?)");
    const std::string_view payload = records_.payloads[next_++];
    SIG_VERIFY(payload.size() >= static_cast<std::size_t>(int_bytes_), where(name)
                                                                           << ": no count word");
    const std::int64_t count = codec_.get_int(payload.data(), int_bytes_);
    SIG_VERIFY(count > 0 && count <= wanted,
               where(name) << ": count word " << count << " where " << wanted << " words remain");
    return {count, payload.substr(int_bytes_)};
  }

  const FortranRecords& records_;
  WordCodec codec_;
  int int_bytes_;
  std::string file_;
  std::size_t next_ = 1; // record 0 is the descriptor
  std::string raw_;
};

std::string text_of_words(const std::string& raw, int int_bytes, int first, int count) {
  std::string text;
  for (int k = first; k < first + count; ++k)
    text.append(raw, k * int_bytes, 4);
  const auto end = text.find_last_not_of(' ');
  return end == std::string::npos ? std::string() : text.substr(0, end + 1);
}

// Read in one piece of the file's size (no stream copy, no zero fill first): the records must
// tile the file, so the whole of it is needed.
struct FileBytes {
  std::unique_ptr<char[]> data;
  std::size_t size = 0;
  std::string_view view() const { return {data.get(), size}; }
};

FileBytes read_bytes(const std::filesystem::path& path) {
  verify_regular_file(path, "NOPO file");
  std::error_code error;
  const auto size = std::filesystem::file_size(path, error);
  SIG_VERIFY(!error, path.string() << ": cannot open the NOPO file: " << error.message());
  std::ifstream in(path, std::ios::binary);
  SIG_VERIFY(in, path.string() << ": cannot open the NOPO file");
  FileBytes bytes{std::unique_ptr<char[]>(new char[size]), size};
  in.read(bytes.data.get(), static_cast<std::streamsize>(size));
  SIG_VERIFY(in.gcount() == static_cast<std::streamsize>(size),
             path.string() << ": read error (" << in.gcount() << " of " << size << " bytes)");
  return bytes;
}

NopoFile parse_nopo_bytes(const std::string& file, std::string_view bytes);

} // namespace

NopoFile read_nopo_file(const std::filesystem::path& path) {
  const PhaseTimer timer("read");
  NopoFile result = parse_nopo_bytes(path.string(), read_bytes(path).view());
  note_case_file("NOPO", path, result.fingerprint); // a stage's case.nopo: an input
  return result;
}

NopoFile parse_nopo_file(const std::string& file, const std::string& bytes) {
  return parse_nopo_bytes(file, bytes);
}

namespace {
NopoFile parse_nopo_bytes(const std::string& file, std::string_view bytes) {
  const FortranRecords records = split_fortran_records(bytes, file);
  NopoFile result;
  result.layout.marker_bytes = records.marker_bytes;
  result.layout.big_endian = records.big_endian;

  // 1. Descriptor: 13, 6, L0..L5, T0..T5 in 14 integer words (4 or 8 bytes).
  const std::string_view descriptor = records.payloads[0];
  SIG_VERIFY(descriptor.size() != 208,
             file << ": Simail 64-bit NOPO files (208-byte descriptor) are not supported");
  SIG_VERIFY(descriptor.size() == 56 || descriptor.size() == 112,
             file << ": record 1 has " << descriptor.size()
                  << " bytes; a NOPO descriptor has 14 words (56 or 112 bytes)");
  const int int_bytes = static_cast<int>(descriptor.size() / 14);
  result.layout.int_bytes = int_bytes;
  const WordCodec codec{records.big_endian};
  std::array<std::int64_t, 14> desc{};
  for (int k = 0; k < 14; ++k)
    desc[k] = codec.get_int(descriptor.data() + k * int_bytes, int_bytes);
  SIG_VERIFY(desc[0] == 13 && desc[1] == 6 && desc[2] == 32 && desc[4] == 27,
             file << ": record 1 is not a NOPO descriptor (expected 13, 6, 32, L1, 27, ...)");
  const std::int64_t l1 = desc[3], l3 = desc[5], l4 = desc[6], l5 = desc[7];
  SIG_VERIFY(l1 >= 0 && l3 >= 0 && l4 > 0 && l5 > 0,
             file << ": record 1: bad array lengths L1 = " << l1 << ", L3 = " << l3
                  << ", L4 = " << l4 << ", L5 = " << l5);

  // 2. The arrays, in order: NOP0, [NOP1 + NTACM arrays], NOP2, [NOP3], NOP4, NOP5.
  ArrayReader arrays(records, int_bytes, file);
  const std::vector<std::int64_t> nop0 = arrays.ints("NOP0", 32, true);
  result.text.title = text_of_words(arrays.raw(), int_bytes, 0, 20);
  result.text.date = text_of_words(arrays.raw(), int_bytes, 20, 2);
  result.text.creator = text_of_words(arrays.raw(), int_bytes, 22, 6);
  SIG_VERIFY(text_of_words(arrays.raw(), int_bytes, 28, 1) == "NOPO",
             file << ": NOP0 word 29 is '" << text_of_words(arrays.raw(), int_bytes, 28, 1)
                  << "', not 'NOPO'");
  // Integrity, before the words are trusted: the fingerprint sig-mesh wrote (mesh/nopo.hpp).
  result.fingerprint = nopo_fingerprint(records);
  const std::string& creator = result.text.creator;
  const bool ours = creator.size() == 24 && creator.starts_with("sig-") &&
                    creator.find_first_not_of("0123456789abcdef", 8) == std::string::npos;
  if (ours)
    SIG_VERIFY(creator.substr(8) == fingerprint_text(result.fingerprint),
               file << ": the mesh (NOP2, NOP4, NOP5) does not match the fingerprint "
                    << creator.substr(8) << " written with it (NOP0 creator; now "
                    << fingerprint_text(result.fingerprint)
                    << "): the file was changed or damaged after " << creator.substr(0, 8)
                    << " wrote it; rerun sig-mesh");
  if (l1 > 0) {
    arrays.ints("NOP1", l1);
    arrays.skip_records(nop0[31], "the NTACM arrays"); // unverified layout (MODULEF.md 7)
  }
  const std::vector<std::int64_t> nop2 = arrays.ints("NOP2", 27);
  std::copy(nop2.begin(), nop2.end(), result.nop2.begin());
  if (l3 > 0) arrays.ints("NOP3", l3);
  int real_bytes = 4;
  std::vector<double> nop4 = arrays.reals("NOP4", l4, real_bytes);
  result.layout.real_bytes = real_bytes;
  const std::vector<std::int64_t> nop5 = arrays.ints("NOP5", l5); // trust L5 over NOP2.LNOP5
  SIG_VERIFY(arrays.records_left() == 0,
             file << ": " << arrays.records_left() << " unexpected records after NOP5");

  // 3. Consistency of NOP2 with what this reader supports.
  const auto& n2 = result.nop2;
  SIG_VERIFY(n2[word::NDIM] == 2 || n2[word::NDIM] == 3,
             file << ": NOP2: NDIM = " << n2[word::NDIM] << ", only 2D and 3D meshes are read");
  SIG_VERIFY(n2[word::NTACOO] <= 1, file << ": NOP2: NTACOO = " << n2[word::NTACOO]
                                         << ", only Cartesian coordinates are read");
  SIG_VERIFY(n2[word::NSUP] == 0, file << ": NOP2: super-elements are not supported");
  SIG_VERIFY(n2[word::NP] > 0 && n2[word::NP] <= max_mesh_nodes,
             file << ": NOP2: NP = " << n2[word::NP] << " points, not in 1.." << max_mesh_nodes);
  SIG_VERIFY(l4 == n2[word::NDIM] * n2[word::NP],
             file << ": NOP4 holds " << l4
                  << " reals but NOP2 says NDIM * NP = " << n2[word::NDIM] * n2[word::NP]);
  SIG_VERIFY(n2[word::NE] > 0, file << ": NOP2: no element (NE = " << n2[word::NE] << ")");

  // 4. Elements and references.
  result.mesh = walk_nop5(nop5, result.nop2, std::move(nop4), file);
  // Our own NOPO in doubles, unchanged since it was written (its fingerprint above), passed
  // check_mesh in write_nopo on the very coordinates read back: its geometry (inverted cells,
  // overlaps, aspect ratios) is not checked again, the better part of a reading stage's time on
  // a large mesh (issue 27). Any other NOPO is, and so is one in 4-byte reals (rounding can
  // flatten a sliver). A file written before a check was added keeps the checks of its writer.
  if (!ours || real_bytes != 8) check_mesh(result.mesh, file);
  return result;
}

} // namespace

Mesh read_nopo(const std::filesystem::path& path) {
  return read_nopo_file(path).mesh;
}

} // namespace sig
