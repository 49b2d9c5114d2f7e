// A controller trace read back: every event kind, the held map's session carried to the cycles,
// a last line cut short by a kill left out, and a broken line in the middle named.

#include "safecell/campaign/controller_trace.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "safecell/files/atomic_write.hpp"
#include "safecell/test/scratch_folder.hpp"

namespace safecell {
namespace {

constexpr const char* kTrace =
    R"({"e":"cycle","t":100,"state":"waiting","fault":"none","link":"no session","scale":0.000,"map":0,"speed":0.000}
{"e":"map","t":200,"session":"00000000000000ff","version":1,"hash":"0123456789abcdef","degraded":0}
{"e":"cycle","t":200,"state":"moving","fault":"none","link":"none","scale":0.840,"map":1,"speed":0.410}
{"e":"link_error","t":300,"error":"loss","detail":3,"errors":1,"latched":false}
{"e":"map_refused","t":320,"reason":"map hash mismatch","refused":1}
{"e":"stop_request","t":350,"cause":"operator"}
{"e":"acknowledged","t":400}
{"e":"stop_request_cleared","t":400}
{"e":"cycle","t":450,"state":"moving","fault":"none","link":"none","scale":null,"map":1,"speed":null}
)";

TEST(ControllerTrace, EveryEventIsReadBack) {
  const test::ScratchFolder scratch("trace");
  const auto file = scratch.path() / "trace.jsonl";
  std::ofstream(file) << kTrace;
  const ControllerTrace trace = read_controller_trace(file);
  ASSERT_EQ(trace.cycles.size(), 3U);
  EXPECT_EQ(trace.cycles[0].link, "no session");
  EXPECT_FALSE(trace.cycles[0].commands_motion());
  EXPECT_TRUE(trace.cycles[1].commands_motion());
  // A scale the controller could not state is not a hold.
  EXPECT_TRUE(trace.cycles[2].commands_motion());
  EXPECT_DOUBLE_EQ(trace.cycles[1].scale, 0.84);
  EXPECT_EQ(trace.cycles[1].session, 0xFFU);
  ASSERT_EQ(trace.maps.size(), 1U);
  EXPECT_EQ(trace.maps[0].hash, 0x0123456789ABCDEFULL);
  ASSERT_EQ(trace.link_errors.size(), 1U);
  EXPECT_EQ(trace.link_errors[0].error, "loss");
  EXPECT_EQ(trace.link_errors[0].errors_so_far, 1U);
  ASSERT_EQ(trace.map_refusals.size(), 1U);
  EXPECT_EQ(trace.map_refusals[0].reason, "map hash mismatch");
  EXPECT_EQ(trace.acknowledged_ns, std::vector<std::uint64_t>{400});
  ASSERT_EQ(trace.stop_requests.size(), 1U);
  EXPECT_EQ(trace.stop_requests[0].cause, "operator");
}

TEST(ControllerTrace, ALastLineCutShortByAKillIsLeftOut) {
  const test::ScratchFolder scratch("trace");
  const auto file = scratch.path() / "trace.jsonl";
  std::ofstream(file) << kTrace << R"({"e":"cycle","t":500,"state":"mov)";
  EXPECT_EQ(read_controller_trace(file).cycles.size(), 3U);
}

TEST(ControllerTrace, ABrokenLineIsNamed) {
  const test::ScratchFolder scratch("trace");
  const auto file = scratch.path() / "trace.jsonl";
  std::ofstream(file) << R"({"e":"cycle","t":1})"
                      << "\n"
                      << kTrace;
  try {
    (void)read_controller_trace(file);
    FAIL() << "a cycle line without its fields was read";
  } catch (const FileError& error) {
    EXPECT_NE(std::string(error.what()).find("line 1"), std::string::npos) << error.what();
  }
  EXPECT_THROW((void)read_controller_trace(scratch.path() / "missing.jsonl"), FileError);
}

}  // namespace
}  // namespace safecell
