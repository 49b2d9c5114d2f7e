#include "safecell/acquisition/acquisition_error.hpp"

namespace safecell {

void throw_acquisition_error(const std::filesystem::path& file, int line, const std::string& field,
                             const std::string& problem) {
  std::string message = file.string();
  if (line > 0) message += ":" + std::to_string(line);
  message += ": " + field + ": " + problem;
  throw AcquisitionError(message);
}

}  // namespace safecell
