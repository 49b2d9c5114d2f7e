#include "demo_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "coverage_picture.hpp"
#include "cspace_pictures.hpp"
#include "png_output.hpp"
#include "safecell/cli/text_table.hpp"
#include "safecell/closed_loop/report_page.hpp"
#include "safecell/closed_loop/timeline_plot.hpp"
#include "safecell/files/atomic_write.hpp"
#include "safecell/validation/percentile.hpp"

namespace safecell {
namespace {

std::string share_text(double share) { return fixed(100.0 * share, 1) + " %"; }

std::string numbered(const char* stem, std::size_t cycle, const char* suffix) {
  char name[64];
  std::snprintf(name, sizeof name, "%s%04zu%s", stem, cycle, suffix);
  return name;
}

}  // namespace

cv::Mat demo_views_picture(const std::vector<cv::Mat>& frames, const SensingPipeline& pipeline,
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

bool write_demo_report(const std::filesystem::path& folder, const SimulatedSensing& sensing,
                       const DemoWorld& world, const std::vector<std::vector<double>>& goals,
                       const DemoRun& run, std::ostream& out, std::ostream& log) {
  // The ground truth over the whole run, then the report.
  const ClosedLoopRecord& record = run.record;
  const CellModel& cell = sensing.cell;
  const CspaceGrid& grid = sensing.grid;
  log << "ground truth: the robot at " << record.joints.size()
      << " joint samples against the person (FCL)\n";
  const PersonAt person_at = [&world](double t) { return world.person_at(t); };
  const ContactFigures contacts = check_contacts(*cell.robot, record, person_at);
  const TaskFigures task =
      task_figures(record, goals, world.person_enters_s(), world.person_leaves_s());
  const StateFigures states = state_figures(record);
  std::vector<double> fusion_ms;
  for (const CycleRecord& cycle : record.cycles) fusion_ms.push_back(cycle.fusion_ms);

  for (const DemoSnapshot& snapshot : run.snapshots) {
    write_png(folder / "views" / numbered("cycle_", snapshot.cycle, ".png"), snapshot.views);
    const std::string title = "forbidden cells at " + fixed(snapshot.time_s, 1) +
                              " s, the robot's last " + fixed(kDemoPathSeconds, 0) + " s in blue";
    write_png(folder / "slices" / numbered("cycle_", snapshot.cycle, "_joints_1_2.png"),
              forbidden_slice(grid, snapshot.forbidden, sensing.luts.set.static_cells,
                              snapshot.robot_cell, 0, 1, title, snapshot.path));
  }
  TimelineCurve distance{"the person's distance to the robot (FCL)", "m", {}, contacts.distance_m};
  for (const JointRecord& sample : record.joints) distance.time_s.push_back(sample.time_s);
  write_png(folder / "timeline.png",
            timeline_plot(record, distance, {world.person_enters_s(), world.person_leaves_s()}));
  CoverageOptions coverage;
  coverage.step_m = kBlindSpotStep_m;
  write_png(folder / "floor_coverage.png", floor_plan(cell, floor_coverage(cell, grid, coverage)));

  const double min_distance =
      std::isfinite(contacts.min_human_distance_m) ? contacts.min_human_distance_m : -1.0;
  nlohmann::ordered_json summary;
  summary["cycles"] = record.cycles.size();
  summary["frames_skipped"] = run.frames_skipped;
  summary["controller_cycles"] = record.joints.size();
  summary["stops"] = states.stops;
  summary["slowdowns"] = states.slowdowns;
  summary["faults"] = states.faults;
  summary["faults_acknowledged"] = run.acknowledged_s.size();
  summary["incidents_not_written"] = run.incidents_not_written;
  summary["stop_explanations"] = nlohmann::ordered_json::array();
  for (const IncidentExplanation& stop : run.stop_explanations) {
    summary["stop_explanations"].push_back({{"time_s", stop.time_s}, {"text", stop.text}});
  }
  summary["min_human_distance_m"] = min_distance;
  summary["contacts_while_moving"] = contacts.contacts_while_moving;
  summary["contacts_with_stopped_robot"] = contacts.contacts_with_stopped_robot;
  summary["samples_checked"] = contacts.samples_checked;
  summary["task_completed"] = task.completed_after_person_left;
  summary["moves_completed"] = task.moves_completed;
  summary["near_person_frames"] = run.near_person.frames;
  summary["near_person_separation_frames"] = run.near_person.separation_frames;
  summary["near_person_slowed_frames"] = run.near_person.slowed_frames;
  summary["near_person_mean_speed_limit"] = run.near_person.mean_speed_limit();
  summary["near_person_map_free_share"] = run.near_person.map_free_share();
  summary["near_person_sent_free_share"] = run.near_person.sent_free_share();
  summary["task_time_s"] = task.move_time_s;
  summary["task_time_without_people_s"] = task.move_time_without_people_s;
  summary["e2e_latency_p50_ms"] = percentile(states.latency_ms, 0.5);
  summary["e2e_latency_p99_ms"] = percentile(states.latency_ms, 0.99);
  summary["fusion_ms_p99"] = percentile(fusion_ms, 0.99);
  summary["missed"] = run.checks.missed;
  summary["configs_checked"] = run.checks.configs_checked;
  summary["colliding_checked"] = run.checks.colliding;
  summary["seconds"] = run.seconds;
  summary["fps"] = run.fps;
  summary["person_enters_s"] = world.person_enters_s();
  summary["person_leaves_s"] = world.person_leaves_s();
  summary["cell"] = cell.config.name;
  summary["c_space_cells"] = grid.cell_count();
  summary["controller_exit_code"] =
      run.controller_exit ? nlohmann::json(*run.controller_exit) : nullptr;
  summary["lut_file"] = sensing.luts.file.string();
  summary["lut_built_now"] = sensing.luts.built;
  write_file_atomically(folder / "summary.json", summary.dump(2) + "\n");

  const bool safe =
      contacts.contacts_while_moving == 0 && run.checks.missed == 0 && !run.controller_died;
  ReportPage page;
  page.title = "safecell demo: " + cell.config.name;
  page.passed = safe;
  page.verdict = safe ? "Safe: the robot never touched the person while moving, and no collision "
                        "with a seen person was left allowed."
                      : "NOT SAFE: see the figures below.";
  std::ostringstream story;
  story << "The robot moved between its two goals for " << fixed(run.seconds, 0)
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
      {"missed collisions with a seen person (must be 0)", std::to_string(run.checks.missed)},
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
       std::to_string(record.cycles.size()) + " / " + std::to_string(run.frames_skipped)},
      {"slow-downs and stops explained", std::to_string(run.stop_explanations.size())},
      {"C-space free with the person within 1 m: the map / the maps sent",
       share_text(run.near_person.map_free_share()) + " / " +
           share_text(run.near_person.sent_free_share()) + " over " +
           std::to_string(run.near_person.frames) + " frames (" +
           std::to_string(run.near_person.separation_frames) +
           " forbidden whole by the protective separation, " +
           std::to_string(run.near_person.slowed_frames) + " slowed by it; mean speed limit " +
           share_text(run.near_person.mean_speed_limit()) + ")"},
  };
  // The first few explanations, as the log shows them (all of them are in summary.json).
  for (std::size_t k = 0; k < run.stop_explanations.size() && k < 5; ++k) {
    page.figures.push_back({"why, at " + fixed(run.stop_explanations[k].time_s, 2) + " s",
                            run.stop_explanations[k].text});
  }
  const std::string film = run.video.write(folder, "run");
  if (!film.empty()) {
    page.film = {film,
                 "The run as the cameras saw it (5 frames a second), the controller's state "
                 "on every view: blocked cells red where they are obstacles, yellow where "
                 "they are the robot itself."};
  }
  page.pictures.push_back({"timeline.png",
                           "Over time: the robot's speed and speed scale, the person's distance, "
                           "the controller's state, the latency. The person's visit is shaded."});
  for (const DemoSnapshot& snapshot : run.snapshots) {
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
  write_file_atomically(folder / "index.html", report_page_html(page));

  out << "demo: " << record.cycles.size() << " frames in " << fixed(run.seconds, 0) << " s ("
      << run.frames_skipped << " skipped), " << record.joints.size() << " controller cycles on "
      << cell.config.name << "\n"
      << "  controller: " << states.slowdowns << " slow-downs, " << states.stops << " stops, "
      << states.faults << " faults; " << task.moves_completed << " moves, "
      << fixed(task.move_time_s, 2) << " s per move with the person, "
      << fixed(task.move_time_without_people_s, 2) << " s without; task "
      << (task.completed_after_person_left ? "completed" : "NOT completed")
      << " after the person left\n"
      << "  person within 1 m of the robot in " << run.near_person.frames
      << " frames: the map left " << share_text(run.near_person.map_free_share())
      << " of the C-space free, the maps sent " << share_text(run.near_person.sent_free_share())
      << " (" << run.near_person.separation_frames
      << " forbidden whole by the protective separation, " << run.near_person.slowed_frames
      << " slowed by it; mean speed limit " << share_text(run.near_person.mean_speed_limit())
      << ")\n"
      << "  latency exposure -> map in the controller: p50 "
      << fixed(percentile(states.latency_ms, 0.5), 1) << " ms, p99 "
      << fixed(percentile(states.latency_ms, 0.99), 1) << " ms; fusion p99 "
      << fixed(percentile(fusion_ms, 0.99), 2) << " ms\n"
      << "  ground truth: closest " << fixed(std::max(min_distance, 0.0), 2)
      << " m, contacts while moving " << contacts.contacts_while_moving
      << ", with the stopped robot " << contacts.contacts_with_stopped_robot << "; "
      << grouped(run.checks.configs_checked) << " configurations checked against the map, missed "
      << run.checks.missed << "\n"
      << "  report: " << (folder / "index.html").string() << "\n";
  return safe;
}

}  // namespace safecell
