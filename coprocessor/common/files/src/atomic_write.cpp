#include "safecell/files/atomic_write.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <optional>
#include <string>
#include <system_error>
#include <utility>

namespace safecell {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& problem) {
  throw FileError(path, problem);
}

// A file descriptor closed on every path out.
class FileHandle {
 public:
  explicit FileHandle(int fd) : fd_(fd) {}
  FileHandle(const FileHandle&) = delete;
  FileHandle& operator=(const FileHandle&) = delete;
  ~FileHandle() {
    if (fd_ >= 0) ::close(fd_);
  }
  [[nodiscard]] int get() const { return fd_; }
  // Closes now and reports whether the close succeeded.
  bool close() { return ::close(std::exchange(fd_, -1)) == 0; }

 private:
  int fd_;
};

// Creates a fresh temporary file beside `path` (O_EXCL: never one that exists already).
std::filesystem::path create_temporary(const std::filesystem::path& path, int& fd) {
  static std::atomic<unsigned> counter{0};
  const std::filesystem::path directory =
      path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::filesystem::path temporary =
        directory / ("." + path.filename().string() + ".tmp." + std::to_string(::getpid()) + "." +
                     std::to_string(counter++));
    fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) return temporary;
    if (errno != EEXIST) {
      fail(path,
           "cannot create a temporary file in " + directory.string() + ": " + std::strerror(errno));
    }
  }
  fail(path, "cannot find a free temporary file name in " + directory.string());
}

void write_all(const FileHandle& file, std::string_view text, const std::filesystem::path& path) {
  while (!text.empty()) {
    const ssize_t written = ::write(file.get(), text.data(), text.size());
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) fail(path, std::string("write error: ") + std::strerror(errno));
    text.remove_prefix(static_cast<std::size_t>(written));
  }
}

// The id of the process that wrote `name` if it is one of create_temporary()'s files
// (".<file name>.tmp.<pid>.<n>"), else nullopt.
std::optional<pid_t> writer_of(const std::string& name) {
  const std::size_t tmp = name.rfind(".tmp.");
  if (name.empty() || name[0] != '.' || tmp == std::string::npos || tmp == 0) return std::nullopt;
  const char* begin = name.data() + tmp + 5;
  const char* end = name.data() + name.size();
  pid_t pid = 0;
  unsigned counter = 0;
  const auto [dot, pid_error] = std::from_chars(begin, end, pid);
  if (pid_error != std::errc{} || dot == end || *dot != '.' || pid <= 0) return std::nullopt;
  const auto [stop, counter_error] = std::from_chars(dot + 1, end, counter);
  if (counter_error != std::errc{} || stop != end) return std::nullopt;
  return pid;
}

}  // namespace

void remove_stale_temporaries(const std::filesystem::path& directory) {
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directory, error)) {
    const auto pid = writer_of(entry.path().filename().string());
    // Only a writer that no longer exists: a running one (or one whose id was reused) keeps it.
    if (pid && *pid != ::getpid() && ::kill(*pid, 0) != 0 && errno == ESRCH) {
      std::error_code ignored;
      std::filesystem::remove(entry.path(), ignored);
    }
  }
}

void sync_directory(const std::filesystem::path& directory) {
  const FileHandle handle(::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (handle.get() >= 0) static_cast<void>(::fsync(handle.get()));
}

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
  remove_stale_temporaries(path.has_parent_path() ? path.parent_path()
                                                  : std::filesystem::path("."));
  int fd = -1;
  const std::filesystem::path temporary = create_temporary(path, fd);
  try {
    FileHandle file(fd);
    write_all(file, bytes, path);
    if (::fsync(file.get()) != 0) fail(path, std::string("fsync failed: ") + std::strerror(errno));
    if (!file.close()) fail(path, std::string("close failed: ") + std::strerror(errno));
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) fail(path, "cannot replace it: " + error.message());
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
  sync_directory(temporary.parent_path());
}

}  // namespace safecell
