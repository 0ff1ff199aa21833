#pragma once
#include "shadow/camera.hpp"

namespace ecoview {

// What the user asks of the camera in one frame (ecoview view): keys held and mouse movement.
struct FlightInput {
  glm::vec3 move{0.0f};  // each -1..1: right, up, forward (keys held)
  glm::vec2 look{0.0f};  // mouse movement in pixels, x to the right, y down
};

// Mouse-look and WASD flight, or an orbit around a point. Motion is speed × elapsed seconds, so
// it does not depend on the frame rate. Up stays +Y; the pitch stays short of straight up or down.
class FlightCamera {
 public:
  explicit FlightCamera(const shadow::Camera& start);

  void update(const FlightInput& input, double seconds);
  // Orbit around the point `distance` ahead (the surface in view): the mouse turns the camera
  // around it, forward and back move nearer and farther in proportion to the distance, right and
  // left circle around it, up and down move it and the camera up and down.
  void orbit(float distance);
  void fly() { orbiting_ = false; }
  bool orbiting() const { return orbiting_; }
  // Flight speed in metres per second, scaled by 1.25 per step.
  void scale_speed(float steps);
  float speed() const { return speed_; }
  shadow::Camera camera() const;
  // Takes the pose of `camera` (a path playing, for example).
  void place(const shadow::Camera& camera);

  static constexpr float radians_per_pixel = 0.0025f;

 private:
  glm::vec3 forward() const;

  shadow::Camera lens_;  // field of view, near, far
  glm::vec3 position_;
  float yaw_ = 0.0f, pitch_ = 0.0f;  // radians; yaw 0 looks along -Z
  float speed_;
  bool orbiting_ = false;
  float orbit_distance_;  // to the point the camera looks at: the scene camera's target, or the orbit's centre
};

}  // namespace ecoview
