#pragma once
// A fresh folder under the system's temp directory for a test's files, removed with everything in
// it when the object goes. Named after the test (or a given name), the process and a counter, so
// that tests running at once and several folders in one test never meet.

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <string>

namespace safecell::test {

class ScratchFolder {
 public:
  // <temp>/safecell-<suite>-<test>-<pid>-<n>
  ScratchFolder() : ScratchFolder(current_test_name()) {}
  // <temp>/<name>-<pid>-<n>
  explicit ScratchFolder(const std::string& name)
      : path_(std::filesystem::temp_directory_path() /
              (name + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter()++))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  ScratchFolder(ScratchFolder&&) = delete;
  ScratchFolder& operator=(ScratchFolder&&) = delete;

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  [[nodiscard]] std::filesystem::path operator/(const std::string& name) const {
    return path_ / name;
  }

 private:
  static std::string current_test_name() {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    if (info == nullptr) return "safecell-test";
    return "safecell-" + std::string(info->test_suite_name()) + "-" + info->name();
  }
  static std::atomic<int>& counter() {
    static std::atomic<int> count{0};
    return count;
  }

  std::filesystem::path path_;
};

}  // namespace safecell::test
