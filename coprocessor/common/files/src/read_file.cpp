#include "safecell/files/read_file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "safecell/files/atomic_write.hpp"

namespace safecell {

std::string read_file(const std::filesystem::path& path, std::string_view context) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw FileError(
        path, std::string("cannot be read (") + std::strerror(errno) + ")" + std::string(context));
  }
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) throw FileError(path, "read error" + std::string(context));
  return bytes.str();
}

}  // namespace safecell
