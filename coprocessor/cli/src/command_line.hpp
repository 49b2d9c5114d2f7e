#pragma once
// How each command joins the safecell command line (cli_app.cpp builds it): each command's file
// adds its subcommand with its options, which the command keeps alive, and on being chosen sets
// the action run once the whole line has been parsed. Private to the CLI.

#include <CLI/CLI.hpp>
#include <functional>
#include <ostream>

namespace safecell {

struct CommandLine {
  std::ostream& out;             // results
  std::ostream& err;             // progress, warnings, one-line errors
  std::function<void()> action;  // the chosen command, set by its callback
  int exit_code = 0;             // what the action leaves (0 unless it says otherwise)
};

// The parent is the app itself or a group ("cell", "luts", ...), as the parameter's name says.
void add_demo_command(CLI::App& app, CommandLine& line);
void add_cell_info_command(CLI::App& cell, CommandLine& line);
void add_cell_coverage_command(CLI::App& cell, CommandLine& line);
void add_sim_render_command(CLI::App& sim, CommandLine& line);
void add_images_show_command(CLI::App& images, CommandLine& line);
void add_luts_build_and_info_commands(CLI::App& luts, CommandLine& line);
void add_luts_record_and_check_commands(CLI::App& luts, CommandLine& line);
void add_validate_command(CLI::App& app, CommandLine& line);
void add_camera_import_command(CLI::App& camera, CommandLine& line);
void add_controller_config_command(CLI::App& controller, CommandLine& line);
void add_run_command(CLI::App& app, CommandLine& line);
void add_replay_command(CLI::App& app, CommandLine& line);
void add_campaign_command(CLI::App& app, CommandLine& line);
void add_bench_command(CLI::App& app, CommandLine& line);

}  // namespace safecell
