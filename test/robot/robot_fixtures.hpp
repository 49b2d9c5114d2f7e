#pragma once
// Robots the tests share: the built-in arm and, when ../shared/data is there, the real RX160.

#include <filesystem>
#include <optional>

#include "safecell/robot/default_robot.hpp"
#include "safecell/robot/urdf_loader.hpp"

namespace safecell::test {

inline std::filesystem::path rx160_urdf_path() {
  return std::filesystem::path(SAFECELL_SHARED_DATA_DIR) / "robots/staubli_rx160/rx160.urdf";
}

// The RX160, or nullopt (the caller skips) when the shared data folder is absent.
inline std::optional<RobotModel> rx160() {
  if (!std::filesystem::exists(rx160_urdf_path())) return std::nullopt;
  return load_urdf_file(rx160_urdf_path());
}

#define SAFECELL_REQUIRE_RX160(model)                                            \
  const auto model##_loaded = ::safecell::test::rx160();                         \
  if (!model##_loaded)                                                           \
    GTEST_SKIP() << "no RX160 model at " << ::safecell::test::rx160_urdf_path(); \
  const RobotModel& model = *model##_loaded

}  // namespace safecell::test
