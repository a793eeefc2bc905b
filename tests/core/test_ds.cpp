// The DS container: round trips, the documented byte layout, and that every kind of damage
// (flipped bytes, truncation, absurd sizes, wrong type) is an error naming the file and array.
#include "core/ds.hpp"
#include "core/error.hpp"
#include "scratch_folder.hpp"

#include <cmath>
#include <csignal>
#include <cstring>
#include <gtest/gtest.h>
#include <limits>
#include <sys/resource.h>

namespace sig {
namespace {

using sig::testing::ScratchFolder;
using sig::testing::slurp;
using sig::testing::spit;

constexpr std::size_t header_offset = 16;       // after magic, version, array count
constexpr std::size_t first_array_offset = 148; // + 128 header bytes + CRC

template <class T> T read_at(const std::string& bytes, std::size_t offset) {
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof value);
  return value;
}

template <class T> void write_at(std::string& bytes, std::size_t offset, T value) {
  std::memcpy(bytes.data() + offset, &value, sizeof value);
}

// Offset of the record of the array called `name` (its name field) in a DS file.
std::size_t record_offset(const std::string& bytes, const std::string& name) {
  std::string field(24, '\0');
  field.replace(0, name.size(), name);
  const auto at = bytes.find(field, first_array_offset);
  EXPECT_NE(at, std::string::npos) << name;
  return at;
}

std::size_t payload_offset(const std::string& bytes, const std::string& name) {
  const auto at = record_offset(bytes, name);
  const auto rank = read_at<std::uint32_t>(bytes, at + 28);
  return at + 24 + 4 + 4 + 8 * rank + 8;
}

Ds sample_ds() {
  Ds ds("TAE", "Hertz contact, half disc N=8", "sig-assemble");
  ds.header.level = 3;
  const std::vector<double> f = {0.5, -2.25, 1e-300};
  const std::vector<std::int64_t> rows = {1, 4, 9, 16};
  std::vector<double> k(12);
  for (std::size_t i = 0; i < k.size(); ++i)
    k[i] = 1.0 / (1.0 + static_cast<double>(i));
  ds.put("f", f);
  ds.put("K_rows", rows);
  ds.put("K_val", k, {3, 4});
  ds.put_text("law", "hooke plane strain");
  return ds;
}

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(DS, RoundTripOfEveryTypeAndShape) {
  ScratchFolder dir;
  Ds ds("B", "", "sig-solve");
  const std::vector<double> reals = {0.0,
                                     -0.0,
                                     1.0 / 3.0,
                                     -1e308,
                                     std::numeric_limits<double>::denorm_min(),
                                     std::numeric_limits<double>::infinity(),
                                     std::numeric_limits<double>::quiet_NaN()};
  const std::vector<std::int64_t> ints = {
      0, -1, 1, std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::max(),
      6};
  const std::string text("UTF-8 \xc3\xa9t\xc3\xa9, a NUL \0 and a newline\n", 36);
  ds.put("reals", reals, {}, Finite::not_required); // the container holds any double
  ds.put("grid", ints, {2, 3});
  ds.put("cube", std::vector<double>(24, 2.5), {2, 3, 4});
  ds.put("none", std::vector<double>{}, {0, 5});
  ds.put("no_ints", std::vector<std::int64_t>{});
  ds.put_text("text", text);
  ds.put_text("empty_text", "");
  ds.put_scalar("energy", -1.25e-7);
  ds.put_int("iterations", 42);
  write_ds(dir / "case.b", ds);

  const Ds back = read_ds(dir / "case.b", "B");
  EXPECT_EQ(back.source, (dir / "case.b").string());
  ASSERT_EQ(back.arrays().size(), ds.arrays().size());
  for (std::size_t i = 0; i < ds.arrays().size(); ++i) {
    EXPECT_EQ(back.arrays()[i].name, ds.arrays()[i].name); // order kept
    EXPECT_EQ(back.arrays()[i].type, ds.arrays()[i].type);
    EXPECT_EQ(back.arrays()[i].shape, ds.arrays()[i].shape);
  }
  const auto r = back.reals_any("reals");
  ASSERT_EQ(r.size(), reals.size());
  for (std::size_t i = 0; i < r.size(); ++i)
    EXPECT_TRUE(same_bits(r[i], reals[i])) << i;
  EXPECT_EQ(back.ints("grid"), ints);
  EXPECT_EQ(back.shape("grid"), (std::vector<std::int64_t>{2, 3}));
  EXPECT_EQ(back.shape("cube"), (std::vector<std::int64_t>{2, 3, 4}));
  EXPECT_EQ(back.reals("cube"), std::vector<double>(24, 2.5));
  EXPECT_TRUE(back.reals("none").empty());
  EXPECT_EQ(back.shape("none"), (std::vector<std::int64_t>{0, 5}));
  EXPECT_TRUE(back.ints("no_ints").empty());
  EXPECT_EQ(back.shape("no_ints"), (std::vector<std::int64_t>{0}));
  EXPECT_EQ(back.text("text"), text);
  EXPECT_EQ(back.text("empty_text"), "");
  EXPECT_EQ(back.scalar("energy"), -1.25e-7);
  EXPECT_EQ(back.integer("iterations"), 42);
}

TEST(DS, HeaderFieldsRoundTrip) {
  ScratchFolder dir;
  Ds ds("MILI", std::string(80, 'T'), std::string(24, 'c'));
  ds.header.date = "26/11/22";
  ds.header.level = -7;
  write_ds(dir / "case.mili", ds);
  Ds back = read_ds(dir / "case.mili");
  EXPECT_EQ(back.header.title, std::string(80, 'T'));
  EXPECT_EQ(back.header.creator, std::string(24, 'c'));
  EXPECT_EQ(back.header.kind, "MILI");
  EXPECT_EQ(back.header.date, "26/11/22");
  EXPECT_EQ(back.header.level, -7);
  EXPECT_TRUE(back.arrays().empty());

  // Short fields come back without their blank padding; a long title is cut at 80 characters.
  Ds shorter("B", "Hertz " + std::string(100, 'x'), "sig-solve");
  write_ds(dir / "case.b", shorter);
  back = read_ds(dir / "case.b");
  EXPECT_EQ(back.header.kind, "B");
  EXPECT_EQ(back.header.creator, "sig-solve");
  EXPECT_EQ(back.header.title, ("Hertz " + std::string(100, 'x')).substr(0, 80));
  EXPECT_EQ(back.header.date.size(), 8u);
  EXPECT_EQ(back.header.date[2], '/');
  EXPECT_EQ(back.header.level, 1);
}

// The layout documented in ds.hpp, read byte by byte without read_ds.
TEST(DS, OnDiskLayoutIsTheDocumentedOne) {
  ScratchFolder dir;
  Ds ds("TAE", "Hertz", "sig-assemble");
  ds.header.date = "24/01/31";
  ds.header.level = 2;
  const std::vector<double> f = {1.5, -3.0, 0.25};
  ds.put("f", f);
  ds.put_int("n", 7);
  write_ds(dir / "case.tae", ds);
  const std::string bytes = slurp(dir / "case.tae");

  EXPECT_EQ(bytes.substr(0, 8), std::string("SIGDS\0\0\0", 8));
  EXPECT_EQ(read_at<std::uint32_t>(bytes, 8), 1u);  // format version
  EXPECT_EQ(read_at<std::uint32_t>(bytes, 12), 2u); // arrays after array 0
  const std::string words = bytes.substr(header_offset, 128);
  EXPECT_EQ(words.substr(0, 80), "Hertz" + std::string(75, ' '));         // words 1-20
  EXPECT_EQ(words.substr(80, 8), "24/01/31");                             // words 21-22
  EXPECT_EQ(words.substr(88, 24), "sig-assemble" + std::string(12, ' ')); // words 23-28
  EXPECT_EQ(words.substr(112, 4), "TAE ");                                // word 29
  EXPECT_EQ(read_at<std::int32_t>(words, 116), 2);                        // word 30: level
  EXPECT_EQ(read_at<std::int32_t>(words, 124), 2);                        // word 32: array count
  EXPECT_EQ(read_at<std::uint32_t>(bytes, 144), crc32(words.data(), 128));

  // Array "f": name[24], type, rank, shape, payload size, payload, CRC of all that.
  std::size_t at = first_array_offset;
  EXPECT_EQ(bytes.substr(at, 24), "f" + std::string(23, '\0'));
  EXPECT_EQ(read_at<std::uint32_t>(bytes, at + 24), 2u); // Float64
  EXPECT_EQ(read_at<std::uint32_t>(bytes, at + 28), 1u); // rank
  EXPECT_EQ(read_at<std::int64_t>(bytes, at + 32), 3);
  EXPECT_EQ(read_at<std::uint64_t>(bytes, at + 40), 24u);
  for (int i = 0; i < 3; ++i)
    EXPECT_EQ(read_at<double>(bytes, at + 48 + 8 * i), f[i]);
  const std::size_t record = 24 + 4 + 4 + 8 + 8 + 24;
  EXPECT_EQ(read_at<std::uint32_t>(bytes, at + record), crc32(bytes.data() + at, record));
  at += record + 4;
  EXPECT_EQ(bytes.substr(at, 24), "n" + std::string(23, '\0'));
  EXPECT_EQ(read_at<std::uint32_t>(bytes, at + 24), 1u); // Int64
  EXPECT_EQ(read_at<std::int64_t>(bytes, at + 48), 7);
  at += 24 + 4 + 4 + 8 + 8 + 8 + 4;
  EXPECT_EQ(bytes.substr(at), "ENDS");
}

TEST(DS, FlippedPayloadByteIsRejectedNamingTheArray) {
  ScratchFolder dir;
  const auto path = dir / "case.tae";
  write_ds(path, sample_ds());
  std::string bytes = slurp(path);
  bytes[payload_offset(bytes, "K_val") + 17] ^= 0x10;
  spit(path, bytes);
  try {
    read_ds(path, "TAE");
    FAIL() << "a corrupted payload was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              path.string() + ": array 'K_val': CRC mismatch (file corrupted)");
  }
}

// Every single-byte change anywhere in the file is caught: magic, sizes, names, payloads, CRCs,
// trailer.
TEST(DS, EveryFlippedByteIsRejected) {
  ScratchFolder dir;
  const auto path = dir / "case.tae";
  write_ds(path, sample_ds());
  const std::string good = slurp(path);
  for (std::size_t i = 0; i < good.size(); ++i) {
    std::string bad = good;
    bad[i] ^= 0x01;
    spit(path, bad);
    EXPECT_THROW(read_ds(path), Error) << "byte " << i;
  }
  spit(path, good);
  EXPECT_NO_THROW(read_ds(path));
}

TEST(DS, TruncationAtEveryOffsetIsRejected) {
  ScratchFolder dir;
  const auto path = dir / "case.tae";
  write_ds(path, sample_ds());
  const std::string good = slurp(path);
  for (std::size_t length = 0; length < good.size(); ++length) {
    spit(path, good.substr(0, length));
    try {
      read_ds(path);
      ADD_FAILURE() << "a file cut at " << length << " bytes was accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    }
  }
  // Cut inside the payload of K_val: 12 doubles expected.
  const std::size_t payload = payload_offset(good, "K_val");
  spit(path, good.substr(0, payload + 5));
  try {
    read_ds(path);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              path.string() + ": truncated in array 'K_val' (expected 96 bytes of data, 5 left)");
  }
  // Cut on an array boundary: only the trailer tells.
  spit(path, good.substr(0, good.size() - 4));
  EXPECT_THROW(read_ds(path), Error);
  // Extra bytes after the trailer are damage too.
  spit(path, good + "x");
  EXPECT_THROW(read_ds(path), Error);
}

// Sizes in a damaged header are checked against the file size before anything is allocated.
TEST(DS, AbsurdSizesAreRejectedWithoutAllocating) {
  ScratchFolder dir;
  const auto path = dir / "case.tae";
  write_ds(path, sample_ds());
  const std::string good = slurp(path);

  std::string bad = good;
  write_at<std::uint32_t>(bad, 12, 0xFFFFFFFFu); // array count
  spit(path, bad);
  EXPECT_THROW(read_ds(path), Error);

  // A consistent shape and payload size of 2^60 bytes: the reader must not try to allocate it.
  bad = good;
  const auto at = record_offset(bad, "f");
  write_at<std::int64_t>(bad, at + 32, std::int64_t{1} << 57);
  write_at<std::uint64_t>(bad, at + 40, std::uint64_t{1} << 60);
  spit(path, bad);
  try {
    read_ds(path);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("truncated in array 'f'"), std::string::npos) << e.what();
  }

  bad = good;
  write_at<std::int64_t>(bad, at + 32, -3); // negative extent
  spit(path, bad);
  EXPECT_THROW(read_ds(path), Error);

  bad = good;
  write_at<std::uint32_t>(bad, at + 28, 0x7FFFFFFFu); // rank
  spit(path, bad);
  EXPECT_THROW(read_ds(path), Error);

  bad = good;
  write_at<std::uint32_t>(bad, at + 24, 9u); // type
  spit(path, bad);
  EXPECT_THROW(read_ds(path), Error);
}

TEST(DS, WrongKindMagicVersionOrMissingFileAreRejected) {
  ScratchFolder dir;
  const auto path = dir / "case.tae";
  write_ds(path, sample_ds());
  try {
    read_ds(path, "MILI");
    FAIL();
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path.string()), std::string::npos);
    EXPECT_NE(what.find("'TAE'"), std::string::npos);
    EXPECT_NE(what.find("'MILI'"), std::string::npos);
  }
  EXPECT_NO_THROW(read_ds(path, "TAE"));

  std::string bytes = slurp(path);
  write_at<std::uint32_t>(bytes, 8, 2u);
  spit(path, bytes);
  EXPECT_THROW(read_ds(path), Error);

  spit(dir / "case.nopo", "This is a NOPO file, not a DS file at all");
  try {
    read_ds(dir / "case.nopo");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "case.nopo").string()), std::string::npos);
  }

  try {
    read_ds(dir / "absent.b");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "absent.b").string()), std::string::npos);
  }
}

TEST(DS, AccessorsCheckTypeAndNameTheArray) {
  ScratchFolder dir;
  write_ds(dir / "case.tae", sample_ds());
  const Ds ds = read_ds(dir / "case.tae");
  const auto expect_error = [&](auto&& call, const std::string& array) {
    try {
      call();
      ADD_FAILURE() << "no error for " << array;
    } catch (const Error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find((dir / "case.tae").string()), std::string::npos) << what;
      EXPECT_NE(what.find("'" + array + "'"), std::string::npos) << what;
    }
  };
  expect_error([&] { ds.reals("K_rows"); }, "K_rows"); // Int64 read as reals
  expect_error([&] { ds.ints("f"); }, "f");
  expect_error([&] { ds.text("f"); }, "f");
  expect_error([&] { ds.scalar("f"); }, "f"); // three values
  expect_error([&] { ds.integer("K_rows"); }, "K_rows");
  expect_error([&] { ds.reals("u"); }, "u"); // missing
  expect_error([&] { ds.shape("u"); }, "u");
  EXPECT_TRUE(ds.has("K_val"));
  EXPECT_FALSE(ds.has("u"));
  EXPECT_EQ(ds.arrays()[2].count(), 12u);
  EXPECT_EQ(ds.arrays()[3].count(), std::string("hooke plane strain").size());
}

TEST(DS, PutReplacesAndChecksShapes) {
  Ds ds("B", "t", "test");
  ds.put("u", std::vector<double>{1, 2, 3, 4});
  ds.put_int("n", 1);
  ds.put("u", std::vector<double>{5, 6}); // replaced in place, order kept
  ASSERT_EQ(ds.arrays().size(), 2u);
  EXPECT_EQ(ds.arrays()[0].name, "u");
  EXPECT_EQ(ds.reals("u"), (std::vector<double>{5, 6}));
  EXPECT_THROW(ds.put("v", std::vector<double>{1, 2, 3}, {2, 2}), Error);
  EXPECT_THROW(ds.put("", std::vector<double>{1}), Error);
  EXPECT_THROW(ds.put(std::string(24, 'a'), std::vector<double>{1}), Error);
  EXPECT_NO_THROW(ds.put(std::string(23, 'a'), std::vector<double>{1}));
  DsArray raw;
  raw.name = "odd";
  raw.type = DsType::Int64;
  raw.bytes.resize(12); // not a whole number of 8-byte values
  EXPECT_THROW(ds.put(raw), Error);
}

// In a death-test child: a file size limit makes the write fail part way; exit 3 if write_ds
// reported it as an error.
[[noreturn]] void write_with_file_size_limit(const std::filesystem::path& path, const Ds& ds,
                                             rlim_t bytes) {
  std::signal(SIGXFSZ, SIG_IGN);
  const rlimit limit{bytes, bytes};
  setrlimit(RLIMIT_FSIZE, &limit);
  try {
    write_ds(path, ds);
  } catch (const Error&) {
    std::_Exit(3);
  }
  std::_Exit(0);
}

// A failed write leaves the previous file as it was and no temporary file behind.
TEST(DS, FailedWriteLeavesTheOldFileIntact) {
  ScratchFolder dir;
  const auto path = dir / "case.tae";
  write_ds(path, sample_ds());
  const std::string old = slurp(path);
  const auto only_target_left = [&] {
    int entries = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir.path())) {
      (void)e;
      ++entries;
    }
    return entries == 1;
  };

  Ds invalid = sample_ds();
  invalid.header.kind = "TOOLONG";
  EXPECT_THROW(write_ds(path, invalid), Error);
  EXPECT_EQ(slurp(path), old);
  EXPECT_TRUE(only_target_left());

  // The temporary name is taken by a folder: the temporary file cannot be created.
  const auto blocker = dir / (".case.tae.tmp." + std::to_string(::getpid()));
  std::filesystem::create_directory(blocker);
  EXPECT_THROW(write_ds(path, Ds("TAE", "new", "test")), Error);
  EXPECT_EQ(slurp(path), old);
  std::filesystem::remove(blocker);

  // The disk fills up in the middle of the payload (file size limit in a child process).
  Ds big = sample_ds();
  big.put("big", std::vector<double>(100000, 1.0));
  EXPECT_EXIT(write_with_file_size_limit(path, big, 4096), ::testing::ExitedWithCode(3), "");
  EXPECT_EQ(slurp(path), old);
  EXPECT_TRUE(only_target_left());
  EXPECT_NO_THROW(read_ds(path, "TAE"));

  // And a good write replaces the file.
  write_ds(path, big);
  EXPECT_EQ(read_ds(path).reals("big").size(), 100000u);
  EXPECT_TRUE(only_target_left());
}

TEST(DS, WriteIntoReadOnlyFolderLeavesTheOldFileIntact) {
  if (::geteuid() == 0) GTEST_SKIP() << "root ignores folder permissions";
  ScratchFolder dir;
  const auto path = dir / "case.tae";
  write_ds(path, sample_ds());
  const std::string old = slurp(path);
  std::filesystem::permissions(dir.path(), std::filesystem::perms::owner_read |
                                               std::filesystem::perms::owner_exec);
  EXPECT_THROW(write_ds(path, Ds("TAE", "new", "test")), Error);
  std::filesystem::permissions(dir.path(), std::filesystem::perms::owner_all);
  EXPECT_EQ(slurp(path), old);
}

TEST(DS, WriteFileAtomicallyReplacesContents) {
  ScratchFolder dir;
  const auto path = dir / "table.csv";
  write_file_atomically(path, "a,b\n1,2\n");
  EXPECT_EQ(slurp(path), "a,b\n1,2\n");
  write_file_atomically(path, "");
  EXPECT_EQ(slurp(path), "");
  EXPECT_THROW(write_file_atomically(dir / "missing" / "x.csv", "x"), Error);
}

TEST(Crc, CheckValueOfTheZlibPolynomial) {
  const char* digits = "123456789";
  EXPECT_EQ(crc32(digits, 9), 0xCBF43926u);
  EXPECT_EQ(crc32(digits, 0), 0u);
  // Running CRC over pieces equals the CRC of the whole.
  EXPECT_EQ(crc32(digits + 4, 5, crc32(digits, 4)), 0xCBF43926u);
  // zlib.crc32(b"The quick brown fox jumps over the lazy dog")
  const std::string fox = "The quick brown fox jumps over the lazy dog";
  EXPECT_EQ(crc32(fox.data(), fox.size()), 0x414FA339u);
}

// Issue 27: a reader that needs a few arrays of a large DS reads those; the fingerprint is
// read_ds's, the layout is still checked, the selected arrays' CRCs too.
TEST(DS, SelectedArraysAreReadAndTheRestSkipped) {
  ScratchFolder dir;
  const auto path = dir / "case.tae";
  write_ds(path, sample_ds());
  const Ds whole = read_ds(path, "TAE");
  const Ds part = read_ds(path, "TAE", [](const std::string& name) { return name == "f"; });
  EXPECT_EQ(part.fingerprint, whole.fingerprint);
  EXPECT_EQ(part.reals("f"), whole.reals("f"));
  EXPECT_FALSE(part.has("K_val"));
  EXPECT_FALSE(part.has("law"));
  const Ds none = read_ds_record(path, "TAE", [](const std::string&) { return false; });
  EXPECT_EQ(none.fingerprint, whole.fingerprint);
  EXPECT_TRUE(none.arrays().empty());

  // A damaged payload of a selected array is caught, of a skipped one not (its reader would).
  std::string bytes = slurp(path);
  bytes[payload_offset(bytes, "K_val") + 17] ^= 0x10;
  spit(path, bytes);
  EXPECT_NO_THROW(read_ds(path, "TAE", [](const std::string& name) { return name == "f"; }));
  try {
    read_ds(path, "TAE", [](const std::string& name) { return name == "K_val"; });
    FAIL() << "a corrupted selected payload was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              path.string() + ": array 'K_val': CRC mismatch (file corrupted)");
  }
  // Truncation is caught wherever the file is cut, skipped arrays or not.
  const std::string good = slurp(path);
  for (std::size_t length = 0; length < good.size(); ++length) {
    spit(path, good.substr(0, length));
    EXPECT_THROW(read_ds(path, "TAE", [](const std::string&) { return false; }), Error)
        << "cut at " << length;
  }
  spit(path, good + "x");
  EXPECT_THROW(read_ds(path, "TAE", [](const std::string&) { return false; }), Error);
}

// The CRC folds 8 bytes a step: every length and alignment against the bit-by-bit definition.
TEST(Crc, EveryLengthAndAlignmentMatchesTheDefinition) {
  const auto reference = [](const unsigned char* p, std::size_t n) {
    std::uint32_t c = 0xFFFFFFFFu;
    for (std::size_t i = 0; i < n; ++i) {
      c ^= p[i];
      for (int k = 0; k < 8; ++k)
        c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    }
    return c ^ 0xFFFFFFFFu;
  };
  std::vector<unsigned char> bytes(4096 + 16);
  std::uint32_t state = 12345;
  for (auto& b : bytes) {
    state = state * 1103515245u + 12345u;
    b = static_cast<unsigned char>(state >> 16);
  }
  for (std::size_t offset = 0; offset < 8; ++offset)
    for (std::size_t n : {0, 1, 7, 8, 9, 15, 16, 17, 63, 64, 65, 1000, 4096})
      EXPECT_EQ(crc32(bytes.data() + offset, n), reference(bytes.data() + offset, n))
          << "offset " << offset << ", " << n << " bytes";
  // Pieces of any size continue one another.
  EXPECT_EQ(crc32(bytes.data() + 13, 4000, crc32(bytes.data(), 13)), reference(bytes.data(), 4013));
}

} // namespace
} // namespace sig

namespace sig {
namespace {

using sig::testing::ScratchFolder;
using sig::testing::slurp;

// No NaN or inf leaves a stage: write_ds refuses it (the old file kept), Ds::reals refuses a file
// that holds one anyway (written by another program, or edited: its CRC is valid), naming the
// file, the array and the value; an array declared to hold them is written and read as such.
TEST(DsFinite, NonFiniteValuesAreNeverWrittenNorHandedOut) {
  ScratchFolder dir;
  const auto path = dir / "case.hist";
  write_ds(path, sample_ds());
  const std::string old = slurp(path);

  Ds bad = sample_ds();
  bad.put("E", std::vector<double>{1.0, std::nan(""), 2.0});
  try {
    write_ds(path, bad);
    ADD_FAILURE() << "NaN written";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string() + ": array 'E': value 2 of 3 is NaN"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(slurp(path), old);

  Ds declared = sample_ds();
  declared.put("E", std::vector<double>{1.0, -INFINITY}, {}, Finite::not_required);
  write_ds(path, declared);
  const Ds back = read_ds(path);
  EXPECT_EQ(back.reals_any("E")[1], -INFINITY);
  try {
    back.reals("E");
    ADD_FAILURE() << "-inf handed out";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string() + ": array 'E': value 2 of 2 is -inf"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(back.scalar("E"), Error); // every accessor of reals checks
}

// What a killed stage leaves (its temporary, named by temporary_path) is removed by the next one;
// a temporary of a process that still runs is kept.
TEST(DsFinite, StaleTemporariesOfDeadProcessesAreRemoved) {
  ScratchFolder dir;
  const auto mine = temporary_path(dir / "case.tae");
  EXPECT_EQ(mine.filename().string(), ".case.tae.tmp." + std::to_string(::getpid()));
  // A pid that cannot run: above the kernel's pid_max (at most 2^22).
  const auto dead = dir / ".case.tae.tmp.99999999";
  const auto vtu = dir / ".hertz_0000.vtu.tmp.99999998";
  const auto other = dir / ".notes.tmp.abc"; // not a temporary of ours
  for (const auto& p : {mine, dead, vtu, other})
    testing::spit(p, "partial");
  const auto removed = remove_stale_temporaries(dir.path());
  EXPECT_EQ(removed.size(), 2u);
  EXPECT_FALSE(std::filesystem::exists(dead));
  EXPECT_FALSE(std::filesystem::exists(vtu));
  EXPECT_TRUE(std::filesystem::exists(mine)); // this process runs
  EXPECT_TRUE(std::filesystem::exists(other));
}

} // namespace
} // namespace sig
