#include "app/view/flight_camera.hpp"

#include <algorithm>
#include <cmath>

namespace ecoview {
namespace {

constexpr float max_pitch = 1.55f;  // radians, about 89 degrees

}  // namespace

FlightCamera::FlightCamera(const shadow::Camera& start)
    : lens_(start),
      position_(start.position),
      // A tenth of the view distance per second: a second or so to cross what is in view.
      speed_(std::max(1.0f, 0.1f * start.far)),
      orbit_distance_(std::max(glm::length(start.target - start.position), 1.0f)) {
  place(start);
}

void FlightCamera::place(const shadow::Camera& camera) {
  position_ = camera.position;
  const glm::vec3 f = camera.forward();
  yaw_ = std::atan2(f.x, -f.z);
  pitch_ = std::clamp(std::asin(std::clamp(f.y, -1.0f, 1.0f)), -max_pitch, max_pitch);
  orbit_distance_ = std::max(glm::length(camera.target - camera.position), 1.0f);
}

glm::vec3 FlightCamera::forward() const {
  return {std::cos(pitch_) * std::sin(yaw_), std::sin(pitch_), -std::cos(pitch_) * std::cos(yaw_)};
}

void FlightCamera::orbit(float distance) {
  orbiting_ = true;
  if (distance > 0.0f) orbit_distance_ = distance;
}

void FlightCamera::scale_speed(float steps) { speed_ = std::clamp(speed_ * std::pow(1.25f, steps), 0.01f, 1e5f); }

void FlightCamera::update(const FlightInput& input, double seconds) {
  const auto dt = static_cast<float>(seconds);
  const glm::vec3 center = position_ + orbit_distance_ * forward();
  yaw_ += radians_per_pixel * input.look.x;
  pitch_ = std::clamp(pitch_ - radians_per_pixel * input.look.y, -max_pitch, max_pitch);
  if (orbiting_) {
    // Circling at the flight speed (on the orbit's horizontal circle at the camera's height).
    yaw_ -= input.move.x * speed_ * dt / orbit_distance_;
    orbit_distance_ = std::max(orbit_distance_ * std::exp(-input.move.z * dt), 0.1f);
    position_ = center - orbit_distance_ * forward() + glm::vec3(0.0f, input.move.y * speed_ * dt, 0.0f);
    return;
  }
  const glm::vec3 right(std::cos(yaw_), 0.0f, std::sin(yaw_));
  position_ += speed_ * dt * (input.move.x * right + input.move.y * glm::vec3(0, 1, 0) + input.move.z * forward());
}

shadow::Camera FlightCamera::camera() const {
  shadow::Camera camera = lens_;
  camera.position = position_;
  camera.target = position_ + orbit_distance_ * forward();
  camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
  return camera;
}

}  // namespace ecoview
