#include "atomic_file.hpp"
#include "core/ds.hpp"
#include "core/ds_stream.hpp"
#include "core/error.hpp"
#include "core/finite.hpp"
#include "core/input_file.hpp"
#include "core/phase_times.hpp"
#include "core/provenance.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

namespace sig {

// Payloads are copied as they lie in memory; the format is little-endian (ds.hpp).
static_assert(std::endian::native == std::endian::little, "DS I/O assumes a little-endian host");

namespace {
constexpr char magic[8] = {'S', 'I', 'G', 'D', 'S', '\0', '\0', '\0'};
constexpr char trailer[4] = {'E', 'N', 'D', 'S'};
constexpr std::uint32_t format_version = 1;
constexpr std::size_t header_words = 32;
constexpr std::size_t name_bytes = 24;
constexpr std::uint32_t max_rank = 8;
// Smallest array on disk: name, type, rank, payload size, CRC (no shape, no payload).
constexpr std::uint64_t min_array_bytes = name_bytes + 4 + 4 + 8 + 4;

// MODULEF stores text in integer words, 4 characters each, blank padded.
void put_chars(std::array<std::int32_t, header_words>& words, std::size_t first_word,
               std::size_t n_chars, const std::string& text) {
  std::string padded = text.substr(0, n_chars);
  padded.resize(n_chars, ' ');
  std::memcpy(&words[first_word], padded.data(), n_chars);
}

std::string get_chars(const std::array<std::int32_t, header_words>& words, std::size_t first_word,
                      std::size_t n_chars) {
  std::string text(n_chars, '\0');
  std::memcpy(text.data(), &words[first_word], n_chars);
  const auto end = text.find_last_not_of(std::string(" \0", 2));
  return end == std::string::npos ? std::string() : text.substr(0, end + 1);
}

std::size_t value_size(DsType type) {
  return type == DsType::Text ? 1 : 8;
}

// Field lengths are MODULEF's; a title is cut (decks may have long ones), the rest are names the
// code chooses and must fit.
void check_writable(const std::filesystem::path& path, const Ds& ds) {
  const std::string p = path.string();
  SIG_VERIFY(ds.header.creator.size() <= 24,
             p << ": DS creator '" << ds.header.creator << "' is longer than 24 characters");
  SIG_VERIFY(!ds.header.kind.empty() && ds.header.kind.size() <= 4,
             p << ": DS type '" << ds.header.kind << "' must have 1 to 4 characters");
  SIG_VERIFY(ds.header.date.size() <= 8,
             p << ": DS date '" << ds.header.date << "' is longer than 8 characters");
  std::set<std::string> names;
  for (const auto& a : ds.arrays()) {
    SIG_VERIFY(is_valid_array_name(a.name), p << ": array '" << a.name << "': name must have 1 to "
                                              << kMaxArrayName << " characters");
    SIG_VERIFY(names.insert(a.name).second, p << ": array '" << a.name << "': name repeated");
    SIG_VERIFY(a.type == DsType::Int64 || a.type == DsType::Float64 || a.type == DsType::Text,
               p << ": array '" << a.name << "': unknown type "
                 << static_cast<std::uint32_t>(a.type));
    SIG_VERIFY(a.shape.size() <= max_rank,
               p << ": array '" << a.name << "': rank " << a.shape.size() << " above " << max_rank);
    std::int64_t product = 1;
    for (auto n : a.shape)
      product = n < 0 ? -1 : product * n;
    const auto expected = a.shape.empty() ? a.count() : static_cast<std::size_t>(product);
    SIG_VERIFY(product >= 0 && a.bytes.size() == expected * value_size(a.type),
               p << ": array '" << a.name << "': " << a.bytes.size()
                 << " payload bytes do not match its shape");
    if (a.type == DsType::Float64 && a.finite == Finite::required) {
      const std::string bad = first_non_finite(std::span<const double>(
          reinterpret_cast<const double*>(a.bytes.data()), a.bytes.size() / sizeof(double)));
      SIG_VERIFY(bad.empty(), p << ": array '" << a.name << "': " << bad
                                << ": a non-finite result is never written (the file is left as "
                                   "it was)");
    }
  }
}

constexpr const char* provenance_array = "provenance";

// Folds the CRC of each array record into the DS fingerprint (header excluded, so that a title
// or a date does not make the same arrays another DS).
std::uint64_t fold_fingerprint(std::uint64_t fingerprint, std::uint32_t record_crc) {
  return fnv1a64(&record_crc, sizeof record_crc, fingerprint);
}

// Writes through to the file while keeping the running CRC of the current record.
class DsWriter {
public:
  explicit DsWriter(AtomicFile& file) : file_(file) {}
  void raw(const void* data, std::size_t size) { file_.write(data, size); }
  void checked(const void* data, std::size_t size) {
    crc_ = crc32(data, size, crc_);
    file_.write(data, size);
  }
  template <class T> void checked_value(T value) { checked(&value, sizeof value); }
  void end_record() {
    raw(&crc_, sizeof crc_);
    crc_ = 0;
  }
  void write_array(const DsArray& a) {
    char name[name_bytes] = {};
    std::memcpy(name, a.name.data(), a.name.size());
    checked(name, name_bytes);
    checked_value(static_cast<std::uint32_t>(a.type));
    checked_value(static_cast<std::uint32_t>(a.shape.size()));
    for (const auto n : a.shape)
      checked_value(n);
    checked_value(static_cast<std::uint64_t>(a.bytes.size()));
    checked(a.bytes.data(), a.bytes.size());
    end_record();
  }

private:
  AtomicFile& file_;
  std::uint32_t crc_ = 0;
};

// Reads from the file with the bytes left always known, so that no size read from a damaged
// file is trusted before it is compared with what the file can still hold.
class DsReader {
public:
  explicit DsReader(const std::filesystem::path& path) : path_(path.string()) {
    verify_regular_file(path, "DS");
    std::error_code error;
    const auto size = std::filesystem::file_size(path, error);
    SIG_VERIFY(!error, path_ << ": cannot read DS: " << error.message());
    left_ = size;
    auto file = std::make_unique<std::ifstream>(path, std::ios::binary);
    SIG_VERIFY(*file, path_ << ": cannot open DS: " << std::strerror(errno));
    in_ = std::move(file);
  }
  DsReader(std::string name, std::string bytes) : path_(std::move(name)), left_(bytes.size()) {
    in_ = std::make_unique<std::istringstream>(std::move(bytes));
  }
  const std::string& path() const { return path_; }
  std::uint64_t left() const { return left_; }
  void set_context(std::string context) { context_ = std::move(context); }

  void read(void* data, std::size_t size, const char* what) {
    SIG_VERIFY(size <= left_, path_ << ": truncated in " << context_ << " (expected " << size
                                    << " bytes of " << what << ", " << left_ << " left)");
    in_->read(static_cast<char*>(data), static_cast<std::streamsize>(size));
    SIG_VERIFY(*in_, path_ << ": read error in " << context_);
    crc_ = crc32(data, size, crc_);
    left_ -= size;
  }
  /// Skip `size` bytes of an unread payload (checked against the bytes left, not CRC'd).
  void skip(std::uint64_t size, const char* what) {
    SIG_VERIFY(size <= left_, path_ << ": truncated in " << context_ << " (expected " << size
                                    << " bytes of " << what << ", " << left_ << " left)");
    in_->seekg(static_cast<std::streamoff>(size), std::ios::cur);
    SIG_VERIFY(*in_, path_ << ": read error in " << context_);
    left_ -= size;
  }
  /// The CRC stored at the end of a record whose payload was skipped: taken as it is.
  std::uint32_t stored_crc() {
    std::uint32_t stored;
    SIG_VERIFY(sizeof stored <= left_, path_ << ": truncated in " << context_ << " (expected "
                                             << sizeof stored << " bytes of CRC, " << left_
                                             << " left)");
    in_->read(reinterpret_cast<char*>(&stored), sizeof stored);
    SIG_VERIFY(*in_, path_ << ": read error in " << context_);
    left_ -= sizeof stored;
    crc_ = 0;
    return stored;
  }
  template <class T> T value(const char* what) {
    T v;
    read(&v, sizeof v, what);
    return v;
  }
  std::uint32_t check_crc() {
    const std::uint32_t computed = crc_;
    const auto stored = value<std::uint32_t>("CRC");
    SIG_VERIFY(stored == computed, path_ << ": " << context_ << ": CRC mismatch (file corrupted)");
    crc_ = 0;
    return computed;
  }
  void start_record() { crc_ = 0; }

private:
  std::string path_;
  std::string context_ = "file start";
  std::unique_ptr<std::istream> in_;
  std::uint64_t left_ = 0;
  std::uint32_t crc_ = 0;
};

DsHeader read_header(DsReader& in) {
  in.set_context("header");
  std::array<std::int32_t, header_words> words{};
  in.start_record();
  in.read(words.data(), sizeof words, "header");
  in.check_crc();
  DsHeader header;
  header.title = get_chars(words, 0, 80);
  header.date = get_chars(words, 20, 8);
  header.creator = get_chars(words, 22, 24);
  header.kind = get_chars(words, 28, 4);
  header.level = words[29];
  return header;
}

/// What a reader takes of a DS: the arrays kept (all when empty) and those streamed to `take`.
struct DsTaking {
  DsSelection wanted;
  DsSelection streamed;
  DsPieces take;
};

/// The next array, or std::nullopt when `taking` does not keep it (its payload skipped, or
/// streamed to taking.take); `array_name` is its name either way.
std::optional<DsArray> read_array(DsReader& in, std::uint32_t index, std::uint64_t& fingerprint,
                                  const DsTaking& taking, std::string& array_name) {
  const DsSelection& wanted = taking.wanted;
  in.set_context("array #" + std::to_string(index + 1));
  in.start_record();
  char name[name_bytes];
  in.read(name, name_bytes, "array name");
  DsArray array;
  array.name.assign(name, strnlen(name, name_bytes));
  in.set_context("array '" + array.name + "'");
  array_name = array.name;
  SIG_VERIFY(!array.name.empty() && name[name_bytes - 1] == '\0',
             in.path() << ": array #" << index + 1 << ": bad name (file corrupted)");
  const auto type = in.value<std::uint32_t>("type");
  SIG_VERIFY(type >= 1 && type <= 3,
             in.path() << ": array '" << array.name << "': unknown type " << type);
  array.type = static_cast<DsType>(type);
  const auto rank = in.value<std::uint32_t>("rank");
  SIG_VERIFY(rank <= max_rank, in.path() << ": array '" << array.name << "': rank " << rank
                                         << " above " << max_rank << " (file corrupted)");
  std::uint64_t count = 1;
  for (std::uint32_t k = 0; k < rank; ++k) {
    const auto n = in.value<std::int64_t>("shape");
    SIG_VERIFY(n >= 0 && !__builtin_mul_overflow(count, static_cast<std::uint64_t>(n), &count),
               in.path() << ": array '" << array.name << "': bad shape (file corrupted)");
    array.shape.push_back(n);
  }
  const auto payload = in.value<std::uint64_t>("payload size");
  std::uint64_t expected = 0;
  SIG_VERIFY(!__builtin_mul_overflow(count, value_size(array.type), &expected) &&
                 (rank == 0 ? payload % value_size(array.type) == 0 : payload == expected),
             in.path() << ": array '" << array.name << "': payload of " << payload
                       << " bytes does not match its shape (file corrupted)");
  // Compared with the bytes left before allocating: a damaged size never becomes a huge buffer.
  SIG_VERIFY(payload <= in.left(), in.path()
                                       << ": truncated in array '" << array.name << "' (expected "
                                       << payload << " bytes of data, " << in.left() << " left)");
  if (taking.streamed && taking.streamed(array.name)) {
    // Whole values per piece, so that the taker never splits one.
    const std::size_t piece = kDsPieceBytes - kDsPieceBytes % value_size(array.type);
    std::vector<char> buffer(static_cast<std::size_t>(std::min<std::uint64_t>(payload, piece)));
    for (std::uint64_t done = 0; done < payload;) {
      const auto size = static_cast<std::size_t>(std::min<std::uint64_t>(payload - done, piece));
      in.read(buffer.data(), size, "data");
      taking.take(array, buffer.data(), size);
      done += size;
    }
    fingerprint = fold_fingerprint(fingerprint, in.check_crc());
    return std::nullopt;
  }
  if (wanted && array.name != provenance_array && !wanted(array.name)) {
    in.skip(payload, "data");
    fingerprint = fold_fingerprint(fingerprint, in.stored_crc());
    return std::nullopt;
  }
  array.bytes.resize(payload);
  in.read(array.bytes.data(), payload, "data");
  fingerprint = fold_fingerprint(fingerprint, in.check_crc());
  if (rank == 0) array.shape = {static_cast<std::int64_t>(array.count())};
  return array;
}
} // namespace

void write_ds(const std::filesystem::path& path, const Ds& ds,
              const std::function<void()>& before_rename) {
  const PhaseTimer timer("write");
  check_writable(path, ds);
  // Inside a stage the DS records the inputs it was built from, replacing what it may hold.
  std::vector<const DsArray*> arrays;
  for (const DsArray& a : ds.arrays())
    if (a.name != provenance_array) arrays.push_back(&a);
  Ds stamp;
  if (const Provenance inputs = case_provenance(ds.header.kind); !inputs.empty()) {
    stamp.put_text(provenance_array, provenance_text(inputs));
    arrays.push_back(&stamp.arrays().front());
  }
  AtomicFile file(path);
  DsWriter out(file);
  out.raw(magic, sizeof magic);
  const std::uint32_t version = format_version;
  const auto n_arrays = static_cast<std::uint32_t>(arrays.size());
  out.raw(&version, sizeof version);
  out.raw(&n_arrays, sizeof n_arrays);

  std::array<std::int32_t, header_words> words{};
  put_chars(words, 0, 80, ds.header.title);
  put_chars(words, 20, 8, ds.header.date);
  put_chars(words, 22, 24, ds.header.creator);
  put_chars(words, 28, 4, ds.header.kind);
  words[29] = ds.header.level;                     // NIVEAU
  words[30] = 1;                                   // ETAT, reserved: 1 as FreeFem writes it
  words[31] = static_cast<std::int32_t>(n_arrays); // NTACM
  out.checked(words.data(), sizeof words);
  out.end_record();

  for (const DsArray* a : arrays)
    out.write_array(*a);
  out.raw(trailer, sizeof trailer);
  file.commit(before_rename);
}

namespace {
Ds read_all(DsReader& in, const std::string& expected_kind, const DsTaking& taking = {}) {
  char file_magic[sizeof magic];
  in.read(file_magic, sizeof magic, "magic");
  SIG_VERIFY(std::memcmp(file_magic, magic, sizeof magic) == 0,
             in.path() << ": not a DS file (bad magic)");
  const auto version = in.value<std::uint32_t>("format version");
  SIG_VERIFY(version == format_version, in.path()
                                            << ": DS format version " << version
                                            << ", this program reads version " << format_version);
  const auto n_arrays = in.value<std::uint32_t>("array count");
  SIG_VERIFY(n_arrays <= in.left() / min_array_bytes,
             in.path() << ": header announces " << n_arrays << " arrays, the file holds at most "
                       << in.left() / min_array_bytes << " (file corrupted or truncated)");

  Ds ds;
  ds.source = in.path();
  ds.header = read_header(in);
  if (!expected_kind.empty())
    SIG_VERIFY(ds.header.kind == expected_kind, in.path()
                                                    << ": DS type is '" << ds.header.kind
                                                    << "', expected '" << expected_kind << "'");
  std::uint64_t fingerprint = fnv1a64(nullptr, 0);
  std::set<std::string> names;
  for (std::uint32_t k = 0; k < n_arrays; ++k) {
    std::string name;
    std::optional<DsArray> array = read_array(in, k, fingerprint, taking, name);
    SIG_VERIFY(names.insert(name).second, in.path() << ": array '" << name << "': repeated");
    if (array) ds.put(std::move(*array));
  }
  in.set_context("trailer");
  char end[sizeof trailer];
  in.read(end, sizeof end, "trailer");
  SIG_VERIFY(std::memcmp(end, trailer, sizeof trailer) == 0,
             in.path() << ": missing ENDS trailer (file corrupted)");
  SIG_VERIFY(in.left() == 0, in.path()
                                 << ": " << in.left() << " unexpected bytes after the trailer");
  ds.fingerprint = fingerprint;
  return ds;
}
} // namespace

Ds read_ds(const std::filesystem::path& path, const std::string& expected_kind) {
  return read_ds(path, expected_kind, DsSelection{});
}

Ds read_ds(const std::filesystem::path& path, const std::string& expected_kind,
           const DsSelection& wanted) {
  return read_ds_streamed(path, expected_kind, wanted, {}, {});
}

Ds read_ds_record(const std::filesystem::path& path, const std::string& expected_kind) {
  return read_ds_record(path, expected_kind, DsSelection{});
}

Ds read_ds_record(const std::filesystem::path& path, const std::string& expected_kind,
                  const DsSelection& wanted) {
  return read_ds_record_streamed(path, expected_kind, wanted, {}, {});
}

Ds read_ds_record_streamed(const std::filesystem::path& path, const std::string& expected_kind,
                           const DsSelection& wanted, const DsSelection& streamed,
                           const DsPieces& take) {
  const PhaseTimer timer("read");
  SIG_VERIFY(std::filesystem::exists(path), path.string() << ": DS file not found");
  DsReader in(path);
  return read_all(in, expected_kind, {wanted, streamed, take});
}

Ds read_ds_streamed(const std::filesystem::path& path, const std::string& expected_kind,
                    const DsSelection& wanted, const DsSelection& streamed, const DsPieces& take) {
  Ds ds = read_ds_record_streamed(path, expected_kind, wanted, streamed, take);
  note_case_input(ds.header.kind, path, ds.fingerprint,
                  ds.has(provenance_array) ? parse_provenance(ds.text(provenance_array), ds.source)
                                           : Provenance{});
  return ds;
}

Ds parse_ds(const std::string& name, std::string bytes, const std::string& expected_kind) {
  DsReader in(name, std::move(bytes));
  return read_all(in, expected_kind);
}

} // namespace sig
