#include "safecell/cell/cell_grid.hpp"

#include <gtest/gtest.h>

#include <string>

#include "cell_errors.hpp"
#include "safecell/cell/cell_error.hpp"
#include "safecell/cell/cell_file.hpp"
#include "safecell/cell/cell_model.hpp"

namespace safecell {
namespace {

constexpr const char* kCell = R"(name: test cell
m_max_m: 0.18
joints:
  - name: a
    range_deg: [-90, 90]
    l_m: 1.0
  - name: b
    range_deg: [-45, 45]
    l_m: 0.5
)";

std::string grid_error_of(const std::string& text) {
  return test::cell_error_of([&] {
    static_cast<void>(make_grid(load_cell_model(parse_cell_yaml(text, "cell.yaml")).config));
  });
}

using test::replaced;

TEST(CellGrid, ConvertsDegreesToRadians) {
  const CspaceGrid grid = make_grid(load_cell_model(parse_cell_yaml(kCell, "cell.yaml")).config);
  EXPECT_NEAR(grid.joint(0).lo_rad, -1.5707963267948966, 1e-15);
  EXPECT_NEAR(grid.joint(1).hi_rad, 0.7853981633974483, 1e-15);
}

TEST(CellGrid, AbsurdValuesAreNamedWithFileLineFieldAndValue) {
  EXPECT_EQ(grid_error_of(replaced(kCell, "0.18", "-0.18")),
            "cell.yaml:2: m_max_m: value -0.18, expected a distance above 0 m");
  EXPECT_EQ(grid_error_of(replaced(kCell, "[-45, 45]", "[45, -45]")),
            "cell.yaml:8: joints[1].range_deg: value [45, -45], expected finite limits with "
            "lower < upper");
  EXPECT_EQ(grid_error_of(replaced(kCell, "l_m: 0.5", "l_m: 0.05")),
            "cell.yaml:9: joints[1].l_m: value 0.05, expected at least m_max_m / 2 = 0.09 m for a "
            "discretised joint (one that moves the robot less is swept: discretised: false)");
  EXPECT_EQ(grid_error_of(replaced(kCell, "0.18", ".nan")),
            "cell.yaml:2: m_max_m: value nan, expected a distance above 0 m");
}

TEST(CellGrid, MoreThanEightJointsAreRefused) {
  std::string text = "name: nine\nm_max_m: 0.18\njoints:\n";
  for (int j = 0; j < 9; ++j) {
    text += "  - {name: j" + std::to_string(j) + ", range_deg: [-10, 10], l_m: 0.3}\n";
  }
  EXPECT_EQ(grid_error_of(text), "cell.yaml:4: joints: 9 joints given, expected 1 to 8");
  EXPECT_EQ(grid_error_of("name: none\nm_max_m: 0.18\njoints: []\n"),
            "cell.yaml:3: joints: 0 joints given, expected 1 to 8");
}

TEST(CellGrid, TooFineAGridIsRefused) {
  const std::string message = grid_error_of(replaced(kCell, "0.18", "0.0000001"));
  EXPECT_NE(message.find("more than 2^32 - 1 cells"), std::string::npos) << message;
}

}  // namespace
}  // namespace safecell
