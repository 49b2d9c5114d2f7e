#include "safecell/cli/camera_import_command.hpp"

#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>

#include "command_line.hpp"
#include "safecell/camera/calibration_file.hpp"
#include "safecell/camera/calibration_import.hpp"
#include "safecell/cli/text_table.hpp"
#include "scene_options.hpp"

namespace safecell {
namespace {

namespace fs = std::filesystem;

void say_written(const fs::path& file, const PinholeCamera& camera, std::ostream& out) {
  const Eigen::Vector3d at = camera.position_m();
  const Eigen::Vector3d axis = camera.camera_to_cell().linear().col(2);
  out << "wrote " << file.string() << ": camera '" << camera.name() << "', "
      << camera.intrinsics().width_px << " x " << camera.intrinsics().height_px << " px, at ("
      << fixed(at.x(), 3) << ", " << fixed(at.y(), 3) << ", " << fixed(at.z(), 3)
      << ") m in the cell, looking along (" << fixed(axis.x(), 2) << ", " << fixed(axis.y(), 2)
      << ", " << fixed(axis.z(), 2) << ")\n";
}

}  // namespace

void run_camera_import(const CameraImportOptions& options, std::ostream& out) {
  if (options.ros_file.empty() == options.mc_calib_file.empty()) {
    bad_option("--ros/--mc-calib", options.ros_file + options.mc_calib_file,
               "exactly one of --ros FILE and --mc-calib FILE");
  }
  if (options.name.empty()) bad_option("--name", "", "a camera name");
  const Eigen::Isometry3d cell_pose = read_cell_pose(options.pose_file);
  if (!options.ros_file.empty()) {
    const PinholeCamera camera(options.name, read_ros_camera_info(options.ros_file), cell_pose);
    write_camera_calibration(options.out, camera);
    say_written(options.out, camera, out);
    return;
  }
  if (!(options.units_m > 0.0 && options.units_m <= 1.0)) {
    bad_option("--units-m", options.units_m == 0.0 ? "" : std::to_string(options.units_m),
               "metres per unit of the MC-Calib file's translations, the unit of its board's "
               "square_size (0.001 for mm, 0.01 for cm, 1 for m): MC-Calib does not record it");
  }
  const auto cameras = read_mc_calib_cameras(options.mc_calib_file, options.units_m);
  fs::create_directories(options.out);
  for (const McCalibCamera& imported : cameras) {
    const std::string name = options.name + std::to_string(imported.index);
    const PinholeCamera camera = mc_calib_camera_in_cell(imported, cell_pose, name);
    const fs::path file = fs::path(options.out) / (name + ".yaml");
    write_camera_calibration(file, camera);
    say_written(file, camera, out);
  }
}

void add_camera_import_command(CLI::App& camera, CommandLine& line) {
  const auto import = std::make_shared<CameraImportOptions>();
  CLI::App* import_command = camera.add_subcommand(
      "import",
      "Turn a calibration made with another tool into this project's calibration files (a cell "
      "file's calibration:): a ROS camera_info file with the camera's cell pose, or an MC-Calib "
      "result with its reference camera's cell pose. A pose file holds the extrinsic keys of a "
      "calibration file only: cell_to_camera_rvec (or _rotation) and cell_to_camera_translation_m");
  import_command->add_option("--ros", import->ros_file, "A ROS camera_info YAML file")
      ->check(CLI::ExistingFile);
  import_command
      ->add_option("--mc-calib", import->mc_calib_file,
                   "An MC-Calib result (calibrated_cameras_data.yml)")
      ->check(CLI::ExistingFile);
  import_command
      ->add_option("--pose", import->pose_file,
                   "Pose file: the camera's cell pose (ROS), or the reference camera's (MC-Calib)")
      ->required()
      ->check(CLI::ExistingFile);
  import_command->add_option(
      "--units-m", import->units_m,
      "MC-Calib (required): metres per unit of its translations, the unit of its "
      "board's square_size (0.001 for mm, 0.01 for cm)");
  import_command
      ->add_option("--name", import->name,
                   "The camera's name (ROS), or the stem of the names (MC-Calib: cam0, cam1, ...)")
      ->capture_default_str();
  import_command
      ->add_option("--out", import->out,
                   "The calibration file to write (ROS), or the folder for them (MC-Calib)")
      ->required();
  import_command->callback(
      [=, &line] { line.action = [=, &line] { run_camera_import(*import, line.out); }; });
}

}  // namespace safecell
