#pragma once
// A whole file's bytes, for the files read at once (cell files, incident records).

#include <filesystem>
#include <string>
#include <string_view>

namespace safecell {

// Throws FileError "<path>: cannot be read (<why>)<context>" when the file cannot be opened or
// read; `context` says what the file was wanted for (may be empty).
std::string read_file(const std::filesystem::path& path, std::string_view context = "");

}  // namespace safecell
