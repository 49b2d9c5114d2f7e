// The controller setup of a cell: the simulated robot's stop from its top speed against the cell
// file's stopping times, which size its separation distances. The default cell's cover it; a
// stopping time shorter than the robot's stop is refused, naming the field.

#include "safecell/closed_loop/controller_setup.hpp"

#include <gtest/gtest.h>

#include "safecell/cell/cell_error.hpp"
#include "safecell/cell/cell_file.hpp"
#include "safecell/cell/cell_grid.hpp"
#include "safecell/cell/default_cell.hpp"

namespace safecell {
namespace {

TEST(ControllerSetup, TheCellsStoppingTimesMustCoverTheRobotsStop) {
  const CellModel cell = load_cell_model(default_cell());
  const CspaceGrid grid = make_grid(cell.config);
  const ControllerSetup setup = controller_setup_of(cell, grid);
  EXPECT_EQ(setup.min_healthy_cameras, static_cast<std::uint32_t>(cell.camera_threshold));
  // 1 rad/s at 4 rad/s^2 (and 2 rad/s at 8 rad/s^2 for the wrist), 2 ms to act.
  EXPECT_NEAR(stop_time_from_top_speed_s(setup), 0.252, 1e-12);

  CellConfig quick = default_cell();
  quick.protective_separation->stopping_s = 0.2;
  try {
    (void)controller_setup_of(load_cell_model(quick), grid);
    FAIL() << "a stopping time of 0.2 s was taken for a robot that needs 0.252 s";
  } catch (const CellError& error) {
    EXPECT_NE(std::string(error.what()).find("protective_separation.stopping_s: value 0.2 s"),
              std::string::npos)
        << error.what();
  }
  CellConfig entry = default_cell();
  entry.entry_separation.stopping_s = 0.25;
  EXPECT_THROW((void)controller_setup_of(load_cell_model(entry), grid), CellError);
}

}  // namespace
}  // namespace safecell
