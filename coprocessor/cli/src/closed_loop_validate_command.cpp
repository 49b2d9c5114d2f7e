#include "safecell/cli/closed_loop_validate_command.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>

#include "progress_bar.hpp"
#include "safecell/cli/text_table.hpp"
#include "safecell/cli/validate_command.hpp"
#include "safecell/closed_loop/closed_loop_scenario.hpp"
#include "safecell/closed_loop/controller_setup.hpp"
#include "safecell/closed_loop/lockstep_scenario.hpp"
#include "safecell/files/atomic_write.hpp"
#include "scene_options.hpp"
#include "simulated_sensing.hpp"

namespace safecell {
namespace {

namespace fs = std::filesystem;

void check_options(const ClosedLoopValidateOptions& options) {
  if (options.scenarios < 1 || options.scenarios > 1'000'000) {
    bad_option("--scenarios", std::to_string(options.scenarios), "1 .. 1000000 scenarios");
  }
  if (!(options.fps >= 5.0 && options.fps <= 60.0)) {
    bad_option("--fps", fixed(options.fps, 1), "a frame rate of 5..60 per second");
  }
  if (!(options.latency_ms >= 0.0 && options.latency_ms < 1e3 / options.fps)) {
    bad_option(
        "--latency", fixed(options.latency_ms, 1),
        "milliseconds from 0 to below one frame period (" + fixed(1e3 / options.fps, 1) + " ms)");
  }
  if (!(options.max_seconds >= 5.0 && options.max_seconds <= 600.0)) {
    bad_option("--max-seconds", fixed(options.max_seconds, 1), "5..600 s per scenario");
  }
  if (options.task_pool < 1 || options.task_pool > 10'000) {
    bad_option("--task-pool", std::to_string(options.task_pool), "1 .. 10000 tasks");
  }
}

struct ScenarioRow {
  ClosedLoopScenario scenario;
  ScenarioResult result;
  const ScenarioResult* baseline = nullptr;
};

struct Totals {
  std::size_t scenarios = 0;
  std::size_t contacts_while_moving = 0;
  std::size_t scenarios_with_contact_while_moving = 0;
  std::size_t contacts_with_stopped_robot = 0;
  std::size_t samples_checked = 0;
  double min_human_distance_m = std::numeric_limits<double>::infinity();
  std::size_t stops = 0;
  std::size_t slowdowns = 0;
  std::size_t faults = 0;
  std::size_t frames = 0;
  std::size_t all_forbidden_frames = 0;
  std::map<std::string, std::size_t> all_forbidden_because;
  std::size_t separation_slowed_frames = 0;
  std::size_t tasks_completed = 0;
  std::size_t compared = 0;  // scenarios whose task and baseline both completed
  double task_time_s = 0.0;  // sums over the compared scenarios
  double baseline_time_s = 0.0;
  double worst_ratio = 0.0;
  double simulated_s = 0.0;
  std::uint64_t controller_cycles = 0;

  void add(const ScenarioRow& row) {
    const ScenarioResult& r = row.result;
    ++scenarios;
    contacts_while_moving += r.contacts.contacts_while_moving;
    if (r.contacts.contacts_while_moving > 0) ++scenarios_with_contact_while_moving;
    contacts_with_stopped_robot += r.contacts.contacts_with_stopped_robot;
    samples_checked += r.contacts.samples_checked;
    min_human_distance_m = std::min(min_human_distance_m, r.contacts.min_human_distance_m);
    stops += r.states.stops;
    slowdowns += r.states.slowdowns;
    faults += r.states.faults;
    frames += r.frames;
    all_forbidden_frames += r.all_forbidden_frames;
    for (const auto& [why, count] : r.all_forbidden_because) all_forbidden_because[why] += count;
    separation_slowed_frames += r.separation_slowed_frames;
    simulated_s += r.simulated_s;
    controller_cycles += r.controller_cycles;
    if (r.task_completed) ++tasks_completed;
    if (r.task_completed && row.baseline != nullptr && row.baseline->task_completed) {
      ++compared;
      task_time_s += r.task_time_s;
      baseline_time_s += row.baseline->task_time_s;
      worst_ratio = std::max(worst_ratio, r.task_time_s / row.baseline->task_time_s);
    }
  }
  [[nodiscard]] double mean_task_time_s() const {
    return compared ? task_time_s / static_cast<double>(compared) : 0.0;
  }
  [[nodiscard]] double mean_baseline_time_s() const {
    return compared ? baseline_time_s / static_cast<double>(compared) : 0.0;
  }
  [[nodiscard]] double productivity() const {
    return task_time_s > 0.0 ? baseline_time_s / task_time_s : 0.0;
  }
};

nlohmann::json totals_json(const Totals& t) {
  nlohmann::json json;
  json["scenarios"] = t.scenarios;
  json["contacts_while_moving"] = t.contacts_while_moving;
  json["scenarios_with_contact_while_moving"] = t.scenarios_with_contact_while_moving;
  json["contacts_with_stopped_robot"] = t.contacts_with_stopped_robot;
  json["samples_checked"] = t.samples_checked;
  json["min_human_distance_m"] =
      std::isfinite(t.min_human_distance_m) ? nlohmann::json(t.min_human_distance_m) : nullptr;
  json["stops"] = t.stops;
  json["slowdowns"] = t.slowdowns;
  json["faults"] = t.faults;
  json["frames"] = t.frames;
  json["all_forbidden_frames"] = t.all_forbidden_frames;
  json["all_forbidden_because"] = t.all_forbidden_because;
  json["separation_slowed_frames"] = t.separation_slowed_frames;
  json["tasks_completed"] = t.tasks_completed;
  json["tasks_compared"] = t.compared;
  json["task_time_with_people_mean_s"] = t.mean_task_time_s();
  json["task_time_without_people_mean_s"] = t.mean_baseline_time_s();
  json["productivity"] = t.productivity();
  json["worst_task_time_ratio"] = t.worst_ratio;
  json["simulated_s"] = t.simulated_s;
  json["controller_cycles"] = t.controller_cycles;
  return json;
}

nlohmann::json row_json(const ScenarioRow& row) {
  const ScenarioResult& r = row.result;
  nlohmann::json json;
  json["index"] = row.scenario.index;
  json["kind"] = row.scenario.kind;
  json["task"] = row.scenario.task.index;
  json["motion"] = row.scenario.task.program_motion ? "program" : "gross motion";
  json["person_speed_m_s"] = row.scenario.person.speed_m_s;
  json["contacts_while_moving"] = r.contacts.contacts_while_moving;
  json["contacts_with_stopped_robot"] = r.contacts.contacts_with_stopped_robot;
  json["min_human_distance_m"] = std::isfinite(r.contacts.min_human_distance_m)
                                     ? nlohmann::json(r.contacts.min_human_distance_m)
                                     : nullptr;
  json["stops"] = r.states.stops;
  json["slowdowns"] = r.states.slowdowns;
  json["faults"] = r.states.faults;
  json["all_forbidden_frames"] = r.all_forbidden_frames;
  json["separation_slowed_frames"] = r.separation_slowed_frames;
  json["outcome"] = r.outcome;
  json["task_time_s"] = r.task_time_s;
  json["task_time_without_people_s"] = row.baseline ? row.baseline->task_time_s : 0.0;
  return json;
}

void print_text(const ClosedLoopValidateOptions& options, const std::vector<ScenarioRow>& rows,
                const std::map<std::string, Totals>& by_kind, const Totals& all,
                std::ostream& out) {
  out << "closed-loop validation: " << all.scenarios << " scenarios (seed " << options.seed
      << ", from " << options.first << "), " << fixed(options.fps, 0) << " frames/s, latency "
      << fixed(options.latency_ms, 1) << " ms"
      << (options.look_ahead_off ? ", NEGATIVE CONTROL: look-ahead off" : "")
      << (options.separation_off ? ", NEGATIVE CONTROL: protective separation off" : "") << "\n\n";
  TextTable table({{"person, robot", TextTable::Align::kLeft},
                   {"scenarios", TextTable::Align::kRight},
                   {"contacts while moving", TextTable::Align::kRight},
                   {"with stopped robot", TextTable::Align::kRight},
                   {"closest m", TextTable::Align::kRight},
                   {"stops", TextTable::Align::kRight},
                   {"slow-downs", TextTable::Align::kRight},
                   {"faults", TextTable::Align::kRight},
                   {"tasks done", TextTable::Align::kRight},
                   {"productivity", TextTable::Align::kRight}});
  const auto add = [&table](const std::string& name, const Totals& t) {
    table.add_row({name, grouped(t.scenarios), grouped(t.contacts_while_moving),
                   grouped(t.contacts_with_stopped_robot),
                   std::isfinite(t.min_human_distance_m) ? fixed(t.min_human_distance_m, 2) : "-",
                   grouped(t.stops), grouped(t.slowdowns), grouped(t.faults),
                   grouped(t.tasks_completed), fixed(100.0 * t.productivity(), 0) + " %"});
  };
  for (const auto& [kind, totals] : by_kind) add(kind, totals);
  add("all", all);
  table.print(out);
  out << "\ncontacts while moving: " << all.contacts_while_moving << " (must be 0), in "
      << all.scenarios_with_contact_while_moving << " scenarios; " << grouped(all.samples_checked)
      << " robot samples checked with a person in the cell (FCL, every 4 ms cycle)\n"
      << "productivity: the tasks took " << fixed(all.mean_task_time_s(), 2)
      << " s with people against " << fixed(all.mean_baseline_time_s(), 2) << " s without ("
      << fixed(100.0 * all.productivity(), 0) << " %, worst scenario " << fixed(all.worst_ratio, 2)
      << " x) over " << all.compared << " scenarios\n"
      << "frames all-forbidden: " << all.all_forbidden_frames << " of " << grouped(all.frames)
      << "; simulated " << fixed(all.simulated_s, 0) << " s, " << grouped(all.controller_cycles)
      << " controller cycles\n";
  for (const auto& [why, count] : all.all_forbidden_because) {
    out << "  all-forbidden because " << why << ": " << count << " frames\n";
  }
  out << "frames slowed by the protective separation (not stopped): "
      << grouped(all.separation_slowed_frames) << "\n";
  for (const ScenarioRow& row : rows) {
    if (row.result.contacts.contacts_while_moving == 0) continue;
    out << "  scenario " << row.scenario.index << " (" << row.scenario.kind << ", "
        << fixed(row.scenario.person.speed_m_s, 2)
        << " m/s): " << row.result.contacts.contacts_while_moving
        << " contacts while moving; again alone: --seed " << options.seed << " --first "
        << row.scenario.index << " --scenarios 1\n";
  }
}

}  // namespace

int run_closed_loop_validate(const ClosedLoopValidateOptions& options, std::ostream& out,
                             std::ostream& err) {
  check_options(options);
  const fs::path program = find_controller_program(options.controller_program);
  SimulatedSensing sensing(options.cell_path, options.lut_cache, options.seed, err,
                           CellOverrides{options.camera_threshold, options.separation_off});
  const fs::path out_dir(options.out_dir);
  fs::create_directories(out_dir);
  LockstepParts parts{sensing.cell,
                      sensing.grid,
                      sensing.pipeline,
                      sensing.sim,
                      sensing.luts.set.fingerprint,
                      sensing.fusion.sync_error_s,
                      program,
                      out_dir,
                      sensing.reference.frames};
  LockstepSettings settings;
  settings.fps = options.fps;
  settings.latency_ms = options.latency_ms;
  settings.max_seconds = options.max_seconds;
  settings.look_ahead_off = options.look_ahead_off;

  std::vector<ScenarioRow> rows;
  for (std::size_t i = 0; i < options.scenarios; ++i) {
    rows.push_back({draw_scenario(sensing.cell, sensing.grid, options.seed, options.first + i,
                                  options.task_pool),
                    {},
                    nullptr});
  }
  // The baselines: each task of the run once, without people.
  std::map<std::size_t, ScenarioResult> baselines;
  for (const ScenarioRow& row : rows) baselines.try_emplace(row.scenario.task.index);
  const std::size_t work = baselines.size() + rows.size();
  std::size_t done = 0;
  ProgressBar progress(err, ProgressBar::stderr_is_terminal());
  for (auto& [index, baseline] : baselines) {
    progress.update("tasks without people",
                    static_cast<double>(done++) / static_cast<double>(work));
    const RobotTask task = draw_task(sensing.cell, sensing.grid, options.seed, index);
    baseline = run_lockstep_scenario(parts, settings, task, std::nullopt);
  }
  for (ScenarioRow& row : rows) {
    progress.update("scenarios with people",
                    static_cast<double>(done++) / static_cast<double>(work));
    if (options.trace) {
      settings.trace_file = out_dir / ("scenario-" + std::to_string(row.scenario.index) + ".csv");
    }
    row.result = run_lockstep_scenario(parts, settings, row.scenario.task, row.scenario.person);
    row.baseline = &baselines.at(row.scenario.task.index);
  }
  progress.finish();

  std::map<std::string, Totals> by_kind;
  Totals all;
  for (const ScenarioRow& row : rows) {
    by_kind[row.scenario.kind + (row.scenario.task.program_motion ? ", program" : ", gross motion")]
        .add(row);
    all.add(row);
  }
  nlohmann::json report;
  report["closed_loop"] = true;
  report["seed"] = options.seed;
  report["first"] = options.first;
  report["fps"] = options.fps;
  report["latency_ms"] = options.latency_ms;
  report["negative_control"] = options.look_ahead_off   ? "look-ahead-off"
                               : options.separation_off ? "separation-off"
                                                        : "none";
  report["totals"] = totals_json(all);
  for (const auto& [kind, totals] : by_kind) report["by_kind"][kind] = totals_json(totals);
  for (const ScenarioRow& row : rows) report["per_scenario"].push_back(row_json(row));
  write_file_atomically(out_dir / "closed_loop.json", report.dump(2) + "\n");
  if (options.json) {
    out << report.dump(2) << "\n";
  } else {
    print_text(options, rows, by_kind, all, out);
    out << "report: " << (out_dir / "closed_loop.json").string() << "\n";
  }
  return all.contacts_while_moving == 0 ? 0 : kExitValidationFailed;
}

}  // namespace safecell
