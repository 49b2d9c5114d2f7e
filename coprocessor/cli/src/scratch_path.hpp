#pragma once
// A path in the temporary folder named after its use and this process (safecell-WHAT-PID), and
// removed with all it holds when the object goes: the benchmarks' map files and the controller's
// scratch folder. Private to the CLI.

#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace safecell {

class ScratchPath {
 public:
  explicit ScratchPath(const std::string& what)
      : path_(std::filesystem::temp_directory_path() /
              ("safecell-" + what + "-" + std::to_string(getpid()))) {}
  ScratchPath(const ScratchPath&) = delete;
  ScratchPath& operator=(const ScratchPath&) = delete;
  ~ScratchPath() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace safecell
