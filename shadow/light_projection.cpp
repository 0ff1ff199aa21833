#include "shadow/light_projection.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace shadow {
namespace {

const float max_half_angle_tan = std::tan(glm::radians(max_single_map_half_angle_deg));
// The nearest caster's w at least this share of the farthest receiver's: casters right at a point
// light are cut off for the depth precision of the rest.
constexpr float min_w_ratio = 1e-3f;

glm::vec3 any_perpendicular(const glm::vec3& v) {
  return glm::normalize(std::abs(v.y) < 0.9f ? glm::cross(v, glm::vec3(0, 1, 0))
                                             : glm::cross(v, glm::vec3(1, 0, 0)));
}

// The plane dot(normal, p) = offset, scaled to a unit normal.
Plane unit_plane(const glm::vec3& normal, float offset) {
  const float length = glm::length(normal);
  return {normal / length, offset / length};
}

// The projection in the light frame (x, y across; t = -z along the rays, 0 at the receivers'
// centre; k = 1 / signed distance from the light to that centre, 0 for a light at infinity):
//   w = 1 + k t,  x_ndc = (2 x / w - (hi.x + lo.x)) / (hi.x - lo.x), likewise y,
//   z_ndc = (alpha t + beta) / w, -1 at t0 and 1 at t1,
// which is a perspective projection from the light at t = -1/k (behind the receivers for k > 0,
// beyond them for an inverted light, k < 0) and an orthographic one at k = 0. Depth grows with t
// wherever w > 0.
glm::mat4 projection(float k, glm::vec2 lo, glm::vec2 hi, float t0, float t1) {
  const float alpha = (2.0f + k * (t0 + t1)) / (t1 - t0);
  const float beta = -(1.0f + k * t0) - alpha * t0;
  const glm::vec2 size = hi - lo, sum = hi + lo;
  glm::mat4 m(0.0f);  // m[column][row]; the frame's z is -t
  m[0][0] = 2.0f / size.x;
  m[2][0] = sum.x * k / size.x;
  m[3][0] = -sum.x / size.x;
  m[1][1] = 2.0f / size.y;
  m[2][1] = sum.y * k / size.y;
  m[3][1] = -sum.y / size.y;
  m[2][2] = -alpha;
  m[3][2] = beta;
  m[2][3] = -k;
  m[3][3] = 1.0f;
  return m;
}

}  // namespace

Cone cone_around(const glm::vec3& apex, const std::vector<glm::vec3>& points) {
  glm::vec3 sum(0.0f);
  for (const glm::vec3& p : points) {
    if (glm::length(p - apex) > 0.0f) sum += glm::normalize(p - apex);
  }
  if (glm::length(sum) < 1e-6f) return {glm::vec3(0, -1, 0), -1.0f};
  Cone cone{glm::normalize(sum), 1.0f};
  for (const glm::vec3& p : points) {
    if (glm::length(p - apex) > 0.0f) cone.cos_half_angle = std::min(cone.cos_half_angle, glm::dot(cone.axis, glm::normalize(p - apex)));
  }
  return cone;
}

glm::vec3 light_up(const glm::vec3& axis, const glm::vec3& forward) {
  const glm::vec3 up = forward - glm::dot(forward, axis) * axis;
  return glm::length(up) > 1e-3f ? glm::normalize(up) : any_perpendicular(axis);
}

std::optional<ShadowView> fit_light_view(const glm::vec4& light, const FocusBodies& bodies, const glm::vec3& forward) {
  if (bodies.receivers.empty()) return std::nullopt;
  const glm::vec4 q = light / glm::length(light);
  const glm::vec3 c = bodies.receivers.centroid();
  // At a point p the rays travel along w p - xyz, whatever the sign of w.
  const glm::vec3 travel = q.w * c - glm::vec3(q);
  if (!(glm::length(travel) > 1e-6f)) return std::nullopt;
  const glm::vec3 axis = glm::normalize(travel);
  const float k = q.w / glm::length(travel);
  const glm::mat4 frame = glm::lookAt(c, c + axis, light_up(axis, forward));

  // Across: the receivers as seen from the light.
  float t1 = -INFINITY, w_near = INFINITY, w_far = 0.0f;
  glm::vec2 lo(INFINITY), hi(-INFINITY);
  const std::vector<glm::vec3> receivers = bodies.receivers.transformed(frame).vertices();
  for (const glm::vec3& p : receivers) {
    const float t = -p.z, w = 1.0f + k * t;
    if (!(w > min_w_ratio)) return std::nullopt;  // the light among or before the receivers
    if (std::abs(k) * glm::length(glm::vec2(p)) > max_half_angle_tan * w) return std::nullopt;
    lo = glm::min(lo, glm::vec2(p) / w);
    hi = glm::max(hi, glm::vec2(p) / w);
    t1 = std::max(t1, t);
    w_near = std::min(w_near, w);
    w_far = std::max(w_far, w);
  }
  const float w_min = min_w_ratio * w_far;
  if (w_near < w_min) return std::nullopt;  // receivers too near the light for the depth range
  const glm::vec2 pad = 0.01f * (hi - lo) + 1e-6f * (glm::abs(lo) + glm::abs(hi)) + 1e-6f;
  lo -= pad;
  hi += pad;

  // In depth: from the first caster inside the rays through the map to the last receiver.
  ConvexBody casters = bodies.casters.transformed(frame);
  const Plane sides[4] = {unit_plane({1, 0, hi.x * k}, hi.x), unit_plane({-1, 0, -lo.x * k}, -lo.x),
                          unit_plane({0, 1, hi.y * k}, hi.y), unit_plane({0, -1, -lo.y * k}, -lo.y)};
  casters.clip(sides);
  if (k != 0.0f) casters.clip(unit_plane({0, 0, k}, 1.0f - w_min));  // w >= w_min
  float t0 = t1;
  for (const glm::vec3& p : casters.vertices()) t0 = std::min(t0, -p.z);
  for (const glm::vec3& p : receivers) t0 = std::min(t0, -p.z);
  const float depth_pad = 0.01f * (t1 - t0) + 1e-6f * (std::abs(t0) + std::abs(t1)) + 1e-6f;
  t0 -= depth_pad;
  t1 += depth_pad;
  if (k > 0.0f) t0 = std::max(t0, (0.5f * w_min - 1.0f) / k);  // the padding stays off the light
  if (k < 0.0f) t1 = std::min(t1, (0.5f * w_min - 1.0f) / k);
  return ShadowView{frame, projection(k, lo, hi, t0, t1)};
}

}  // namespace shadow
