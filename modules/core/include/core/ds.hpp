#pragma once
// The DS container: MODULEF's "data structure" as a file. A DS is an ordered list of named,
// typed arrays; array 0 is MODULEF's 32-word header (title, date, creator, type, level).
// Every array carries a CRC-32 and every write goes to a temporary file renamed into place, so a
// reader either sees a whole, checked DS or an error naming the file and the array.
//
// Distrust of what a DS holds lives here too, so that every stage and every new array gets it
// without code of its own:
//  - Finite values: write_ds refuses a Float64 array holding NaN or inf, and Ds::reals refuses to
//    hand one out, each naming the file, the array and the value. An array that may hold them
//    (none today) is put with Finite::not_required and read with reals_any.
//  - Provenance: inside a stage (core/provenance.hpp) every DS of the case that read_ds reads,
//    and the mesh, is an input with a fingerprint; write_ds records them all in the DS it writes
//    (Text array "provenance", one line "KIND FINGERPRINT FILE" each, transitively), with the
//    deck's cards the DS depends on (one line "CARD KEYWORD FINGERPRINT VALUES" each), and
//    read_ds refuses a DS whose recorded inputs are not the files this stage reads (another
//    case's case.mili, a foreign case.nopo), naming both files, or whose recorded cards are not
//    the deck's (a stale DS), naming the card and the stage to rerun.
//  - Value ranges: readers check what a DS array means with the ranges of the card schema
//    (core/ranges.hpp), the same ranges the datafile reader enforces.
//
// On disk (little-endian):
//   "SIGDS\0\0\0" (8 bytes magic), uint32 format version, uint32 number of arrays after array 0,
//   array 0: 32 x int32 words (title 20 words, date 2, creator 6, type 1, level, state, count),
//            uint32 CRC-32 of those 128 bytes,
//   each array: char name[24] (NUL padded), uint32 type, uint32 rank, int64 shape[rank],
//               uint64 payload bytes, payload, uint32 CRC-32 of everything from name to payload,
//   "ENDS" trailer (a truncated file is caught even when it ends on an array boundary).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace sig {

enum class DsType : std::uint32_t { Int64 = 1, Float64 = 2, Text = 3 };

/// Whether a Float64 array must be finite: the rule for every result (write_ds checks it).
enum class Finite { required, not_required };

struct DsHeader {
  std::string title;   ///< up to 80 characters
  std::string date;    ///< 8 characters, "yy/mm/dd" as MODULEF and FreeFem write it
  std::string creator; ///< up to 24 characters: the stage that wrote the DS
  std::string kind;    ///< 4 characters: NOPO, MILI, CONT, TAE, B, HIST ...
  int level = 1;
};

/// The longest array name a DS record holds (24 bytes, NUL-terminated).
inline constexpr std::size_t kMaxArrayName = 23;
/// 1 to kMaxArrayName characters, no NUL: what the file format can store.
bool is_valid_array_name(const std::string& name);

struct DsArray {
  std::string name; ///< is_valid_array_name
  DsType type = DsType::Float64;
  std::vector<std::int64_t> shape; ///< product = number of values; rank 1 when not given
  std::vector<char> bytes;         ///< raw little-endian payload
  /// In memory only: write_ds refuses NaN and inf in a Float64 array unless this is
  /// Finite::not_required (readers choose with Ds::reals or Ds::reals_any).
  Finite finite = Finite::required;
  std::size_t count() const; ///< number of values (characters for Text)
};

class Ds {
public:
  Ds() = default;
  Ds(std::string kind, std::string title, std::string creator);

  DsHeader header;
  std::string source; ///< file it was read from; empty for a DS built in memory
  /// Of the arrays (header excluded), set by read_ds: what a DS built from this one records in
  /// its provenance. 0 for a DS built in memory.
  std::uint64_t fingerprint = 0;

  // Writers replace an array of the same name. Shape empty = rank 1 of the data size.
  void put(const std::string& name, std::span<const double> values,
           std::vector<std::int64_t> shape = {}, Finite finite = Finite::required);
  void put(const std::string& name, std::span<const std::int64_t> values,
           std::vector<std::int64_t> shape = {});
  void put_text(const std::string& name, const std::string& text);
  void put_scalar(const std::string& name, double value);
  void put_int(const std::string& name, std::int64_t value);
  /// Insert or replace a raw array (name, type, shape and payload size are checked).
  void put(DsArray array);

  bool has(const std::string& name) const;
  // Readers throw sig::Error naming the DS file and the array if it is missing or of another type.
  /// The values, every one finite (else an error naming the file, the array and the value).
  std::vector<double> reals(const std::string& name) const;
  /// The values, NaN and inf included: for arrays put with Finite::not_required.
  std::vector<double> reals_any(const std::string& name) const;
  std::vector<std::int64_t> ints(const std::string& name) const;
  std::string text(const std::string& name) const;
  double scalar(const std::string& name) const;
  std::int64_t integer(const std::string& name) const;
  const std::vector<std::int64_t>& shape(const std::string& name) const;
  const std::vector<DsArray>& arrays() const { return arrays_; }

private:
  const DsArray& find(const std::string& name, DsType type) const;
  std::vector<DsArray> arrays_;
};

/// Write to `path` atomically: a temporary file in the same folder, flushed, then renamed.
/// Refuses (writing nothing) a Float64 array holding NaN or inf unless put with
/// Finite::not_required. Inside a stage, adds the array "provenance" (core/provenance.hpp).
/// `before_rename` as AtomicFile's (core/atomic_file.hpp): it runs with the temporary whole.
void write_ds(const std::filesystem::path& path, const Ds& ds,
              const std::function<void()>& before_rename = {});

/// Read and check magic, version, every CRC and the trailer; if `expected_kind` is not empty the
/// header type must match. Errors name the file and the array. Inside a stage, a DS of the case
/// is also checked against the other inputs of the stage (core/provenance.hpp).
Ds read_ds(const std::filesystem::path& path, const std::string& expected_kind = "");

/// read_ds without registering the DS as an input of the case: a record kept beside another file
/// (core/provenance.hpp), a case's files looked at from outside (core/stale.hpp).
Ds read_ds_record(const std::filesystem::path& path, const std::string& expected_kind = "");

/// The arrays a reader takes from a DS (by name); the others it skips on disk.
using DsSelection = std::function<bool(const std::string& name)>;

/// read_ds of only the arrays `wanted` selects (and "provenance", always): a stage that needs
/// a few kB of a DS of hundreds of MB (sig-post's loads from case.tae) reads those. The whole
/// file is still checked for its layout (magic, version, every record's name, type, shape and
/// size against what the file holds, the trailer), the selected arrays for their CRC; a skipped
/// array's stored CRC enters the fingerprint as read_ds folds it (the same fingerprint), unchecked
/// against its payload. Asking the Ds for an array not selected is an error saying "missing".
Ds read_ds(const std::filesystem::path& path, const std::string& expected_kind,
           const DsSelection& wanted);

/// read_ds_record of the selected arrays only (core/stale.hpp: a fingerprint, a provenance).
Ds read_ds_record(const std::filesystem::path& path, const std::string& expected_kind,
                  const DsSelection& wanted);

/// The same checks on the bytes of a file called `name` (tests, fuzzing); registers no input.
Ds parse_ds(const std::string& name, std::string bytes, const std::string& expected_kind = "");

/// Replace `path` with `contents` atomically (temporary file + rename); for text outputs
/// (CSV, JSON, reports) so that a killed stage leaves the previous file intact.
void write_file_atomically(const std::filesystem::path& path, const std::string& contents);

/// Every file written atomically (DS, NOPO, text) is synced, its data and its folder's entry,
/// before it counts as written: whole on disk even after a crash of the machine. A process that
/// writes many small files of one computation may defer that: after defer_file_syncs() files are
/// still renamed into place complete (no reader, and no killed stage, sees half of one) but not
/// synced one by one, and sync_deferred_files() makes every one durable with one syncfs of the
/// file system of `folder`. The adaptive loop (sig-adapt) does so once a step: some 20 files a
/// step, each fsync of a file and its folder 3-4 ms on the shared machine (measured: 0.46 s of
/// a 0.5 s loop of 7 steps), where the stages' work is a few ms.
void defer_file_syncs();
void sync_deferred_files(const std::filesystem::path& folder);

/// CRC-32 (IEEE 802.3, the zlib polynomial).
std::uint32_t crc32(const void* data, std::size_t size, std::uint32_t crc = 0);

/// 64-bit FNV-1a, continued from `hash` (fingerprints: of the mesh, of a DS's arrays).
std::uint64_t fnv1a64(const void* data, std::size_t size,
                      std::uint64_t hash = 0xcbf29ce484222325ull);
/// A fingerprint as 16 lower-case hex digits.
std::string fingerprint_text(std::uint64_t fingerprint);

/// The hidden temporary name under which a file is written before it is renamed over `target`
/// (".NAME.tmp.PID" in the same folder). Everything that writes atomically uses it, so that
/// remove_stale_temporaries finds what a killed stage left.
std::filesystem::path temporary_path(const std::filesystem::path& target);
/// Remove the temporaries (temporary_path: files, and the scratch folders of TemporaryFolder) in
/// `folder` whose process no longer runs; returns their names. Stages call it when they start
/// (parse_stage_args).
std::vector<std::string> remove_stale_temporaries(const std::filesystem::path& folder);

/// For the test suite: when $SIG_STOP_WRITING is the file name of `target`, the process stops
/// itself (SIGSTOP) here, with the temporary of `target` half written, so that a test can kill it
/// at a point known to be mid-write (tests/pipeline/killed_stage.sh). Writers call it once the
/// temporary holds data but before it is renamed.
void stop_point_for_tests(const std::filesystem::path& target);

} // namespace sig
