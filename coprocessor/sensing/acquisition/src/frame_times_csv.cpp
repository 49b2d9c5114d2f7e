#include "frame_times_csv.hpp"

#include <charconv>
#include <cmath>
#include <fstream>

#include "safecell/acquisition/acquisition_error.hpp"

namespace safecell {
namespace {

// An hour of four cameras at 30 fps is some 15 MB of rows; a row names one image file.
constexpr std::uintmax_t kMaxCsvBytes = std::uintmax_t{256} << 20;
constexpr std::size_t kMaxRowBytes = 4096;

std::string without_carriage_return(std::string text) {
  if (!text.empty() && text.back() == '\r') text.pop_back();
  return text;
}

}  // namespace

std::map<std::string, FrameTime> read_frame_times_csv(const std::filesystem::path& csv) {
  std::error_code size_error;
  if (const auto bytes = std::filesystem::file_size(csv, size_error);
      !size_error && bytes > kMaxCsvBytes) {
    throw_acquisition_error(csv, 0, "file",
                            std::to_string(bytes) + " bytes, expected at most " +
                                std::to_string(kMaxCsvBytes) + " for a list of frame times");
  }
  std::ifstream in(csv);
  if (!in) throw_acquisition_error(csv, 0, "file", "cannot be read");
  std::string text;
  int line = 1;
  if (!std::getline(in, text) || without_carriage_return(text) != "file,time_s") {
    throw_acquisition_error(csv, line, "header", "expected 'file,time_s', got '" + text + "'");
  }
  std::map<std::string, FrameTime> rows;
  while (std::getline(in, text)) {
    ++line;
    if (text.size() > kMaxRowBytes) {
      throw_acquisition_error(csv, line, "row",
                              std::to_string(text.size()) + " bytes, expected at most " +
                                  std::to_string(kMaxRowBytes) + " ('file,time_s')");
    }
    text = without_carriage_return(text);
    if (text.empty()) continue;
    const std::size_t comma = text.find(',');
    if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos) {
      throw_acquisition_error(csv, line, "row", "expected 'file,time_s', got '" + text + "'");
    }
    const std::string file = text.substr(0, comma);
    const std::string time_text = text.substr(comma + 1);
    if (file.empty()) throw_acquisition_error(csv, line, "file", "empty file name");
    double time_s = 0.0;
    const char* end = time_text.data() + time_text.size();
    const auto [stop, error] = std::from_chars(time_text.data(), end, time_s);
    if (time_text.empty() || error != std::errc() || stop != end || !std::isfinite(time_s)) {
      throw_acquisition_error(csv, line, "time_s",
                              "'" + time_text + "' is not a number of seconds");
    }
    if (!rows.emplace(file, FrameTime{time_s, line}).second) {
      throw_acquisition_error(csv, line, "file",
                              "'" + file + "' is named twice (first on line " +
                                  std::to_string(rows.at(file).line) + ")");
    }
  }
  return rows;
}

}  // namespace safecell
