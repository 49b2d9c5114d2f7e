#pragma once
// `safecell camera import`: a calibration made with another tool turned into this project's
// calibration files, which a cell file's `calibration:` names. A ROS camera_info file gives one
// camera's lens, placed in the cell by a pose file; an MC-Calib result gives every camera of the
// rig, placed by the cell pose of its reference camera (camera 0).

#include <ostream>
#include <string>

namespace safecell {

struct CameraImportOptions {
  std::string ros_file;       // a ROS camera_info YAML file; or
  std::string mc_calib_file;  // an MC-Calib calibrated_cameras_data.yml
  // The pose file (this project's calibration format with only the cell_to_camera keys): of the
  // camera itself for ROS, of the reference camera for MC-Calib.
  std::string pose_file;
  // MC-Calib: metres per unit of its translations (its board's unit). Required: MC-Calib does
  // not record the unit, and a wrong guess puts the cameras 10 or 1,000 times off. 0: not given.
  double units_m = 0.0;
  std::string name = "cam";  // the camera's name (ROS) or the names' stem (MC-Calib: cam0, cam1...)
  std::string out;           // ROS: the file to write; MC-Calib: the folder for <name><N>.yaml
};

// Writes the files atomically and says what it wrote, with where each camera stands in the cell.
void run_camera_import(const CameraImportOptions& options, std::ostream& out);

}  // namespace safecell
