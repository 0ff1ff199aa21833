#include "app/errors.hpp"
#include "app/scene/camera_path.hpp"

#include <gtest/gtest.h>

namespace ecoview {
namespace {

CameraPath load_path(const std::string& json) {
  return CameraPath::load({"path.json", json, [](const std::string&) { return std::nullopt; }});
}

const char* three_keys = R"([{"t": 0, "position": [0, 5, 10], "target": [0, 0, 0]},
                             {"t": 1, "position": [10, 5, 0], "target": [0, 1, 0]},
                             {"t": 3, "position": [0, 5, -10], "target": [0, 0, 0]}])";

TEST(CameraPath, PassesThroughEveryKeyAndHoldsAtTheEnds) {
  const CameraPath path = load_path(three_keys);
  const shadow::Camera base;
  EXPECT_DOUBLE_EQ(path.duration(), 3.0);
  const glm::vec3 at_key = path.at(1.0, base).position;
  EXPECT_NEAR(at_key.x, 10.0f, 1e-5f);
  EXPECT_NEAR(at_key.z, 0.0f, 1e-5f);
  EXPECT_NEAR(path.at(1.0, base).target.y, 1.0f, 1e-5f);
  EXPECT_NEAR(path.at(-5.0, base).position.z, 10.0f, 1e-5f);
  EXPECT_NEAR(path.at(99.0, base).position.z, -10.0f, 1e-5f);
  EXPECT_FLOAT_EQ(path.at(2.0, base).fov_y_deg, base.fov_y_deg);
}

TEST(CameraPath, IsSmoothAcrossKeys) {
  const CameraPath path = load_path(three_keys);
  const shadow::Camera base;
  // The velocity just before and just after the middle key agrees (C1 continuity).
  const float h = 1e-3f;
  const glm::vec3 before = (path.at(1.0, base).position - path.at(1.0 - h, base).position) / h;
  const glm::vec3 after = (path.at(1.0 + h, base).position - path.at(1.0, base).position) / h;
  EXPECT_LT(glm::length(before - after), 0.05f * glm::length(before));
}

TEST(CameraPath, WrittenKeysReadBackExactly) {
  const CameraPath path({{0.0, {0.1f, 1e-7f, -3.3f}, {1.0f / 3.0f, 2.0f, 0.7f}, {0.0f, 1.0f, 0.0f}},
                         {0.0333, {1.23456789f, 5.0f, -3.0f}, {2.0f, 2.0f, 2.0f}, {0.0f, 0.0f, 1.0f}}});
  const CameraPath again = load_path(path.json());
  for (double t : {0.0, 0.0333, 0.02}) {
    const shadow::Camera a = path.at(t, shadow::Camera{}), b = again.at(t, shadow::Camera{});
    EXPECT_EQ(a.position, b.position);
    EXPECT_EQ(a.target, b.target);
    EXPECT_EQ(a.up, b.up);
  }
}

TEST(CameraPath, JsonNestedDeeperThan256LevelsIsRefusedAtItsPlace) {
  try {
    load_path(std::string(100000, '[') + std::string(100000, ']'));
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "path.json:1:257: invalid JSON: nested deeper than 256 levels");
  }
}

TEST(CameraPath, BadKeysAreNamed) {
  auto expect_error = [](const std::string& json, const char* field) {
    try {
      load_path(json);
      ADD_FAILURE() << "no error for " << json;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  expect_error(R"([{"t": 1, "position": [0, 5, 10], "target": [0, 0, 0]},
                   {"t": 1, "position": [1, 5, 10], "target": [0, 0, 0]}])", "[1].t");
  expect_error(R"([{"t": 0, "position": [0, 5], "target": [0, 0, 0]}])", "[0].position");
  expect_error(R"([{"t": 0, "position": [0, 5, NaN], "target": [0, 0, 0]}])", "path.json:1:");
  expect_error(R"([])", "at least 1");
  expect_error(R"({"t": 0})", "array");
}

}  // namespace
}  // namespace ecoview
