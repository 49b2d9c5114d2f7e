#pragma once
// A two-joint arm written as URDF text, for the loader's tests, and helpers that load a variant
// of it and return the loader's error.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "safecell/robot/robot_error.hpp"
#include "safecell/robot/urdf_loader.hpp"

namespace safecell::test {

// A two-joint arm; {EXTRA} is replaced by each test.
inline constexpr const char* kTwoJointArm = R"(<?xml version="1.0"?>
<robot name="two">
  <link name="base"/>
  <joint name="a" type="revolute">
    <parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.5"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="2"/>
  </joint>
  <link name="upper">
    <collision><geometry><box size="0.1 0.1 0.4"/></geometry></collision>
  </link>
  <joint name="b" type="revolute">
    <parent link="upper"/><child link="lower"/>
    <origin xyz="0 0 0.4"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="1" velocity="2"/>
  </joint>
  <link name="lower">
    <collision><geometry><cylinder radius="0.05" length="0.3"/></geometry></collision>
  </link>
  {EXTRA}
</robot>)";

inline std::string arm_with(const std::string& extra) {
  std::string text = kTwoJointArm;
  return text.replace(text.find("{EXTRA}"), 7, extra);
}

inline std::string error_of(const std::string& xml, const UrdfOptions& options = {}) {
  try {
    static_cast<void>(parse_urdf(xml, "arm.urdf", std::filesystem::temp_directory_path(), options));
  } catch (const RobotError& error) {
    return error.what();
  }
  return "(no error)";
}

inline void expect_error(const std::string& message, const std::string& part) {
  EXPECT_EQ(message.rfind("arm.urdf:", 0), 0u) << message;
  EXPECT_NE(message.find(part), std::string::npos) << message;
}

}  // namespace safecell::test
