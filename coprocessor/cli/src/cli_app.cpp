#include "safecell/cli/cli_app.hpp"

#include <CLI/CLI.hpp>

#include "command_line.hpp"
#include "safecell/errors/input_error.hpp"

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
  CommandLine line{out, err, {}, 0};
  add_demo_command(app, line);

  CLI::App* cell = app.add_subcommand("cell", "Inspect a cell description");
  cell->require_subcommand(1);
  add_cell_info_command(*cell, line);
  add_cell_coverage_command(*cell, line);

  CLI::App* sim = app.add_subcommand("sim", "The simulated work cell");
  sim->require_subcommand(1);
  add_sim_render_command(*sim, line);

  CLI::App* images = app.add_subcommand("images", "The image pipeline, as pictures");
  images->require_subcommand(1);
  add_images_show_command(*images, line);

  CLI::App* luts = app.add_subcommand("luts", "The look-up tables (LUT-1, LUT-2) of a cell");
  luts->require_subcommand(1);
  add_luts_build_and_info_commands(*luts, line);
  add_luts_record_and_check_commands(*luts, line);

  add_validate_command(app, line);

  CLI::App* camera = app.add_subcommand("camera", "Camera calibrations");
  camera->require_subcommand(1);
  add_camera_import_command(*camera, line);

  CLI::App* controller = app.add_subcommand("controller", "The controller's side of a cell");
  controller->require_subcommand(1);
  add_controller_config_command(*controller, line);

  add_run_command(app, line);
  add_replay_command(app, line);
  add_campaign_command(app, line);
  add_bench_command(app, line);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // --help and --version end here too, with 0; every refused command line is bad input.
    return app.exit(error, out, err) == 0 ? 0 : kExitBadInput;
  }
  // The one place errors become exit codes: what a user can fix (InputError and its kinds, each
  // naming the file, field or option) is 2; anything else is a broken precondition, 70.
  try {
    line.action();
    return line.exit_code;
  } catch (const InputError& error) {
    err << "error: " << error.what() << '\n';
    return kExitBadInput;
  } catch (const std::exception& error) {
    err << "internal error: " << error.what() << '\n';
    return kExitInternalError;
  }
}

}  // namespace safecell
