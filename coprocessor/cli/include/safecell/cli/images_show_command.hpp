#pragma once
// `safecell images show`: the image pipeline of every camera as pictures (the paper's Figures 6
// and 7): the frame, its five feature images, the reference image made from frames of the robot
// in chosen configurations, and the blocked feature cells over the frame.

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace safecell {

struct ImagesShowOptions {
  std::string cell_path;                  // empty: the built-in default cell
  std::string q_deg = "20,40,50,0,60,0";  // the robot in the shown frame, degrees
  std::vector<std::string> humans{"1.2,-0.8,120"};
  std::string out_dir;
  std::uint64_t seed = 1;
  int reference_frames = 9;  // the paper uses 9
};

void run_images_show(const ImagesShowOptions& options, std::ostream& out);

}  // namespace safecell
