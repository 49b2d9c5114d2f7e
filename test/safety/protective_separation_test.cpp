#include "safecell/safety/protective_separation.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace safecell {
namespace {

TEST(ProtectiveSeparation, WorkedExample) {
  // v_h = 1.6 m/s, v_r = 1.0 m/s, T_r = 0.156 s, T_s = 0.300 s, S_s = 0.15 m, C = 0.10 m,
  // Z_d = 0.05 m, Z_r = 0.02 m:
  // S_h = 1.6 x (0.156 + 0.300) = 0.7296 m; S_r = 1.0 x 0.156 = 0.156 m;
  // S_p = 0.7296 + 0.156 + 0.15 + 0.10 + 0.05 + 0.02 = 1.2056 m.
  const SeparationInputs inputs{1.6, 1.0, 0.156, 0.300, 0.15, 0.10, 0.05, 0.02};
  EXPECT_NEAR(protective_separation_m(inputs).value(), 1.2056, 1e-12);
}

TEST(ProtectiveSeparation, RefusesInvalidInputs) {
  SeparationInputs inputs{1.6, 1.0, 0.156, 0.300, 0.15, 0.10, 0.05, 0.02};
  inputs.stop_distance_m = -0.1;
  EXPECT_EQ(protective_separation_m(inputs).error(), Status::kInvalidArgument);
  inputs.stop_distance_m = std::numeric_limits<double>::infinity();
  EXPECT_EQ(protective_separation_m(inputs).error(), Status::kInvalidArgument);
}

}  // namespace
}  // namespace safecell
