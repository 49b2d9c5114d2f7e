#include "safecell/files/atomic_write.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <sstream>
#include <string>

namespace safecell {
namespace {

std::string contents(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

class AtomicWrite : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ =
        std::filesystem::temp_directory_path() /
        ("safecell-atomic-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
         "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(directory_);
    std::filesystem::create_directories(directory_);
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  std::size_t files_in_directory() const {
    std::size_t count = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(directory_))
      ++count;
    return count;
  }

  std::filesystem::path directory_;
};

TEST_F(AtomicWrite, CreatesAndReplacesWithoutLeavingTemporaries) {
  const auto path = directory_ / "map.bin";
  write_file_atomically(path, std::string("first\0binary", 12));
  EXPECT_EQ(contents(path), std::string("first\0binary", 12));
  write_file_atomically(path, "second");
  EXPECT_EQ(contents(path), "second");
  EXPECT_EQ(files_in_directory(), 1u);
}

TEST_F(AtomicWrite, FailureNamesThePathAndKeepsTheOldFile) {
  const auto missing = directory_ / "no-such-folder" / "x.png";
  try {
    write_file_atomically(missing, "data");
    FAIL() << "no error";
  } catch (const FileError& error) {
    EXPECT_EQ(std::string(error.what()).rfind(missing.string() + ": ", 0), 0u) << error.what();
  }
  // A directory in the way of the rename: the old entry survives and no temporary is left.
  const auto blocked = directory_ / "blocked";
  std::filesystem::create_directories(blocked / "inside");
  EXPECT_THROW(write_file_atomically(blocked, "data"), FileError);
  EXPECT_TRUE(std::filesystem::is_directory(blocked));
  EXPECT_EQ(files_in_directory(), 1u);
}

// A writer killed while writing leaves its temporary file: the next write in the folder removes it,
// but never one whose writer still runs, nor a file that only looks alike.
TEST_F(AtomicWrite, TemporariesOfKilledWritersAreRemovedThoseOfLiveOnesKept) {
  const pid_t dead = ::fork();
  ASSERT_GE(dead, 0);
  if (dead == 0) ::_exit(0);
  ::waitpid(dead, nullptr, 0);  // reaped: its id names no process now
  const auto stale = directory_ / (".0x1234.sclut.tmp." + std::to_string(dead) + ".0");
  const auto live = directory_ / (".0x1234.sclut.tmp." + std::to_string(::getppid()) + ".3");
  const auto alike = directory_ / (".notes.tmp." + std::to_string(dead) + ".x");
  for (const auto& path : {stale, live, alike}) std::ofstream(path) << "partial";
  write_file_atomically(directory_ / "other.sclut", "tables");
  EXPECT_FALSE(std::filesystem::exists(stale));
  EXPECT_TRUE(std::filesystem::exists(live));
  EXPECT_TRUE(std::filesystem::exists(alike));
  EXPECT_EQ(files_in_directory(), 3u);
}

}  // namespace
}  // namespace safecell
