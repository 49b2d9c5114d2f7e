#include "safecell/cli/demo_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <thread>
#include <unordered_map>

#include "coverage_picture.hpp"
#include "cspace_pictures.hpp"
#include "lut_loading.hpp"
#include "png_output.hpp"
#include "progress_bar.hpp"
#include "safecell/cell/cell_file.hpp"
#include "safecell/cell/cell_grid.hpp"
#include "safecell/cli/text_table.hpp"
#include "safecell/cli/validate_command.hpp"
#include "safecell/closed_loop/closed_loop_record.hpp"
#include "safecell/closed_loop/controller_process.hpp"
#include "safecell/closed_loop/controller_setup.hpp"
#include "safecell/closed_loop/demo_world.hpp"
#include "safecell/closed_loop/live_simulated_cameras.hpp"
#include "safecell/closed_loop/report_page.hpp"
#include "safecell/closed_loop/timeline_plot.hpp"
#include "safecell/files/atomic_write.hpp"
#include "safecell/link/link_errors.hpp"
#include "safecell/link/udp_transport.hpp"
#include "safecell/lut/configuration_silhouettes.hpp"
#include "safecell/lut/model_silhouettes.hpp"
#include "safecell/pipeline/sensing_pipeline.hpp"
#include "safecell/pipeline/simulated_reference.hpp"
#include "safecell/service/sensing_service.hpp"
#include "safecell/sim/cell_simulation.hpp"
#include "safecell/validation/configuration_strata.hpp"
#include "safecell/validation/percentile.hpp"
#include "safecell/validation/scene_check.hpp"
#include "scene_options.hpp"

namespace safecell {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr std::size_t kReferenceFrames = 9;
constexpr double kControlPeriod_ms = 4.0;
constexpr double kWatchdog_ms = 250.0;  // a few frame periods: a late frame is not yet a fault
constexpr double kPathSeconds = 3.0;    // of the robot's path drawn on each slice

// The simulated robot's limits: the URDF's speed limit, held to a pace people near it find
// comfortable, and the data sheet's order of acceleration.
ControllerSetup demo_controller_setup(const CellModel& cell, const CspaceGrid& grid,
                                      const DemoWorld& world) {
  ControllerSetup setup;
  for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
    const double urdf = j < cell.robot->joints.size() ? cell.robot->joints[j].max_speed : 0.0;
    const double speed = std::min(urdf > 0.0 ? urdf : 1.0, j < 3 ? 1.0 : 2.0);
    setup.joints.push_back({speed, j < 3 ? 4.0 : 8.0, j < 3 ? 4.0 : 8.0});
  }
  setup.start_rad = world.start_rad();
  setup.goals_rad = world.goals_rad();
  setup.repeat = true;
  setup.period_ms = kControlPeriod_ms;
  setup.watchdog_ms = kWatchdog_ms;
  setup.max_data_age_ms = kWatchdog_ms;
  setup.min_healthy_cameras = static_cast<std::uint32_t>(cell.camera_threshold);
  return setup;
}

std::string numbered(const char* stem, std::size_t cycle, const char* suffix) {
  char name[64];
  std::snprintf(name, sizeof name, "%s%04zu%s", stem, cycle, suffix);
  return name;
}

// The pictures of one moment, composed in the loop and written after it (PNG encoding would cost
// the loop frames).
struct Snapshot {
  std::size_t cycle = 0;
  double time_s = 0.0;
  cv::Mat views;
  CellSet forbidden;
  CellIndex robot_cell = 0;
  std::vector<CellIndex> path;
};

cv::Mat views_picture(const std::vector<cv::Mat>& frames, const SensingPipeline& pipeline,
                      const CellModel& cell, const std::string& state) {
  std::vector<cv::Mat> tiles;
  for (std::size_t c = 0; c < frames.size(); ++c) {
    const auto& observation = pipeline.observations()[c];
    tiles.push_back(labelled(
        camera_overlay(frames[c], observation.blocked, pipeline.fusion().robot_silhouette(c),
                       pipeline.fusion().obstacles(c), cell.cameras[c].name() + "  " + state),
        0.5, ""));
  }
  return contact_sheet(tiles, 2);
}

std::string controller_log_tail(const fs::path& log) {
  std::string text;
  std::ifstream in(log);
  std::string line;
  std::vector<std::string> lines;
  while (std::getline(in, line)) lines.push_back(line);
  for (std::size_t i = lines.size() > 5 ? lines.size() - 5 : 0; i < lines.size(); ++i) {
    text += "\n  " + lines[i];
  }
  return text.empty() ? " (none)" : text;
}

}  // namespace

int run_demo(const DemoOptions& options, std::ostream& out, std::ostream& err) {
  if (!(options.seconds >= 5.0 && options.seconds <= 3600.0)) {
    bad_option("--seconds", std::to_string(options.seconds), "a duration of 5..3600 s");
  }
  if (!(options.fps >= 2.0 && options.fps <= 60.0)) {
    bad_option("--fps", std::to_string(options.fps), "a frame rate of 2..60 per second");
  }
  if (!(options.views_every_s >= 0.0)) {
    bad_option("--views-every", std::to_string(options.views_every_s), "seconds >= 0");
  }
  const fs::path program = find_controller_program(options.controller_program);
  const CellModel cell = load_cell_model(load_cell_file_or_default(options.cell_path));
  const CspaceGrid grid = make_grid(cell.config);
  const fs::path out_dir(options.out_dir);
  for (const char* sub : {"views", "slices"}) fs::create_directories(out_dir / sub);

  const CachedLuts luts = cell_luts(cell, grid, ModelLutOptions{}, options.lut_cache, err);
  const ModelSilhouettes silhouettes(cell, grid, ModelLutOptions{});
  SensorSettings sensor;
  sensor.seed = options.seed;
  SimulatedCell sim = simulate_cell(cell, sensor);
  err << "reference images: median of " << kReferenceFrames << " frames of the empty cell\n";
  const SimulatedReference reference =
      simulated_reference(sim, cell, kReferenceFrames, options.seed);
  FusionSettings fusion;
  fusion.camera_threshold = cell.camera_threshold;
  SensingPipeline pipeline(cell, grid, luts.set, silhouettes, reference.frames, {}, fusion);

  // The person comes in once the robot has done a few moves alone (the productivity baseline)
  // and leaves with time to spare for moves after.
  const DemoWorld world(cell, grid, 0.3 * options.seconds);
  const ControllerSetup setup = demo_controller_setup(cell, grid, world);

  // The link: this end binds first, so the controller's file can name our port.
  UdpTransport transport({"127.0.0.1", 0}, {"127.0.0.1", 0});
  ControllerSetup controller = setup;
  controller.coprocessor_port = transport.local_port();
  controller.listen_port = free_udp_port();
  controller.lut_fingerprint = luts.set.fingerprint;
  transport.set_peer({"127.0.0.1", controller.listen_port});
  const fs::path config_file = out_dir / "controller.yaml";
  write_file_atomically(config_file, controller_config_yaml(grid, controller));
  const fs::path controller_log = out_dir / "controller.log";
  ControllerProcess controller_process(
      program, {"--config", config_file.string(), "--status-hz", "1"}, controller_log);
  err << "controller: " << program.string() << " (log " << controller_log.string() << ")\n";

  CoprocessorLinkConfig link_config;
  link_config.cell_count = grid.cell_count();
  link_config.grid_fingerprint = grid.fingerprint();
  link_config.lut_fingerprint = luts.set.fingerprint;
  link_config.map_cycle_us = static_cast<std::uint32_t>(std::lround(1e6 / options.fps));
  link_config.control_cycle_us = static_cast<std::uint32_t>(kControlPeriod_ms * 1e3);
  link_config.watchdog_us = static_cast<std::uint32_t>(kWatchdog_ms * 1e3);
  link_config.max_data_age_us = static_cast<std::uint32_t>(kWatchdog_ms * 1e3);
  CoprocessorLink link(link_config, transport);
  // The controller needs a moment to start; a refusal, or the program gone, ends the wait.
  const auto give_up = Clock::now() + std::chrono::seconds(10);
  while (true) {
    try {
      link.open(std::chrono::milliseconds(500));
      break;
    } catch (const LinkSetupError& error) {
      if (link.refused_because() || !controller_process.running() || Clock::now() > give_up) {
        throw LinkSetupError(std::string(error.what()) + "; the controller's last words:" +
                             controller_log_tail(controller_log));
      }
    }
  }

  SensingServiceSettings service_settings;
  for (const SimulatedJointLimits& joint : setup.joints) {
    service_settings.joints.max_acceleration_rad_s2.push_back(
        std::max(joint.accel_rad_s2, joint.decel_rad_s2));
  }
  service_settings.widening_budget_m =
      removal_widening_m(*cell.robot, grid, 0.0, fusion.sync_error_s).value_or(0.02);
  service_settings.camera_threshold = static_cast<std::uint32_t>(cell.camera_threshold);
  SensingService service(grid, pipeline, link, service_settings);

  const std::uint64_t start_ns = steady_now_ns();
  const auto seconds_since_start = [start_ns](std::uint64_t ns) {
    return (static_cast<double>(ns) - static_cast<double>(start_ns)) * 1e-9;
  };
  ClosedLoopRecord record;
  std::unordered_map<std::uint64_t, double> exposure_of_version;  // for the live latency
  double last_latency_ms = -1.0;
  link.on_joint_state([&](const ReceivedJointState& received) {
    if (received.coprocessor_time_ns == 0) return;
    const v1::JointState& state = received.state;
    JointRecord sample;
    sample.time_s = seconds_since_start(received.coprocessor_time_ns);
    sample.q.assign(state.position_rad().begin(), state.position_rad().end());
    sample.velocity.assign(state.velocity_rad_s().begin(), state.velocity_rad_s().end());
    sample.state = state.state();
    sample.speed_scale = state.speed_scale();
    sample.critical_joint = state.critical_joint();
    sample.applied_map_version = state.applied_map_version();
    if (record.joints.empty() ||
        record.joints.back().applied_map_version != sample.applied_map_version) {
      const auto exposure = exposure_of_version.find(sample.applied_map_version);
      if (exposure != exposure_of_version.end()) {
        last_latency_ms = (sample.time_s - exposure->second) * 1e3;
      }
    }
    record.joints.push_back(std::move(sample));
  });

  // The cameras see the robot where the controller's joint stream puts it at the exposure.
  std::vector<double> rendered_q = setup.start_rad;
  LiveSimulatedCameras cameras(sim, [&](std::uint64_t exposure_ns) {
    const JointsAtTime joints = service.joints().at(exposure_ns);
    if (joints.known) rendered_q = joints.position_rad;
    SimScene scene{rendered_q, {}};
    if (auto person = world.person_at(seconds_since_start(exposure_ns))) {
      scene.humans.push_back(*person);
    }
    return scene;
  });

  const bool interactive = &err == &std::cerr && ProgressBar::stderr_is_terminal();
  const auto period = std::chrono::nanoseconds(static_cast<std::int64_t>(1e9 / options.fps));
  const auto start = Clock::time_point(std::chrono::nanoseconds(start_ns));
  const auto end =
      start + std::chrono::nanoseconds(static_cast<std::int64_t>(options.seconds * 1e9));
  const std::size_t views_every =
      options.views_every_s > 0.0
          ? std::max<std::size_t>(
                1, static_cast<std::size_t>(std::lround(options.views_every_s * options.fps)))
          : 0;
  std::mt19937_64 rng(options.seed);
  SceneCheck checks;
  std::vector<Snapshot> snapshots;
  std::size_t frames_skipped = 0;
  std::size_t cycle_count = 0;
  bool controller_died = false;
  std::optional<double> fault_since;  // the controller has reported a fault since then
  std::vector<double> acknowledged;   // when the operator acknowledged one
  std::int64_t k = 0;
  double next_status_s = 0.0;
  while (true) {
    const auto exposure_at = start + k * period;
    if (exposure_at >= end) break;
    service.serve_link(exposure_at);
    if (!controller_process.running()) {
      controller_died = true;
      break;
    }
    // The operator: a fault holds the robot until acknowledged; the demo's operator presses the
    // key once the fault has held for a while (a real one would look at the cause first).
    if (!record.joints.empty() && record.joints.back().state == v1::CONTROLLER_STATE_FAULT) {
      if (!fault_since) fault_since = record.joints.back().time_s;
      if (options.acknowledge_after_s > 0.0 &&
          record.joints.back().time_s - *fault_since >= options.acknowledge_after_s) {
        controller_process.acknowledge_fault();
        acknowledged.push_back(record.joints.back().time_s);
        err << "operator: acknowledged the controller's fault at "
            << fixed(record.joints.back().time_s, 1) << " s (it held "
            << fixed(record.joints.back().time_s - *fault_since, 1) << " s)\n";
        fault_since.reset();
      }
    } else {
      fault_since.reset();
    }
    // Behind by a frame or more (a slow machine): skip to the present, as a camera would.
    const auto behind = Clock::now() - exposure_at;
    if (behind > period) {
      const auto skip = behind / period;
      frames_skipped += static_cast<std::size_t>(skip);
      k += skip;
      continue;
    }
    ++k;
    const ServiceCycle& cycle = service.process(cameras.acquire());
    const std::size_t index = cycle_count++;
    const double time_s = seconds_since_start(cycle.exposure_ns);
    CycleRecord cycle_record;
    cycle_record.exposure_s = time_s;
    cycle_record.sent_s = seconds_since_start(cycle.sent_ns);
    cycle_record.map_version = cycle.map_version;
    cycle_record.forbidden_cells = cycle.forbidden_cells;
    cycle_record.blocked_per_camera = cycle.blocked_per_camera;
    cycle_record.features_ms = cycle.times.features_ms;
    cycle_record.fusion_ms = cycle.times.fusion_ms;
    cycle_record.person_present = !cameras.last_scene().humans.empty();
    cycle_record.all_forbidden = cycle.all_forbidden;
    record.cycles.push_back(cycle_record);
    exposure_of_version[cycle.map_version] = time_s;

    if (cycle.pose_known && cycle.all_forbidden.empty() && options.check_every > 0 &&
        index % static_cast<std::size_t>(options.check_every) == 0) {
      const SceneUnderTest under_test{cameras.last_scene(),
                                      cameras.last_object_ids(),
                                      service.last_map(),
                                      fusion.camera_threshold,
                                      "demo",
                                      index};
      checks += check_scene(cell, grid, sim, under_test, options.checks_per_cycle, rng);
    }
    const JointRecord* joints = record.joints.empty() ? nullptr : &record.joints.back();
    const std::string state = joints ? state_name(joints->state) : "waiting";
    if (views_every > 0 && index % views_every == 0 && cycle.all_forbidden.empty()) {
      Snapshot snapshot;
      snapshot.cycle = index;
      snapshot.time_s = time_s;
      snapshot.views = views_picture(cameras.last_frames(), pipeline, cell, state);
      snapshot.forbidden = service.last_map();
      snapshot.robot_cell = pipeline.robot_cell();
      for (const JointRecord& sample : record.joints) {
        if (sample.time_s >= time_s - kPathSeconds)
          snapshot.path.push_back(cell_of(grid, sample.q));
      }
      snapshots.push_back(std::move(snapshot));
    }

    if (time_s >= next_status_s || interactive) {
      std::string blocked;
      for (const std::size_t count : cycle.blocked_per_camera) {
        blocked += (blocked.empty() ? "" : "/") + std::to_string(count);
      }
      std::string status =
          "cycle " + std::to_string(index) + "  t " + fixed(time_s, 1) + " s  blocked " +
          (blocked.empty() ? "-" : blocked) + "  forbidden " + grouped(cycle.forbidden_cells) +
          " (" + fixed(100.0 * static_cast<double>(cycle.forbidden_cells) / grid.cell_count(), 1) +
          " %)  " + state;
      if (joints) {
        status += "  scale " + fixed(joints->speed_scale, 2);
        if (joints->critical_joint > 0)
          status += "  joint " + std::to_string(joints->critical_joint);
      }
      status += "  latency " + (last_latency_ms >= 0.0 ? fixed(last_latency_ms, 1) + " ms" : "-");
      if (!cycle.all_forbidden.empty()) status += "  ALL FORBIDDEN: " + cycle.all_forbidden;
      if (interactive) {
        err << '\r' << status << "\x1b[K" << std::flush;
      } else {
        err << status << '\n';
        next_status_s = time_s + 1.0;
      }
    }
  }
  if (interactive) err << '\n';

  // A clean end: the controller is asked to stop (it holds the robot), then the program exits.
  // What follows the request is not part of the run.
  const double run_end_s = seconds_since_start(steady_now_ns());
  if (!controller_died) {
    link.send_stop_request(v1::FAULT_CAUSE_OPERATOR, "safecell demo finished");
    service.serve_link(Clock::now() + std::chrono::milliseconds(50));
  }
  const std::optional<int> controller_exit = controller_process.stop(std::chrono::seconds(3));
  if (controller_died) {
    err << "the controller exited during the demo (code "
        << (controller_exit ? std::to_string(*controller_exit) : "?")
        << "); its last words:" << controller_log_tail(controller_log) << "\n";
  }

  // The ground truth over the whole run, then the report.
  err << "ground truth: the robot at " << record.joints.size()
      << " joint samples against the person (FCL)\n";
  while (!record.joints.empty() && record.joints.back().time_s > run_end_s)
    record.joints.pop_back();
  const PersonAt person_at = [&world](double t) { return world.person_at(t); };
  const ContactFigures contacts = check_contacts(*cell.robot, record, person_at);
  const TaskFigures task =
      task_figures(record, setup.goals_rad, world.person_enters_s(), world.person_leaves_s());
  const StateFigures states = state_figures(record);
  std::vector<double> fusion_ms;
  for (const CycleRecord& cycle : record.cycles) fusion_ms.push_back(cycle.fusion_ms);

  for (const Snapshot& snapshot : snapshots) {
    write_png(out_dir / "views" / numbered("cycle_", snapshot.cycle, ".png"), snapshot.views);
    const std::string title = "forbidden cells at " + fixed(snapshot.time_s, 1) +
                              " s, the robot's last " + fixed(kPathSeconds, 0) + " s in blue";
    write_png(out_dir / "slices" / numbered("cycle_", snapshot.cycle, "_joints_1_2.png"),
              forbidden_slice(grid, snapshot.forbidden, luts.set.static_cells, snapshot.robot_cell,
                              0, 1, title, snapshot.path));
  }
  write_png(out_dir / "timeline.png",
            timeline_plot(record, contacts.distance_m,
                          {world.person_enters_s(), world.person_leaves_s()}));
  CoverageOptions coverage;
  coverage.step_m = kBlindSpotStep_m;
  write_png(out_dir / "floor_coverage.png", floor_plan(cell, floor_coverage(cell, grid, coverage)));

  const double min_distance =
      std::isfinite(contacts.min_human_distance_m) ? contacts.min_human_distance_m : -1.0;
  nlohmann::ordered_json summary;
  summary["cycles"] = record.cycles.size();
  summary["frames_skipped"] = frames_skipped;
  summary["controller_cycles"] = record.joints.size();
  summary["stops"] = states.stops;
  summary["slowdowns"] = states.slowdowns;
  summary["faults"] = states.faults;
  summary["faults_acknowledged"] = acknowledged.size();
  summary["min_human_distance_m"] = min_distance;
  summary["contacts_while_moving"] = contacts.contacts_while_moving;
  summary["contacts_with_stopped_robot"] = contacts.contacts_with_stopped_robot;
  summary["samples_checked"] = contacts.samples_checked;
  summary["task_completed"] = task.completed_after_person_left;
  summary["moves_completed"] = task.moves_completed;
  summary["task_time_s"] = task.move_time_s;
  summary["task_time_without_people_s"] = task.move_time_without_people_s;
  summary["e2e_latency_p50_ms"] = percentile(states.latency_ms, 0.5);
  summary["e2e_latency_p99_ms"] = percentile(states.latency_ms, 0.99);
  summary["fusion_ms_p99"] = percentile(fusion_ms, 0.99);
  summary["missed"] = checks.missed;
  summary["configs_checked"] = checks.configs_checked;
  summary["colliding_checked"] = checks.colliding;
  summary["seconds"] = options.seconds;
  summary["fps"] = options.fps;
  summary["person_enters_s"] = world.person_enters_s();
  summary["person_leaves_s"] = world.person_leaves_s();
  summary["cell"] = cell.config.name;
  summary["c_space_cells"] = grid.cell_count();
  summary["controller_exit_code"] = controller_exit ? nlohmann::json(*controller_exit) : nullptr;
  summary["lut_file"] = luts.file.string();
  summary["lut_built_now"] = luts.built;
  write_file_atomically(out_dir / "summary.json", summary.dump(2) + "\n");

  const bool safe = contacts.contacts_while_moving == 0 && checks.missed == 0 && !controller_died;
  ReportPage page;
  page.title = "safecell demo: " + cell.config.name;
  page.passed = safe;
  page.verdict = safe ? "Safe: the robot never touched the person while moving, and no collision "
                        "with a seen person was left allowed."
                      : "NOT SAFE: see the figures below.";
  std::ostringstream story;
  story << "The robot moved between its two goals for " << fixed(options.seconds, 0)
        << " s. A person walked in at " << fixed(world.person_enters_s(), 1)
        << " s, stood next to the arm reaching towards it, and left at "
        << fixed(world.person_leaves_s(), 1) << " s. The controller slowed the robot "
        << states.slowdowns << " times and stopped it " << states.stops
        << " times; the person came within " << fixed(std::max(min_distance, 0.0), 2)
        << " m of it. " << task.moves_completed << " moves were completed"
        << (task.completed_after_person_left ? ", the task went on after the person left."
                                             : "; the task did not resume after the person left.");
  page.story = story.str();
  page.figures = {
      {"contacts while the robot moved (must be 0)",
       std::to_string(contacts.contacts_while_moving)},
      {"contacts with the stopped robot", std::to_string(contacts.contacts_with_stopped_robot)},
      {"missed collisions with a seen person (must be 0)", std::to_string(checks.missed)},
      {"closest distance person - robot", fixed(std::max(min_distance, 0.0), 3) + " m"},
      {"slow-downs / stops / faults", std::to_string(states.slowdowns) + " / " +
                                          std::to_string(states.stops) + " / " +
                                          std::to_string(states.faults)},
      {"time per move with the person / without",
       fixed(task.move_time_s, 2) + " s / " + fixed(task.move_time_without_people_s, 2) + " s"},
      {"latency exposure -> map in the controller, p50 / p99",
       fixed(percentile(states.latency_ms, 0.5), 1) + " / " +
           fixed(percentile(states.latency_ms, 0.99), 1) + " ms"},
      {"fusion p99", fixed(percentile(fusion_ms, 0.99), 2) + " ms"},
      {"frames / skipped",
       std::to_string(record.cycles.size()) + " / " + std::to_string(frames_skipped)},
  };
  page.pictures.push_back({"timeline.png",
                           "Over time: the robot's speed and speed scale, the person's distance, "
                           "the controller's state, the latency. The person's visit is shaded."});
  for (const Snapshot& snapshot : snapshots) {
    page.pictures.push_back(
        {"views/" + numbered("cycle_", snapshot.cycle, ".png"),
         "The four cameras at " + fixed(snapshot.time_s, 1) +
             " s: the robot's silhouette blue, its own blocked pixels yellow, obstacles red."});
    page.pictures.push_back({"slices/" + numbered("cycle_", snapshot.cycle, "_joints_1_2.png"),
                             "Forbidden cells over joints 1 and 2 at " + fixed(snapshot.time_s, 1) +
                                 " s, with the robot's path."});
  }
  page.pictures.push_back(
      {"floor_coverage.png", "How many cameras see a person standing at each place of the floor."});
  write_file_atomically(out_dir / "index.html", report_page_html(page));

  out << "demo: " << record.cycles.size() << " frames in " << fixed(options.seconds, 0) << " s ("
      << frames_skipped << " skipped), " << record.joints.size() << " controller cycles on "
      << cell.config.name << "\n"
      << "  controller: " << states.slowdowns << " slow-downs, " << states.stops << " stops, "
      << states.faults << " faults; " << task.moves_completed << " moves, "
      << fixed(task.move_time_s, 2) << " s per move with the person, "
      << fixed(task.move_time_without_people_s, 2) << " s without; task "
      << (task.completed_after_person_left ? "completed" : "NOT completed")
      << " after the person left\n"
      << "  latency exposure -> map in the controller: p50 "
      << fixed(percentile(states.latency_ms, 0.5), 1) << " ms, p99 "
      << fixed(percentile(states.latency_ms, 0.99), 1) << " ms; fusion p99 "
      << fixed(percentile(fusion_ms, 0.99), 2) << " ms\n"
      << "  ground truth: closest " << fixed(std::max(min_distance, 0.0), 2)
      << " m, contacts while moving " << contacts.contacts_while_moving
      << ", with the stopped robot " << contacts.contacts_with_stopped_robot << "; "
      << grouped(checks.configs_checked) << " configurations checked against the map, missed "
      << checks.missed << "\n"
      << "  report: " << (out_dir / "index.html").string() << "\n";
  return safe ? 0 : kExitValidationFailed;
}

}  // namespace safecell
