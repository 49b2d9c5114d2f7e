#include "safecell/cli/cli_app.hpp"

#include <CLI/CLI.hpp>
#include <functional>

#include "safecell/cli/bench_command.hpp"
#include "safecell/cli/camera_import_command.hpp"
#include "safecell/cli/campaign_command.hpp"
#include "safecell/cli/cell_coverage_command.hpp"
#include "safecell/cli/cell_info_command.hpp"
#include "safecell/cli/closed_loop_validate_command.hpp"
#include "safecell/cli/controller_config_command.hpp"
#include "safecell/cli/demo_command.hpp"
#include "safecell/cli/images_show_command.hpp"
#include "safecell/cli/luts_command.hpp"
#include "safecell/cli/luts_record_command.hpp"
#include "safecell/cli/replay_command.hpp"
#include "safecell/cli/run_command.hpp"
#include "safecell/cli/sim_render_command.hpp"
#include "safecell/cli/validate_command.hpp"
#include "safecell/closed_loop/controller_setup.hpp"
#include "safecell/errors/input_error.hpp"
#include "scene_options.hpp"

namespace safecell {
namespace {

constexpr const char* kDescription =
    "safecell: cameras watch a robot cell; a coprocessor turns every set of frames into the\n"
    "robot configurations that are forbidden right now, and the controller core slows or stops\n"
    "the robot before it reaches one.";

}  // namespace

int run_safecell(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CLI::App app{kDescription, "safecell"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "safecell 0.1.0");
  std::function<void()> action;

  int exit_code = 0;
  DemoOptions demo;
  CLI::App* demo_command = app.add_subcommand(
      "demo",
      "The closed loop on the simulated cell, in real time: this coprocessor and "
      "safecell-controller "
      "(the controller core on the simulated robot, a second process) over loopback UDP; the robot "
      "works through a pick-and-place task while a person walks in, reaches towards it and leaves. "
      "Writes a report folder (index.html, timeline.png, camera views, C-space slices, "
      "summary.json)");
  demo_command->add_option("--cell", demo.cell_path,
                           "Cell file (YAML); without it the built-in default cell");
  demo_command->add_option("--seconds", demo.seconds, "Duration (real time), 5..3600 s")
      ->capture_default_str();
  demo_command->add_option("--fps", demo.fps, "Camera frames per second, 2..60")
      ->capture_default_str();
  demo_command->add_option("--out", demo.out_dir, "Report folder")->capture_default_str();
  demo_command->add_option("--lut-cache", demo.lut_cache,
                           "Folder of cached look-up tables; default $SAFECELL_CACHE or "
                           "~/.cache/safecell");
  demo_command->add_option("--seed", demo.seed, "Seed of the sensor noise and the checks")
      ->capture_default_str();
  demo_command
      ->add_option("--views-every", demo.views_every_s,
                   "Seconds between saved camera views and slices (0: none)")
      ->capture_default_str();
  demo_command
      ->add_option("--checks-per-frame", demo.checks_per_cycle,
                   "Configurations checked against the map (FCL) per checked frame")
      ->capture_default_str()
      ->check(CLI::Range(0, 10000));
  demo_command
      ->add_option("--check-every", demo.check_every, "Frames between checked frames (0: none)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000000));
  demo_command
      ->add_option("--acknowledge-after", demo.acknowledge_after_s,
                   "The demo's operator acknowledges a controller fault after it held this many "
                   "seconds (0: never)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 3600.0));
  demo_command
      ->add_option("--incident-seconds", demo.incident_seconds,
                   "Seconds before each stop or fault written into <out>/incidents for safecell "
                   "replay (0: none)")
      ->capture_default_str();
  demo_command->add_option("--controller-program", demo.controller_program,
                           "The safecell-controller program; default $SAFECELL_CONTROLLER, the one "
                           "beside safecell, or the one this build made");
  demo_command->callback([&] { action = [&] { exit_code = run_demo(demo, out, err); }; });

  CLI::App* cell = app.add_subcommand("cell", "Inspect a cell description");
  cell->require_subcommand(1);
  CellInfoOptions cell_info;
  CLI::App* info = cell->add_subcommand(
      "info", "Show the C-space grid of a cell: per joint range, l_i, dq_i and cell count");
  info->add_option("--cell", cell_info.cell_path,
                   "Cell file (YAML); without it the built-in default cell of the paper");
  info->add_flag("--json", cell_info.json, "Print one JSON object instead of a table");
  info->callback([&] { action = [&] { run_cell_info(cell_info, out); }; });
  CellCoverageOptions coverage;
  CLI::App* coverage_command = cell->add_subcommand(
      "coverage",
      "Where a person can stand that too few cameras see: a floor plan (PNG) of the cameras "
      "seeing each position, and the blind share of the robot's reach");
  coverage_command->add_option("--cell", coverage.cell_path,
                               "Cell file (YAML); without it the built-in default cell");
  coverage_command->add_option("--out", coverage.out_dir, "Folder for the picture and the JSON")
      ->capture_default_str();
  coverage_command->add_option("--step", coverage.step_m, "Floor grid spacing, metres")
      ->capture_default_str()
      ->check(CLI::Range(0.02, 1.0));
  coverage_command->add_flag("--json", coverage.json, "Print one JSON object instead of text");
  coverage_command->callback([&] { action = [&] { run_cell_coverage(coverage, out, err); }; });

  CLI::App* sim = app.add_subcommand("sim", "The simulated work cell");
  sim->require_subcommand(1);
  SimRenderOptions render;
  CLI::App* render_command = sim->add_subcommand(
      "render", "Write what every camera sees (PNG) for one robot configuration and some humans");
  render_command->add_option("--cell", render.cell_path,
                             "Cell file (YAML); without it the built-in default cell");
  render_command->add_option("--q", render.q_deg,
                             "Joint values in degrees, comma-separated, e.g. 0,30,60,0,45,0");
  render_command->add_option("--q-rad", render.q_rad, "Joint values in radians instead");
  render_command->add_option("--human", render.humans,
                             "A human standing at x,y (metres, on the floor), optionally facing "
                             "x,y,heading_deg; repeat for more");
  render_command->add_option("--out", render.out_dir, "Folder for the PNG files")->required();
  render_command->add_option("--seed", render.seed, "Seed of the sensor noise")
      ->capture_default_str();
  render_command->add_option("--noise", render.noise_sigma, "Sensor noise sigma in gray levels")
      ->capture_default_str();
  render_command->add_flag("--visual", render.visual,
                           "Show the robot's visual geometry (meshes) instead of its collision "
                           "geometry");
  render_command->callback([&] { action = [&] { run_sim_render(render, out); }; });

  CLI::App* images = app.add_subcommand("images", "The image pipeline, as pictures");
  images->require_subcommand(1);
  ImagesShowOptions show;
  CLI::App* show_command = images->add_subcommand(
      "show",
      "Write, per camera of the simulated cell, the frame, its five feature images, the reference "
      "image and the blocked feature cells over the frame (PNG)");
  show_command->add_option("--cell", show.cell_path,
                           "Cell file (YAML); without it the built-in default cell");
  show_command->add_option("--q", show.q_deg, "Joint values of the shown frame in degrees")
      ->capture_default_str();
  show_command->add_option("--human", show.humans, "A human at x,y[,heading_deg]; repeat for more")
      ->capture_default_str();
  show_command->add_option("--out", show.out_dir, "Folder for the PNG files")->required();
  show_command
      ->add_option("--seed", show.seed, "Seed of the noise and the candidate configurations")
      ->capture_default_str();
  show_command
      ->add_option("--reference-frames", show.reference_frames,
                   "Frames in the median reference image (the paper: 9)")
      ->capture_default_str();
  show_command->callback([&] { action = [&] { run_images_show(show, out); }; });

  CLI::App* luts = app.add_subcommand("luts", "The look-up tables (LUT-1, LUT-2) of a cell");
  luts->require_subcommand(1);
  LutsBuildOptions build;
  CLI::App* build_command = luts->add_subcommand(
      "build",
      "Build the tables of a cell from its robot model and camera calibrations (model mode) into "
      "a folder, one file per fingerprint; a file already there is kept");
  build_command->add_option("--cell", build.cell_path,
                            "Cell file (YAML); without it the built-in default cell");
  build_command->add_option("--out", build.out_dir,
                            "Folder for the LUT file; without it the cache folder "
                            "($SAFECELL_CACHE or ~/.cache/safecell)");
  build_command
      ->add_option("--ball-radius", build.ball_radius_m,
                   "Size of the balls covering the robot, metres")
      ->capture_default_str()
      ->check(CLI::Range(0.005, 0.5));
  build_command
      ->add_option("--padding", build.padding_m,
                   "Margin added all round the robot, metres (calibration error)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  build_command->add_option("--threads", build.threads, "Worker threads; 0: one per core")
      ->capture_default_str();
  build_command->add_flag("--force", build.force, "Build again even when the file exists");
  build_command->add_flag("--json", build.json, "Print one JSON object instead of a table");
  build_command->callback([&] { action = [&] { run_luts_build(build, out, err); }; });
  LutsInfoOptions lut_info;
  CLI::App* info_command = luts->add_subcommand(
      "info", "What a LUT file holds: sizes per camera, compression, cells, fingerprint");
  info_command->add_option("path", lut_info.path, "A LUT file (*.sclut) or a folder of them")
      ->required();
  info_command->add_flag("--json", lut_info.json, "Print JSON instead of a table");
  info_command->callback([&] { action = [&] { exit_code = run_luts_info(lut_info, out, err); }; });

  LutsRecordOptions record;
  const auto add_recording_options = [&record](CLI::App* command) {
    command->add_option("--cell", record.cell_path,
                        "Cell file (YAML); without it the built-in default cell");
    command
        ->add_option("--key-stride", record.key_stride,
                     "Cells between key configurations along each discretised joint (1: every "
                     "cell, the paper's brute force)")
        ->capture_default_str()
        ->check(CLI::Range(1, 64));
    command
        ->add_option("--wrist-samples", record.wrist_samples,
                     "Values recorded per joint that is not discretised")
        ->capture_default_str()
        ->check(CLI::Range(1, 64));
    command
        ->add_option("--min-coverage", record.min_coverage,
                     "Share of the recorded robot that must lie inside the model's silhouettes")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 1.0));
    command->add_flag("--json", record.json, "Print one JSON object instead of a table");
  };
  CLI::App* record_command = luts->add_subcommand(
      "record",
      "Build the tables from difference images of the robot at key configurations (recorded "
      "mode; the simulated cell stands in for the real robot and cameras)");
  add_recording_options(record_command);
  record_command->add_option("--out", record.out_dir, "Folder for the LUT file")->required();
  record_command
      ->add_option("--padding", record.padding_m, "Margin added to the motion bound, metres")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  record_command->callback([&] { action = [&] { run_luts_record(record, out, err); }; });
  CLI::App* check_command = luts->add_subcommand(
      "check",
      "Compare what each camera sees of the robot with the model's silhouettes and flag a "
      "camera whose calibration is off (exit 1); the simulated cell stands in for the real "
      "robot and cameras");
  add_recording_options(check_command);
  check_command->callback([&] { action = [&] { exit_code = run_luts_check(record, out, err); }; });

  ValidateOptions validate;
  CLI::App* validate_command = app.add_subcommand(
      "validate",
      "Run the sensing pipeline on random simulated scenes and compare the forbidden map with "
      "the exact collisions (FCL); fails when a collision with a seen obstacle is not forbidden. "
      "With --closed-loop: the whole system (pipeline, link, safecell-controller, robot) in "
      "simulated time with people walking in; fails when the robot touches a person while "
      "moving");
  validate_command->add_option("--cell", validate.cell_path,
                               "Cell file (YAML); without it the built-in default cell");
  validate_command->add_option("--scenes", validate.scenes, "Random scenes")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  validate_command->add_option("--seed", validate.seed, "Seed of the scenes")
      ->capture_default_str();
  validate_command
      ->add_option("--configs", validate.configurations, "Robot configurations checked per scene")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  validate_command->add_option("--humans", validate.humans, "At most this many humans per scene")
      ->capture_default_str()
      ->check(CLI::Range(1, 10));
  validate_command
      ->add_option("--objects", validate.objects,
                   "At most this many boxes per scene (objects the cell file does not know)")
      ->capture_default_str()
      ->check(CLI::Range(0, 10));
  validate_command
      ->add_option("--removal", validate.removal, "Robot removal: occlusion-aware or plain")
      ->capture_default_str();
  validate_command->add_option("--lut-cache", validate.lut_cache,
                               "Folder of cached look-up tables; default $SAFECELL_CACHE or "
                               "~/.cache/safecell");
  validate_command
      ->add_option("--padding", validate.padding_m,
                   "Margin added all round the robot in the tables and in robot removal, metres")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  validate_command
      ->add_option("--ball-radius", validate.ball_radius_m,
                   "Size of the balls covering the robot, metres")
      ->capture_default_str()
      ->check(CLI::Range(0.005, 0.5));
  validate_command
      ->add_option("--m-max", validate.m_max_m,
                   "Max-move m_max of the C-space grid, metres (default: the cell's)")
      ->check(CLI::Range(0.01, 1.0));
  validate_command
      ->add_option("--camera-threshold", validate.camera_threshold,
                   "Cameras that must see a cell blocked (default: the cell's)")
      ->check(CLI::Range(1, 64));
  validate_command->add_flag(
      "--model-error", validate.documented_model_error,
      "Apply the documented tolerances to the simulated world: cameras turned 0.5 deg and moved "
      "1 cm, focal length 1 % off, lens k1 -0.02, the robot 5 mm larger");
  validate_command
      ->add_option("--camera-rotation-error", validate.camera_rotation_error_deg,
                   "Each simulated camera turned this far about a random axis, degrees")
      ->check(CLI::Range(0.0, 10.0));
  validate_command
      ->add_option("--camera-translation-error", validate.camera_translation_error_m,
                   "Each simulated camera moved this far, metres")
      ->check(CLI::Range(0.0, 0.5));
  validate_command
      ->add_option("--focal-error", validate.focal_error,
                   "Each simulated camera's focal length off by this fraction (0.01: 1 %)")
      ->check(CLI::Range(0.0, 0.2));
  CLI::Option* lens_k1 =
      validate_command
          ->add_option("--lens-k1", validate.lens_k1,
                       "Radial distortion of the simulated lenses the model does not know")
          ->check(CLI::Range(-0.5, 0.5));
  validate_command
      ->add_option("--robot-growth", validate.robot_growth_m,
                   "The simulated robot this much larger all round than its model, metres")
      ->check(CLI::Range(0.0, 0.2));
  validate_command
      ->add_option("--trace-needless-stops", validate.traced_per_scene,
                   "Needless stops per scene traced to a cause (cell size, visual hull, envelope)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000));
  validate_command
      ->add_option("--negative-control", validate.negative_control,
                   "Break the pipeline on purpose to show the check fails: none, empty-masks, "
                   "dropped-strip or envelope-removal; with --closed-loop: look-ahead-off")
      ->capture_default_str();
  validate_command
      ->add_option("--shard", validate.shard,
                   "K/N: run only the K-th of N disjoint parts of the scenes (merge the JSON "
                   "reports with `validate merge`)")
      ->capture_default_str();
  validate_command->add_option("--threads", validate.threads, "Worker threads; 0: one per core")
      ->capture_default_str()
      ->check(CLI::Range(0, 256));
  validate_command->add_flag("--json", validate.json, "Print one JSON object instead of text");
  bool closed_loop = false;
  ClosedLoopValidateOptions loop;
  validate_command->add_flag("--closed-loop", closed_loop,
                             "Validate the closed loop in simulated time (the options below)");
  validate_command
      ->add_option("--scenarios", loop.scenarios, "Closed loop: random scenarios (task + person)")
      ->capture_default_str();
  validate_command
      ->add_option("--first", loop.first,
                   "Closed loop: index of the first scenario (to run one of a run again)")
      ->capture_default_str();
  validate_command->add_option("--fps", loop.fps, "Closed loop: camera frames per second")
      ->capture_default_str();
  validate_command
      ->add_option("--latency", loop.latency_ms,
                   "Closed loop: exposure to map at the controller, ms (below a frame period)")
      ->capture_default_str();
  validate_command
      ->add_option("--max-seconds", loop.max_seconds,
                   "Closed loop: a scenario ends after this long (simulated seconds)")
      ->capture_default_str();
  validate_command
      ->add_option("--task-pool", loop.task_pool,
                   "Closed loop: robot tasks the scenarios share (each run once without people)")
      ->capture_default_str();
  validate_command
      ->add_option("--out", loop.out_dir,
                   "Closed loop: folder for closed_loop.json and the last controller's log")
      ->capture_default_str();
  validate_command->add_flag("--trace", loop.trace,
                             "Closed loop: every controller cycle of each scenario as a CSV in "
                             "--out (time, state, joints, the person, the distance)");
  validate_command->add_option("--controller-program", loop.controller_program,
                               "Closed loop: the safecell-controller program (default: found "
                               "beside safecell or from $SAFECELL_CONTROLLER)");
  validate_command->require_subcommand(0, 1);
  ValidateMergeOptions merge;
  CLI::App* merge_command = validate_command->add_subcommand(
      "merge", "Add the JSON reports of the shards of one run into the report of the whole run");
  merge_command->add_option("files", merge.files, "JSON reports of `validate --json --shard K/N`")
      ->required()
      ->check(CLI::ExistingFile);
  merge_command->add_flag("--json", merge.json, "Print one JSON object instead of text");
  merge_command->callback([&] { action = [&] { exit_code = run_validate_merge(merge, out); }; });
  validate_command->callback([&] {
    if (merge_command->parsed()) return;
    validate.lens_k1_set = lens_k1->count() > 0;
    if (closed_loop) {
      loop.cell_path = validate.cell_path;
      loop.lut_cache = validate.lut_cache;
      loop.seed = validate.seed;
      loop.json = validate.json;
      loop.look_ahead_off = validate.negative_control == "look-ahead-off";
      action = [&] {
        if (!loop.look_ahead_off && validate.negative_control != "none") {
          bad_option("--negative-control", validate.negative_control,
                     "none or look-ahead-off with --closed-loop");
        }
        exit_code = run_closed_loop_validate(loop, out, err);
      };
      return;
    }
    action = [&] { exit_code = run_validate(validate, out, err); };
  });

  CLI::App* camera = app.add_subcommand("camera", "Camera calibrations");
  camera->require_subcommand(1);
  CameraImportOptions import;
  CLI::App* import_command = camera->add_subcommand(
      "import",
      "Turn a calibration made with another tool into this project's calibration files (a cell "
      "file's calibration:): a ROS camera_info file with the camera's cell pose, or an MC-Calib "
      "result with its reference camera's cell pose. A pose file holds the extrinsic keys of a "
      "calibration file only: cell_to_camera_rvec (or _rotation) and cell_to_camera_translation_m");
  import_command->add_option("--ros", import.ros_file, "A ROS camera_info YAML file")
      ->check(CLI::ExistingFile);
  import_command
      ->add_option("--mc-calib", import.mc_calib_file,
                   "An MC-Calib result (calibrated_cameras_data.yml)")
      ->check(CLI::ExistingFile);
  import_command
      ->add_option("--pose", import.pose_file,
                   "Pose file: the camera's cell pose (ROS), or the reference camera's (MC-Calib)")
      ->required()
      ->check(CLI::ExistingFile);
  import_command->add_option(
      "--units-m", import.units_m,
      "MC-Calib (required): metres per unit of its translations, the unit of its "
      "board's square_size (0.001 for mm, 0.01 for cm)");
  import_command
      ->add_option("--name", import.name,
                   "The camera's name (ROS), or the stem of the names (MC-Calib: cam0, cam1, ...)")
      ->capture_default_str();
  import_command
      ->add_option("--out", import.out,
                   "The calibration file to write (ROS), or the folder for them (MC-Calib)")
      ->required();
  import_command->callback([&] { action = [&] { run_camera_import(import, out); }; });

  CLI::App* controller = app.add_subcommand("controller", "The controller's side of a cell");
  controller->require_subcommand(1);
  ControllerConfigOptions controller_config;
  CLI::App* config_command = controller->add_subcommand(
      "config",
      "Write a safecell-controller configuration for a cell: its grid to the last bit, the LUT "
      "fingerprint of its tables, the link's addresses; the robot, timing and task sections are "
      "the simulated robot's, to be set for a real one");
  config_command->add_option("--cell", controller_config.cell_path,
                             "Cell file (YAML); without it the built-in default cell");
  config_command->add_option("--lut-cache", controller_config.lut_cache,
                             "Folder of cached look-up tables; default $SAFECELL_CACHE or "
                             "~/.cache/safecell");
  config_command
      ->add_option("--listen", controller_config.listen,
                   "The controller's UDP address, HOST:PORT (safecell run's --controller)")
      ->capture_default_str();
  config_command
      ->add_option("--coprocessor", controller_config.coprocessor,
                   "The coprocessor's UDP address, HOST:PORT (safecell run's --listen)")
      ->capture_default_str();
  config_command->add_option("--out", controller_config.out, "The file to write")
      ->capture_default_str();
  config_command->callback(
      [&] { action = [&] { run_controller_config(controller_config, out, err); }; });

  RunOptions run;
  CLI::App* run_command = app.add_subcommand(
      "run",
      "The coprocessor service on the cell file's cameras (each camera's source: a capture "
      "device, a video file, an image folder with frame_times.csv, a GStreamer pipeline or an "
      "RTSP URL), sending its maps to a safecell-controller over UDP. Recordings play at their "
      "recorded pace. Stops on SIGINT or SIGTERM, after --seconds, or when every camera has "
      "stopped; the controller then gets a stop request and holds the robot");
  run_command->add_option("--cell", run.cell_path, "Cell file (YAML) whose cameras name a source")
      ->required();
  run_command->add_option("--lut-cache", run.lut_cache,
                          "Folder of cached look-up tables; default $SAFECELL_CACHE or "
                          "~/.cache/safecell");
  run_command
      ->add_option("--controller", run.controller,
                   "The controller's UDP address, HOST:PORT (its link.listen)")
      ->capture_default_str();
  run_command
      ->add_option("--listen", run.listen,
                   "This end's UDP address, HOST:PORT (the controller's link.coprocessor)")
      ->capture_default_str();
  run_command->add_option("--reference", run.reference_dir,
                          "Folder of reference images, <camera>.png each (the empty cell)");
  run_command->add_flag("--record-reference", run.record_reference,
                        "Record the reference images at the start instead (nobody may be in the "
                        "cell; the robot may move) and write them to <out>/reference");
  run_command
      ->add_option("--reference-sets", run.reference_sets,
                   "Frame sets whose median is the recorded reference")
      ->capture_default_str();
  run_command->add_option("--seconds", run.seconds, "Stop after this long (0: until stopped)")
      ->capture_default_str();
  run_command
      ->add_option("--out", run.out_dir,
                   "Folder for the recorded reference and "
                   "run_summary.json")
      ->capture_default_str();
  run_command
      ->add_option("--incident-seconds", run.incident_seconds,
                   "Seconds before each stop or fault the incident recorder writes into "
                   "<out>/incidents (0: none)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 60.0));
  run_command
      ->add_option("--max-acceleration", run.max_acceleration_rad_s2,
                   "The robot's largest joint acceleration, rad/s^2 (bounds the joint stream's "
                   "interpolation error)")
      ->capture_default_str();
  run_command->add_option("--fps", run.fps, "The cameras' frame rate (announced to the controller)")
      ->capture_default_str();
  run_command
      ->add_option("--sync-error", run.sync_error_ms,
                   "How far apart the cameras' exposures may be, ms (hardware-triggered cameras: "
                   "a few; free-running ones up to a frame period, which widens the robot's "
                   "removal)")
      ->capture_default_str();
  run_command
      ->add_option("--connect-timeout", run.connect_timeout_s,
                   "Seconds to wait for the controller's answer")
      ->capture_default_str();
  run_command->callback([&] { action = [&] { exit_code = run_service(run, out, err); }; });

  ReplayOptions replay;
  CLI::App* replay_command = app.add_subcommand(
      "replay",
      "Run the sensing pipeline again on an incident folder that safecell run recorded: every "
      "cycle's recorded frames and robot pose give a forbidden map, compared bit for bit with "
      "the map sent then; the report (cameras, C-space slice, timeline, index.html) goes into "
      "<incident>/replay. Exit 1 when a map differs");
  replay_command->add_option("incident", replay.incident_dir, "The incident folder")
      ->required()
      ->check(CLI::ExistingDirectory);
  replay_command->add_option("--cell", replay.cell_path,
                             "The cell file (default: the one the incident names; its text must "
                             "be the recorded one)");
  replay_command->add_option("--lut-cache", replay.lut_cache,
                             "Folder of cached look-up tables; default $SAFECELL_CACHE or "
                             "~/.cache/safecell");
  replay_command->add_option("--out", replay.out_dir,
                             "Folder for the report (default: <incident>/replay)");
  replay_command->callback([&] { action = [&] { exit_code = run_replay(replay, out, err); }; });

  CampaignOptions campaign;
  CLI::App* campaign_command = app.add_subcommand(
      "campaign",
      "Fault campaign on loopback with real processes: each fault class of SAFETY.md (link "
      "corruption, repetition, reorder, loss, insertion, foreign session, delay, cut; wrong "
      "fingerprint, coprocessor killed, controller restarted; cameras frozen, blinded, moved, "
      "unplugged) injected into a working closed loop with safecell-controller; checks that the "
      "robot is held in time, that no map the coprocessor did not send is accepted, that the "
      "robot never moves on stale data, that the cause is named and that the loop recovers "
      "after acknowledgement. Prints a table, writes <out>/campaign.json; exit 1 on a failure");
  campaign_command->add_option("--faults", campaign.faults,
                               "Comma-separated fault classes (default: all)");
  campaign_command->add_option("--out", campaign.out_dir, "Folder for the trials and campaign.json")
      ->capture_default_str();
  campaign_command->add_option("--cell", campaign.cell_path,
                               "The cell file (default: the built-in default cell)");
  campaign_command->add_option("--lut-cache", campaign.lut_cache,
                               "Folder of cached look-up tables; default $SAFECELL_CACHE or "
                               "~/.cache/safecell");
  campaign_command
      ->add_option("--settle", campaign.settle_s, "Seconds the robot works before each fault")
      ->capture_default_str();
  campaign_command->add_option("--fault-seconds", campaign.fault_s, "Seconds each fault lasts")
      ->capture_default_str();
  campaign_command
      ->add_option("--recover", campaign.recover_s,
                   "Seconds after each fault for acknowledgement and recovery")
      ->capture_default_str();
  campaign_command
      ->add_option("--rate", campaign.rate,
                   "Probability per datagram of the faults injected at a rate")
      ->capture_default_str();
  campaign_command->add_option("--seed", campaign.seed, "Seed of the proxy and the sensor noise")
      ->capture_default_str();
  campaign_command->add_flag("--json", campaign.json, "Print campaign.json instead of the table");
  campaign_command->add_option("--controller-program", campaign.controller_program,
                               "The safecell-controller program (default: beside safecell)");
  campaign_command->add_option(
      "--test-only-controller-limits-ms", campaign.test_only_controller_limits_ms,
      "The negative control: the controller's watchdog and data age limit in ms instead of "
      "250 (the checks keep 250): the campaign must then fail");
  campaign_command->callback(
      [&] { action = [&] { exit_code = run_campaign(campaign, out, err); }; });

  BenchOptions bench;
  CLI::App* bench_command = app.add_subcommand(
      "bench", "Run the project's benchmarks on the default cell (median and worst case)");
  bench_command->add_flag("--json", bench.json, "Print one JSON object instead of a table");
  bench_command->add_flag("--quick", bench.quick, "Short runs: a smoke test, not a measurement");
  bench_command->callback([&] { action = [&] { run_bench(bench, out, err); }; });

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // --help and --version end here too, with 0; every refused command line is bad input.
    return app.exit(error, out, err) == 0 ? 0 : kExitBadInput;
  }
  // The one place errors become exit codes: what a user can fix (InputError and its kinds, each
  // naming the file, field or option) is 2; anything else is a broken precondition, 70.
  try {
    action();
    return exit_code;
  } catch (const InputError& error) {
    err << "error: " << error.what() << '\n';
    return kExitBadInput;
  } catch (const std::exception& error) {
    err << "internal error: " << error.what() << '\n';
    return kExitInternalError;
  }
}

}  // namespace safecell
