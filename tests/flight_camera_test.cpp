#include "app/view/flight_camera.hpp"

#include <gtest/gtest.h>

namespace ecoview {
namespace {

shadow::Camera start_camera() {
  shadow::Camera c;
  c.position = {0.0f, 2.0f, 10.0f};
  c.target = {4.0f, 1.0f, 0.0f};
  c.far = 300.0f;
  return c;
}

void expect_near(const glm::vec3& a, const glm::vec3& b, float tolerance) {
  EXPECT_LT(glm::length(a - b), tolerance) << "(" << a.x << ", " << a.y << ", " << a.z << ") against (" << b.x << ", " << b.y
                                           << ", " << b.z << ")";
}

TEST(FlightCamera, StartsWhereTheSceneCameraLooks) {
  const shadow::Camera start = start_camera();
  const shadow::Camera c = FlightCamera(start).camera();
  expect_near(c.position, start.position, 1e-5f);
  expect_near(c.forward(), start.forward(), 1e-5f);
  EXPECT_FLOAT_EQ(c.fov_y_deg, start.fov_y_deg);
  EXPECT_FLOAT_EQ(c.far, start.far);
}

TEST(FlightCamera, MotionDoesNotDependOnTheFrameRate) {
  FlightCamera fast(start_camera()), slow(start_camera());
  FlightInput input;
  input.move = {0.5f, 0.2f, 1.0f};
  for (int i = 0; i < 60; ++i) fast.update(input, 1.0 / 60.0);
  slow.update(input, 1.0);
  expect_near(fast.camera().position, slow.camera().position, 1e-3f);
  // Zooming an orbit scales the distance by e^-t whatever the steps.
  fast.orbit(20.0f);
  slow.orbit(20.0f);
  input.move = {0.0f, 0.0f, 1.0f};
  for (int i = 0; i < 60; ++i) fast.update(input, 1.0 / 60.0);
  slow.update(input, 1.0);
  expect_near(fast.camera().position, slow.camera().position, 1e-3f);
  // Forward for a second goes speed metres along the view.
  FlightCamera forward(start_camera());
  forward.update({{0.0f, 0.0f, 1.0f}, {0.0f, 0.0f}}, 1.0);
  expect_near(forward.camera().position, start_camera().position + forward.speed() * start_camera().forward(), 1e-3f);
}

TEST(FlightCamera, MouseTurnsAndPitchStopsShortOfVertical) {
  FlightCamera camera(start_camera());
  const glm::vec3 before = camera.camera().forward();
  // Mouse to the right turns to the right: the view turns clockwise seen from above.
  camera.update({{}, {100.0f, 0.0f}}, 0.0);
  const glm::vec3 after = camera.camera().forward();
  EXPECT_LT(glm::cross(before, after).y, 0.0f);
  EXPECT_NEAR(std::acos(glm::dot(glm::normalize(glm::vec2(before.x, before.z)), glm::normalize(glm::vec2(after.x, after.z)))),
              100.0f * FlightCamera::radians_per_pixel, 1e-4f);
  camera.update({{}, {0.0f, -1e6f}}, 0.0);  // far up
  EXPECT_LT(camera.camera().forward().y, 0.9999f);
  EXPECT_GT(glm::length(glm::cross(camera.camera().forward(), camera.camera().up)), 1e-3f);
}

TEST(FlightCamera, OrbitKeepsThePointInViewAndItsDistance) {
  const shadow::Camera start = start_camera();
  FlightCamera camera(start);
  const float distance = 0.5f * glm::length(start.target - start.position);
  const glm::vec3 center = start.position + distance * start.forward();
  camera.orbit(distance);
  camera.update({{1.0f, 0.0f, 0.0f}, {250.0f, 80.0f}}, 0.7);
  const shadow::Camera c = camera.camera();
  EXPECT_NEAR(glm::length(c.target - c.position), distance, 1e-3f * distance);
  expect_near(c.target, center, 1e-3f * distance);
  EXPECT_GT(glm::length(c.position - start.position), 1.0f);
  // Forward moves nearer, in proportion: e^-1 of the distance after a second.
  camera.update({{0.0f, 0.0f, 1.0f}, {}}, 1.0);
  EXPECT_NEAR(glm::length(camera.camera().target - camera.camera().position), distance * std::exp(-1.0f), 1e-3f * distance);
  expect_near(camera.camera().target, center, 1e-3f * distance);
  // Back to flight: the camera flies from where the orbit left it.
  camera.fly();
  const shadow::Camera before = camera.camera();
  camera.update({{0.0f, 0.0f, 1.0f}, {}}, 1.0);
  expect_near(camera.camera().position, before.position + camera.speed() * before.forward(), 1e-3f);
}

// A speed step is 1.25 times (two make 1.5625); place() takes the given pose as it is.
TEST(FlightCamera, SpeedStepsByAQuarterAndPlaceTakesThePose) {
  FlightCamera camera(start_camera());
  const float speed = camera.speed();
  camera.scale_speed(2.0f);
  EXPECT_NEAR(camera.speed(), speed * 1.5625f, 1e-4f * speed);
  shadow::Camera elsewhere = start_camera();
  elsewhere.position = {50.0f, 5.0f, 0.0f};
  elsewhere.target = {50.0f, 5.0f, -10.0f};
  camera.place(elsewhere);
  expect_near(camera.camera().position, elsewhere.position, 1e-5f);
  expect_near(camera.camera().forward(), glm::vec3(0, 0, -1), 1e-5f);
}

}  // namespace
}  // namespace ecoview
