// The fuzz targets' kept corpora, replayed with the normal tests (every build, sanitizers too):
// a fix found by fuzzing stays fixed. New findings go into test/fuzz/corpus/<target>/.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz_targets.hpp"

namespace safecell {
namespace {

namespace fs = std::filesystem;

std::vector<std::vector<std::uint8_t>> corpus_of(const std::string& target) {
  std::vector<std::vector<std::uint8_t>> inputs;
  for (const auto& entry : fs::directory_iterator(fs::path(SAFECELL_FUZZ_CORPUS) / target)) {
    std::ifstream in(entry.path(), std::ios::binary);
    inputs.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  return inputs;
}

void replay(const std::string& target, int (*run)(const std::uint8_t*, std::size_t)) {
  const auto inputs = corpus_of(target);
  ASSERT_FALSE(inputs.empty()) << "no corpus for " << target;
  for (const auto& input : inputs) {
    EXPECT_EQ(run(input.data(), input.size()), 0);
    // Every prefix too: truncation is the commonest damage.
    for (std::size_t cut = 0; cut < input.size(); cut += 1 + input.size() / 16) {
      EXPECT_EQ(run(input.data(), cut), 0);
    }
  }
}

TEST(FuzzCorpus, FrameChecker) { replay("frame_checker", &fuzz::frame_checker); }
TEST(FuzzCorpus, NanopbDecode) { replay("nanopb_decode", &fuzz::nanopb_decode); }
TEST(FuzzCorpus, MapChunkApply) { replay("map_chunk_apply", &fuzz::map_chunk_apply); }
#ifdef SAFECELL_FUZZ_FILE_LOADERS
TEST(FuzzCorpus, CellFile) { replay("cell_file", &fuzz::cell_file); }
TEST(FuzzCorpus, Urdf) { replay("urdf", &fuzz::urdf); }
TEST(FuzzCorpus, Calibration) { replay("calibration", &fuzz::calibration); }
TEST(FuzzCorpus, ControllerConfig) { replay("controller_config", &fuzz::controller_config); }
TEST(FuzzCorpus, LutFile) { replay("lut_file", &fuzz::lut_file); }
TEST(FuzzCorpus, FrameTimes) { replay("frame_times", &fuzz::frame_times); }
#endif

}  // namespace
}  // namespace safecell
