#pragma once
// Replacing a file so that readers see the old contents or the new, never a part, and a crash
// or power cut loses neither.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "safecell/errors/input_error.hpp"

namespace safecell {

// "<path>: <problem>"; problem() alone for callers that name the path their own way.
class FileError : public InputError {
 public:
  FileError(const std::filesystem::path& path, std::string problem)
      : InputError(path.string() + ": " + problem), problem_(std::move(problem)) {}
  const std::string& problem() const { return problem_; }

 private:
  std::string problem_;
};

// Writes `bytes` to a new temporary file beside `path`, flushes it to disk, and renames it over
// `path`. Throws FileError ("<path>: <problem>") on failure; the temporary file is then removed.
// Temporary files left in its folder by writers that were killed are removed first.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

// Removes the temporary files of write_file_atomically() in `directory` (".<name>.tmp.<pid>.<n>")
// whose writing process no longer exists: what a killed writer left. A file another running
// process writes is kept.
void remove_stale_temporaries(const std::filesystem::path& directory);

// Flushes a directory's entries (files and folders created or renamed in it) to disk, so that
// they survive a power cut; best effort, as not every file system allows it.
void sync_directory(const std::filesystem::path& directory);

}  // namespace safecell
