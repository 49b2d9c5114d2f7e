#include "safecell/cli/validate_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "command_line.hpp"
#include "lut_loading.hpp"
#include "progress_bar.hpp"
#include "safecell/cell/cell_file.hpp"
#include "safecell/cell/cell_grid.hpp"
#include "safecell/cli/closed_loop_validate_command.hpp"
#include "safecell/cli/text_table.hpp"
#include "safecell/errors/input_error.hpp"
#include "safecell/pipeline/cell_fusion_settings.hpp"
#include "safecell/silhouettes/model_silhouettes.hpp"
#include "safecell/validation/ground_truth_validation.hpp"
#include "scene_options.hpp"
#include "validation_json.hpp"

namespace safecell {
namespace {

RobotRemoval removal_of(const std::string& text) {
  if (text == "occlusion-aware") return RobotRemoval::kOcclusionAware;
  if (text == "plain") return RobotRemoval::kPlain;
  bad_option("--removal", text, "occlusion-aware or plain");
}

// The options that only the closed loop reads, and those both read: any other given with
// --closed-loop, or one of these without it, would be ignored, so it is refused.
bool closed_loop_only(const std::string& name) {
  static const std::set<std::string> names{"--scenarios", "--first",       "--fps",
                                           "--latency",   "--max-seconds", "--task-pool",
                                           "--out",       "--trace",       "--controller-program"};
  return names.count(name) > 0;
}

bool read_by_both(const std::string& name) {
  static const std::set<std::string> names{"--help",
                                           "--cell",
                                           "--seed",
                                           "--lut-cache",
                                           "--json",
                                           "--closed-loop",
                                           "--negative-control",
                                           "--camera-threshold"};
  return names.count(name) > 0;
}

void refuse_options_of_the_other_loop(const CLI::App& validate, bool closed_loop) {
  for (const CLI::Option* option : validate.get_options()) {
    if (option->count() == 0) continue;
    const std::string name = option->get_name(false, true);
    if (read_by_both(name) || closed_loop_only(name) == closed_loop) continue;
    throw InputError(name + (closed_loop
                                 ? " applies to the open-loop validation only (without "
                                   "--closed-loop)"
                                 : " applies to the closed loop only (with --closed-loop)"));
  }
}

void check_robot_parts(const std::string& text) {
  PartSplit split = PartSplit::kArmSegments;
  if (!text.empty() && !parse_part_split(text, split)) {
    bad_option("--robot-parts", text, part_split_names());
  }
}

NegativeControl control_of(const std::string& text) {
  if (const auto control = negative_control_named(text)) return *control;
  bad_option("--negative-control", text, "none, empty-masks, dropped-strip or envelope-removal");
}

Shard shard_of(const std::string& text, std::size_t scenes) {
  Shard shard;
  char slash = 0;
  std::istringstream in(text);
  if (!(in >> shard.index >> slash >> shard.count) || slash != '/' || !in.eof() ||
      shard.index < 1 || shard.index > shard.count || shard.count > scenes) {
    bad_option("--shard", text,
               "K/N with 1 <= K <= N <= the scenes (" + std::to_string(scenes) + ")");
  }
  return shard;
}

ModelError model_error_of(const ValidateOptions& options) {
  ModelError error = options.documented_model_error ? kDocumentedTolerances : ModelError{};
  if (options.camera_rotation_error_deg >= 0.0) {
    error.camera_rotation_deg = options.camera_rotation_error_deg;
  }
  if (options.camera_translation_error_m >= 0.0) {
    error.camera_translation_m = options.camera_translation_error_m;
  }
  if (options.focal_error >= 0.0) error.focal_error = options.focal_error;
  if (options.lens_k1_set) error.lens_k1 = options.lens_k1;
  if (options.robot_growth_m >= 0.0) error.robot_growth_m = options.robot_growth_m;
  return error;
}

std::string percent(double share) { return fixed(100.0 * share, 2) + " %"; }

void print_report(const ValidationRun& run, const ValidationReport& report, std::ostream& out) {
  out << "validated " << grouped(report.scenes) << " scenes (seed " << run.seed << ", shards "
      << run.shards.size() << " of " << run.shard_count << ", " << run.removal
      << " robot removal (reach " << run.occlusion_reach << "), envelopes of "
      << run.envelope_subdivision << " sub-cells per joint, camera threshold "
      << run.camera_threshold << ", cameras voting per " << run.robot_parts
      << (run.hidden_votes ? ", hidden votes" : ", no hidden votes") << ")"
      << (run.negative_control == "none" ? "" : ", NEGATIVE CONTROL " + run.negative_control)
      << "\n  " << grouped(report.configs_checked)
      << " configurations against FCL and the renderer's object ids: colliding "
      << grouped(report.colliding) << ", missed " << report.missed << ", unseen "
      << grouped(report.unseen) << " (" << grouped(report.unseen_forbidden)
      << " of them forbidden all the same)\n  unseen because:";
  for (std::size_t r = 0; r < kUnseenReasonCount; ++r) {
    out << " " << to_string(static_cast<UnseenReason>(r)) << " "
        << grouped(report.unseen_reasons[r]);
  }
  out << "\n  bodies visible in enough cameras: " << grouped(report.bodies_visible_enough) << " of "
      << grouped(report.bodies) << "\n  needless stops: " << percent(report.needless_stop_share())
      << " of " << grouped(report.clear)
      << " configurations at least 0.5 m from every body; false positives "
      << percent(report.false_positive_rate()) << " of free ones; forbidden "
      << percent(report.forbidden_share()) << " of the grid on average\n";
  if (report.causes.traced > 0) {
    out << "  needless stops traced: " << grouped(report.causes.traced) << ", the cell holds a "
        << "collision " << percent(report.causes.share(report.causes.in_cell))
        << ", visual hull / phantoms " << percent(report.causes.share(report.causes.visual_hull))
        << ", envelope width " << percent(report.causes.share(report.causes.envelope)) << "\n";
  }
  if (report.separation.scenes > 0) {
    const SeparationFigures& separation = report.separation;
    out << "  protective separation: slowed the robot in " << grouped(separation.slowed)
        << " and stopped it in " << grouped(separation.fired - separation.slowed) << " of "
        << grouped(separation.scenes) << " scenes; a visible body within its full-speed "
        << "distance in " << grouped(separation.within) << ", nearer than the allowed speed's "
        << "(missed) " << separation.missed << "; every body 0.5 m beyond it in "
        << grouped(separation.far) << ", slowed or stopped all the same "
        << percent(separation.needless_share()) << "\n";
  }
  if (run.model_error.any()) {
    out << "  model error in the simulated world: cameras turned "
        << fixed(run.model_error.camera_rotation_deg, 2) << " deg, moved "
        << fixed(100.0 * run.model_error.camera_translation_m, 1) << " cm, focal length +-"
        << fixed(100.0 * run.model_error.focal_error, 1) << " %, lens k1 "
        << fixed(run.model_error.lens_k1, 3) << "; robot "
        << fixed(1000.0 * run.model_error.robot_growth_m, 1) << " mm larger\n";
  }
  using Align = TextTable::Align;
  TextTable table({{"stratum", Align::kLeft},
                   {"configs", Align::kRight},
                   {"colliding", Align::kRight},
                   {"missed", Align::kRight},
                   {"unseen", Align::kRight},
                   {"needless stops", Align::kRight}});
  for (const auto& [name, counts] : report.strata) {
    table.add_row({name, grouped(counts.configs), grouped(counts.colliding),
                   std::to_string(counts.missed), grouped(counts.unseen),
                   percent(counts.needless_stop_share())});
  }
  table.print(out);
  out << "  p99 per cycle: features " << fixed(report.features_ms_p99, 2) << " ms, fusion "
      << fixed(report.fusion_ms_p99, 2) << " ms\n";
  for (const auto& missed : report.missed_cases) {
    out << "  MISSED: scene " << missed.scene << " (" << missed.stratum << "), " << missed.body
        << " visible in " << missed.cameras_visible << " cameras\n";
  }
}

int emit(const ValidationRun& run, const ValidationReport& report, bool json, std::ostream& out) {
  if (json) {
    out << validation_json(run, report).dump(2) << '\n';
  } else {
    print_report(run, report, out);
  }
  return report.missed == 0 && report.separation.missed == 0 ? 0 : kExitValidationFailed;
}

}  // namespace

int run_validate(const ValidateOptions& options, std::ostream& out, std::ostream& err) {
  CellConfig config = load_cell_file_or_default(options.cell_path);
  if (options.m_max_m > 0.0) config.m_max_m = options.m_max_m;
  if (options.camera_threshold > 0) config.camera_threshold = options.camera_threshold;
  if (options.occlusion_reach >= 0) config.occlusion_reach_cells = options.occlusion_reach;
  if (options.envelope_max_move_m > 0.0) config.envelope_max_move_m = options.envelope_max_move_m;
  if (options.ball_radius_m > 0.0) config.ball_radius_m = options.ball_radius_m;
  check_robot_parts(options.robot_parts);
  if (!options.robot_parts.empty()) config.robot_parts = options.robot_parts;
  const CellModel cell = load_cell_model(std::move(config));
  const CspaceGrid grid = make_grid(cell.config);
  ModelLutOptions tables;
  tables.padding_m = options.padding_m;
  ValidationOptions validation;
  validation.scenes = options.scenes;
  validation.seed = options.seed;
  validation.configurations_per_scene = options.configurations;
  validation.limits = SceneLimits{options.humans, options.objects};
  validation.fusion = cell_fusion_settings(cell);
  validation.fusion.removal = removal_of(options.removal);
  validation.fusion.hidden_votes = options.hidden_votes;
  validation.negative_control = control_of(options.negative_control);
  validation.shard = shard_of(options.shard, options.scenes);
  validation.threads = options.threads;
  validation.fusion.padding_m = options.padding_m;
  validation.model_error = model_error_of(options);
  validation.needless_stops_traced_per_scene = options.traced_per_scene;
  const CachedLuts luts = cell_luts(cell, grid, tables, options.lut_cache, err);
  const ModelSilhouettes silhouettes(cell, grid, tables, CellDrawing::kWholeCells);
  ProgressBar bar(err, &err == &std::cerr && ProgressBar::stderr_is_terminal());
  const ValidationReport report = validate_against_ground_truth(
      cell, grid, luts.set, silhouettes, validation, [&bar](std::size_t done, std::size_t total) {
        bar.update("validating scenes", static_cast<double>(done) / static_cast<double>(total));
      });
  bar.finish();
  ValidationRun run;
  run.seed = options.seed;
  run.scenes = options.scenes;
  run.configurations_per_scene = options.configurations;
  run.camera_threshold = cell.camera_threshold;
  run.removal = options.removal;
  run.negative_control = options.negative_control;
  run.padding_m = options.padding_m;
  run.ball_radius_m = cell.ball_radius_m;
  run.robot_parts = to_string(cell.robot_parts);
  run.hidden_votes = options.hidden_votes;
  run.occlusion_reach = validation.fusion.occlusion_reach;
  run.m_max_m = cell.config.m_max_m;
  run.envelope_subdivision = cell.envelope_subdivision;
  run.model_error = validation.model_error;
  run.shard_count = validation.shard.count;
  run.shards = {validation.shard.index};
  return emit(run, report, options.json, out);
}

int run_validate_merge(const ValidateMergeOptions& options, std::ostream& out) {
  if (options.files.empty()) bad_option("merge", "", "at least one report file");
  ValidationRun merged_run;
  ValidationReport merged;
  for (std::size_t f = 0; f < options.files.size(); ++f) {
    const std::string& path = options.files[f];
    std::ifstream in(path);
    if (!in) throw InputError(path + ": cannot be read");
    nlohmann::json json;
    try {
      json = nlohmann::json::parse(in);
    } catch (const nlohmann::json::parse_error& error) {
      throw InputError(path + ": not JSON (" + error.what() + ")");
    }
    ValidationRun run;
    ValidationReport report;
    read_validation_json(json, path, run, report);
    if (f == 0) {
      merged_run = run;
      merged_run.shards.clear();
    } else if (!same_run(run, merged_run)) {
      throw InputError(path + ": a shard of another run than " + options.files[0] +
                       " (seed, scenes, configs, threshold, removal, votes, control, table "
                       "settings, model error and shard count must agree)");
    }
    for (const std::size_t shard : run.shards) {
      if (std::find(merged_run.shards.begin(), merged_run.shards.end(), shard) !=
          merged_run.shards.end()) {
        throw InputError(path + ": shard " + std::to_string(shard) +
                         " is in an earlier file already");
      }
      merged_run.shards.push_back(shard);
    }
    merged += report;
  }
  std::sort(merged_run.shards.begin(), merged_run.shards.end());
  return emit(merged_run, merged, options.json, out);
}

void add_validate_command(CLI::App& app, CommandLine& line) {
  const auto validate = std::make_shared<ValidateOptions>();
  // The padding of the tables under test: the service's.
  validate->padding_m = ModelLutOptions{}.padding_m;
  CLI::App* validate_command = app.add_subcommand(
      "validate",
      "Run the sensing pipeline on random simulated scenes and compare the forbidden map with "
      "the exact collisions (FCL); fails when a collision with a seen obstacle is not forbidden. "
      "With --closed-loop: the whole system (pipeline, link, safecell-controller, robot) in "
      "simulated time with people walking in; fails when the robot touches a person while "
      "moving");
  validate_command->add_option("--cell", validate->cell_path,
                               "Cell file (YAML); without it the built-in default cell");
  validate_command->add_option("--scenes", validate->scenes, "Random scenes")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  validate_command->add_option("--seed", validate->seed, "Seed of the scenes")
      ->capture_default_str();
  validate_command
      ->add_option("--configs", validate->configurations, "Robot configurations checked per scene")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  validate_command->add_option("--humans", validate->humans, "At most this many humans per scene")
      ->capture_default_str()
      ->check(CLI::Range(1, 10));
  validate_command
      ->add_option("--objects", validate->objects,
                   "At most this many boxes per scene (objects the cell file does not know)")
      ->capture_default_str()
      ->check(CLI::Range(0, 10));
  validate_command
      ->add_option("--removal", validate->removal, "Robot removal: occlusion-aware or plain")
      ->capture_default_str();
  validate_command->add_option("--lut-cache", validate->lut_cache,
                               "Folder of cached look-up tables; default $SAFECELL_CACHE or "
                               "~/.cache/safecell");
  validate_command
      ->add_option("--padding", validate->padding_m,
                   "Margin added all round the robot in the tables and in robot removal, metres")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  validate_command
      ->add_option("--ball-radius", validate->ball_radius_m,
                   "Size of the balls covering the robot, metres (default: the cell's)")
      ->check(CLI::Range(kMinBallRadius_m, kMaxBallRadius_m));
  validate_command->add_option(
      "--robot-parts", validate->robot_parts,
      "The robot parts the cameras vote on: per-link, links-and-wrist (base | link 1 | link 2 | "
      "link 3 | the wrist, links 4 on), arm-segments (base | links 1-2 | the rest) or "
      "whole-robot (the paper's vote) (default: the cell's)");
  validate_command
      ->add_option("--hidden-votes", validate->hidden_votes,
                   "Whether a camera whose view of a cell the robot hides votes for it where "
                   "another camera sees an obstacle: on, or off (the paper's vote)")
      ->capture_default_str();
  validate_command
      ->add_option("--occlusion-reach", validate->occlusion_reach,
                   "How far occlusion-aware removal grows a person's blob into the robot's "
                   "silhouette, feature cells (default: the cell's)")
      ->check(CLI::Range(0, 10000));
  validate_command
      ->add_option("--m-max", validate->m_max_m,
                   "Max-move m_max of the C-space grid, metres (default: the cell's)")
      ->check(CLI::Range(0.01, 1.0));
  validate_command
      ->add_option("--envelope-max-move", validate->envelope_max_move_m,
                   "Largest motion of the sub-cells whose envelopes draw a cell's silhouette, "
                   "metres; m_max or more: whole cells (default: the cell's)")
      ->check(CLI::Range(0.001, 10.0));
  validate_command
      ->add_option("--camera-threshold", validate->camera_threshold,
                   "Cameras that must see a cell blocked (default: the cell's)")
      ->check(CLI::Range(1, 64));
  validate_command->add_flag(
      "--model-error", validate->documented_model_error,
      "Apply the documented tolerances to the simulated world: cameras turned 0.5 deg and moved "
      "1 cm, focal length 1 % off, lens k1 -0.02, the robot 5 mm larger");
  validate_command
      ->add_option("--camera-rotation-error", validate->camera_rotation_error_deg,
                   "Each simulated camera turned this far about a random axis, degrees")
      ->check(CLI::Range(0.0, 10.0));
  validate_command
      ->add_option("--camera-translation-error", validate->camera_translation_error_m,
                   "Each simulated camera moved this far, metres")
      ->check(CLI::Range(0.0, 0.5));
  validate_command
      ->add_option("--focal-error", validate->focal_error,
                   "Each simulated camera's focal length off by this fraction (0.01: 1 %)")
      ->check(CLI::Range(0.0, 0.2));
  CLI::Option* lens_k1 =
      validate_command
          ->add_option("--lens-k1", validate->lens_k1,
                       "Radial distortion of the simulated lenses the model does not know")
          ->check(CLI::Range(-0.5, 0.5));
  validate_command
      ->add_option("--robot-growth", validate->robot_growth_m,
                   "The simulated robot this much larger all round than its model, metres")
      ->check(CLI::Range(0.0, 0.2));
  validate_command
      ->add_option("--trace-needless-stops", validate->traced_per_scene,
                   "Needless stops per scene traced to a cause (cell size, visual hull, envelope)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000));
  validate_command
      ->add_option("--negative-control", validate->negative_control,
                   "Break the pipeline on purpose to show the check fails: none, empty-masks, "
                   "dropped-strip or envelope-removal; with --closed-loop: look-ahead-off or "
                   "separation-off (the cell's protective separation off)")
      ->capture_default_str();
  validate_command
      ->add_option("--shard", validate->shard,
                   "K/N: run only the K-th of N disjoint parts of the scenes (merge the JSON "
                   "reports with `validate merge`)")
      ->capture_default_str();
  validate_command->add_option("--threads", validate->threads, "Worker threads; 0: one per core")
      ->capture_default_str()
      ->check(CLI::Range(0, 256));
  validate_command->add_flag("--json", validate->json, "Print one JSON object instead of text");
  const auto closed_loop = std::make_shared<bool>(false);
  const auto loop = std::make_shared<ClosedLoopValidateOptions>();
  validate_command->add_flag("--closed-loop", *closed_loop,
                             "Validate the closed loop in simulated time (the options below)");
  validate_command
      ->add_option("--scenarios", loop->scenarios, "Closed loop: random scenarios (task + person)")
      ->capture_default_str();
  validate_command
      ->add_option("--first", loop->first,
                   "Closed loop: index of the first scenario (to run one of a run again)")
      ->capture_default_str();
  validate_command->add_option("--fps", loop->fps, "Closed loop: camera frames per second")
      ->capture_default_str();
  validate_command
      ->add_option("--latency", loop->latency_ms,
                   "Closed loop: exposure to map at the controller, ms (below a frame period)")
      ->capture_default_str();
  validate_command
      ->add_option("--max-seconds", loop->max_seconds,
                   "Closed loop: a scenario ends after this long (simulated seconds)")
      ->capture_default_str();
  validate_command
      ->add_option("--task-pool", loop->task_pool,
                   "Closed loop: robot tasks the scenarios share (each run once without people)")
      ->capture_default_str();
  validate_command
      ->add_option("--out", loop->out_dir,
                   "Closed loop: folder for closed_loop.json and the last controller's log")
      ->capture_default_str();
  validate_command->add_flag("--trace", loop->trace,
                             "Closed loop: every controller cycle of each scenario as a CSV in "
                             "--out (time, state, joints, the person, the distance)");
  validate_command->add_option("--controller-program", loop->controller_program,
                               "Closed loop: the safecell-controller program (default: found "
                               "beside safecell or from $SAFECELL_CONTROLLER)");
  validate_command->require_subcommand(0, 1);
  const auto merge = std::make_shared<ValidateMergeOptions>();
  CLI::App* merge_command = validate_command->add_subcommand(
      "merge", "Add the JSON reports of the shards of one run into the report of the whole run");
  merge_command->add_option("files", merge->files, "JSON reports of `validate --json --shard K/N`")
      ->required()
      ->check(CLI::ExistingFile);
  merge_command->add_flag("--json", merge->json, "Print one JSON object instead of text");
  merge_command->callback([=, &line] {
    line.action = [=, &line] { line.exit_code = run_validate_merge(*merge, line.out); };
  });
  validate_command->callback([=, &line] {
    if (merge_command->parsed()) return;
    validate->lens_k1_set = lens_k1->count() > 0;
    if (*closed_loop) {
      loop->cell_path = validate->cell_path;
      loop->camera_threshold = validate->camera_threshold;
      loop->lut_cache = validate->lut_cache;
      loop->seed = validate->seed;
      loop->json = validate->json;
      loop->look_ahead_off = validate->negative_control == "look-ahead-off";
      loop->separation_off = validate->negative_control == "separation-off";
      line.action = [=, &line] {
        refuse_options_of_the_other_loop(*validate_command, true);
        if (!loop->look_ahead_off && !loop->separation_off &&
            validate->negative_control != "none") {
          bad_option("--negative-control", validate->negative_control,
                     "none, look-ahead-off or separation-off with --closed-loop");
        }
        line.exit_code = run_closed_loop_validate(*loop, line.out, line.err);
      };
      return;
    }
    line.action = [=, &line] {
      refuse_options_of_the_other_loop(*validate_command, false);
      line.exit_code = run_validate(*validate, line.out, line.err);
    };
  });
}

}  // namespace safecell
