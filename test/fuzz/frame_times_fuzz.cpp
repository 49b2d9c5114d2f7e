// Any bytes as the frame_times.csv of an image folder holding 0001.png and 0002.png, read as the
// service opens a replayed camera (ImageFolderSource): the CSV reader, then its rows against the
// folder's images. A refusal is an AcquisitionError; anything else is a finding.

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "fuzz_targets.hpp"
#include "safecell/acquisition/acquisition_error.hpp"
#include "safecell/acquisition/image_folder_source.hpp"

namespace safecell::fuzz {

int frame_times(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path folder = [] {
    const std::filesystem::path made = std::filesystem::temp_directory_path() /
                                       ("safecell-fuzz-frame-times-" + std::to_string(::getpid()));
    std::filesystem::create_directories(made);
    // The images are only listed, never decoded, while the folder is opened.
    std::ofstream(made / "0001.png").put('\0');
    std::ofstream(made / "0002.png").put('\0');
    return made;
  }();
  {
    std::ofstream out(folder / "frame_times.csv", std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    const ImageFolderSource source("fuzzed", cv::Size(4, 4), folder);
    static_cast<void>(source.frame_count());
  } catch (const AcquisitionError&) {
  }
  return 0;
}

}  // namespace safecell::fuzz

SAFECELL_FUZZ_ENTRY_POINT(frame_times)
