#pragma once
// A fresh directory for a camera test's files, removed with everything in it at the end.

#include <unistd.h>

#include <filesystem>
#include <string>

namespace safecell {

class TempDirectory {
 public:
  TempDirectory() {
    static int counter = 0;
    path_ =
        std::filesystem::temp_directory_path() /
        ("safecell-camera-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  TempDirectory(const TempDirectory&) = delete;
  TempDirectory& operator=(const TempDirectory&) = delete;
  ~TempDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace safecell
