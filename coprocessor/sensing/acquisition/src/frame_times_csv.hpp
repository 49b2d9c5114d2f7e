#pragma once
// The sidecar CSV of an image folder: when each image was exposed. The format:
//   file,time_s
//   0001.png,12.500
//   0002.png,12.533
// a header line exactly "file,time_s", then one row per image: the file name (inside the folder,
// no commas) and the exposure time in seconds on any clock that increases. Blank lines are
// skipped; nothing else is allowed.

#include <filesystem>
#include <map>
#include <string>

namespace safecell {

struct FrameTime {
  double time_s = 0.0;
  int line = 0;  // the CSV line, for messages
};

// The rows by file name. Throws AcquisitionError "<csv>:<line>: <field>: <problem>" for an
// unreadable file, a wrong header, a row without exactly two fields, an empty file name, a time
// that is not a finite number, or a file named twice.
std::map<std::string, FrameTime> read_frame_times_csv(const std::filesystem::path& csv);

}  // namespace safecell
