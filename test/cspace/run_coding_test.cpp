// The run coding of forbidden maps: published test vectors (bytes worked out by hand from the
// definition in run_coding.hpp), and hostile input refused without reading out of range.

#include "safecell/cspace/run_coding.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "safecell/test/property.hpp"

namespace safecell {
namespace {

std::vector<std::uint8_t> encode(const std::vector<CellRun>& runs, CellIndex origin) {
  std::vector<std::uint8_t> out(runs.size() * kMaxRunRecordBytes);
  RunWriter writer(out.data(), out.size(), origin);
  for (const CellRun& run : runs) EXPECT_TRUE(writer.append(run));
  out.resize(writer.size());
  return out;
}

std::vector<CellRun> decode(const std::vector<std::uint8_t>& bytes, CellIndex origin,
                            CellIndex limit, Status& ending) {
  RunReader reader(bytes.data(), bytes.size(), origin, limit);
  std::vector<CellRun> runs;
  for (;;) {
    const Result<CellRun> run = reader.next();
    if (!run.ok()) {
      ending = run.error();
      return runs;
    }
    runs.push_back(run.value());
  }
}

std::string hex(const std::vector<std::uint8_t>& bytes) {
  std::string text;
  for (const std::uint8_t byte : bytes) {
    constexpr char kDigits[] = "0123456789abcdef";
    text += kDigits[byte >> 4];
    text += kDigits[byte & 15];
  }
  return text;
}

bool same(const std::vector<CellRun>& a, const std::vector<CellRun>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].begin != b[i].begin || a[i].end != b[i].end || a[i].value != b[i].value) return false;
  }
  return true;
}

TEST(RunCoding, TestVectors) {
  // Cells 0, 5..9 and 99 forbidden: (gap 0, length 1 set) (gap 4, length 5 set) (gap 89, 1 set).
  EXPECT_EQ(encode({{0, 1, true}, {5, 10, true}, {99, 100, true}}, 0),
            (std::vector<std::uint8_t>{0x00, 0x03, 0x04, 0x0B, 0x59, 0x03}));
  // From origin 1000: cells 1000..1199 cleared (length 200: 400 = 0x190 -> 0x90 0x03), then
  // 1200..1201 set right after it (gap 0).
  EXPECT_EQ(encode({{1000, 1200, false}, {1200, 1202, true}}, 1000),
            (std::vector<std::uint8_t>{0x00, 0x90, 0x03, 0x00, 0x05}));
  // The largest run: 2^32 - 1 cells set, length-and-value 0x1FFFFFFFF in five bytes.
  EXPECT_EQ(encode({{0, 0xFFFFFFFFu, true}}, 0),
            (std::vector<std::uint8_t>{0x00, 0xFF, 0xFF, 0xFF, 0xFF, 0x1F}));
}

TEST(RunCoding, RoundTripsRandomRunLists) {
  test::PropertyRun run(300);
  for (int i = 0; i < run.iterations(); ++i) {
    const auto origin = static_cast<CellIndex>(run.rng()() % 1000000);
    std::vector<CellRun> runs;
    CellIndex at = origin;
    const int count = static_cast<int>(run.rng()() % 40);
    for (int r = 0; r < count; ++r) {
      const auto begin = static_cast<CellIndex>(at + run.rng()() % 5000);
      const auto end = static_cast<CellIndex>(begin + 1 + run.rng()() % 100000);
      runs.push_back({begin, end, run.rng()() % 2 == 0});
      at = end;
    }
    Status ending = Status::kOk;
    const std::vector<CellRun> back = decode(encode(runs, origin), origin, at, ending);
    ASSERT_EQ(ending, Status::kEmpty) << "iteration " << i << ", " << runs.size() << " runs";
    ASSERT_TRUE(same(back, runs)) << "iteration " << i << ", origin " << origin;
  }
}

TEST(RunCoding, AWriterThatIsFullWritesNothingMore) {
  std::uint8_t out[3];
  RunWriter writer(out, sizeof out, 0);
  EXPECT_TRUE(writer.append({0, 1, true}));    // 2 bytes
  EXPECT_FALSE(writer.append({5, 10, true}));  // 2 more do not fit
  EXPECT_EQ(writer.size(), 2u);
  EXPECT_EQ(writer.cursor(), 1u);
}

TEST(RunCoding, HostileRunListsAreRefused) {
  Status ending = Status::kOk;
  // Truncated: the length varint is missing, or cut inside.
  EXPECT_TRUE(decode({0x00}, 0, 100, ending).empty());
  EXPECT_EQ(ending, Status::kInvalidArgument);
  EXPECT_TRUE(decode({0x00, 0x83}, 0, 100, ending).empty());
  EXPECT_EQ(ending, Status::kInvalidArgument);
  // Over-long varint (six bytes).
  EXPECT_TRUE(decode({0x80, 0x80, 0x80, 0x80, 0x80, 0x00, 0x03}, 0, 100, ending).empty());
  EXPECT_EQ(ending, Status::kInvalidArgument);
  // A run of length zero.
  EXPECT_TRUE(decode({0x00, 0x01}, 0, 100, ending).empty());
  EXPECT_EQ(ending, Status::kInvalidArgument);
  // Past the limit, and a gap that would overflow 32 bits.
  EXPECT_TRUE(decode({0x63, 0x05}, 0, 100, ending).empty());
  EXPECT_EQ(ending, Status::kOutOfRange);
  EXPECT_TRUE(decode({0xFF, 0xFF, 0xFF, 0xFF, 0x0F, 0x03}, 10, 0xFFFFFFFFu, ending).empty());
  EXPECT_EQ(ending, Status::kOutOfRange);
  // Valid runs before the bad record are returned; the error still ends the list.
  EXPECT_EQ(decode({0x00, 0x03, 0x00}, 0, 100, ending).size(), 1u);
  EXPECT_EQ(ending, Status::kInvalidArgument);
}

// Random bytes: the reader never reads past its input (ASan) and every run it returns lies
// within the limit, in order.
TEST(RunCoding, RandomBytesNeverEscapeTheLimit) {
  test::PropertyRun run(2000);
  for (int i = 0; i < run.iterations(); ++i) {
    std::vector<std::uint8_t> bytes(run.rng()() % 24);
    for (auto& byte : bytes) byte = static_cast<std::uint8_t>(run.rng()());
    Status ending = Status::kOk;
    CellIndex previous_end = 7;
    for (const CellRun& r : decode(bytes, 7, 5000, ending)) {
      ASSERT_GE(r.begin, previous_end) << "bytes " << hex(bytes);
      ASSERT_GT(r.end, r.begin) << "bytes " << hex(bytes);
      ASSERT_LE(r.end, 5000u) << "bytes " << hex(bytes);
      previous_end = r.end;
    }
    ASSERT_NE(ending, Status::kOk) << "bytes " << hex(bytes);
  }
}

}  // namespace
}  // namespace safecell
