#include "shadow/focus_body.hpp"

#include <algorithm>
#include <cmath>

namespace shadow {

std::array<glm::vec3, 8> frustum_corners(const glm::mat4& view_projection) {
  const glm::mat4 inverse = glm::inverse(view_projection);
  std::array<glm::vec3, 8> corners;
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 ndc((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f, 1.0f);
    const glm::vec4 world = inverse * ndc;
    corners[static_cast<std::size_t>(i)] = glm::vec3(world) / world.w;
  }
  return corners;
}

std::vector<Plane> light_frustum_planes(const Light& light) {
  if (light.type != LightType::spot) return {};
  const glm::vec3 axis = glm::normalize(light.direction);
  const glm::vec3 u = glm::normalize(std::abs(axis.y) < 0.9f ? glm::cross(axis, glm::vec3(0, 1, 0))
                                                             : glm::cross(axis, glm::vec3(1, 0, 0)));
  const glm::vec3 v = glm::cross(axis, u);
  const float t = std::tan(glm::radians(light.cone_deg));
  std::vector<Plane> planes;
  for (const glm::vec3& side : {u, -u, v, -v}) planes.push_back(Plane::through(light.position, side - t * axis));
  return planes;
}

std::vector<Plane> hull_with_light(const ConvexBody& body, const Light& light) {
  const bool directional = light.type == LightType::directional;
  const glm::vec3 towards_light = -glm::normalize(light.direction);
  const std::vector<glm::vec3> points = body.vertices();
  float scale = 1.0f;
  for (const glm::vec3& p : points) scale = std::max({scale, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  const float eps = 1e-5f * scale;

  std::vector<Plane> planes;
  // Faces the light does not see stay faces of the hull.
  for (const Plane& face : body.face_planes()) {
    const bool sees_face = directional ? glm::dot(face.normal, towards_light) > 1e-6f
                                       : face.distance(light.position) > eps;
    if (!sees_face) planes.push_back(face);
  }
  // The other faces of the hull contain the light and two vertices of the body (a silhouette
  // edge): every such plane that has the whole body on one side supports the hull.
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (std::size_t j = i + 1; j < points.size(); ++j) {
      const glm::vec3 edge = points[j] - points[i];
      const glm::vec3 normal = directional ? glm::cross(edge, towards_light)
                                           : glm::cross(edge, light.position - points[i]);
      if (glm::length(normal) <= 1e-6f * glm::length(edge) * (directional ? 1.0f : glm::length(light.position - points[i]))) continue;
      const Plane plane = Plane::through(points[i], normal);
      bool below = true, above = true;
      for (const glm::vec3& p : points) {
        const float d = plane.distance(p);
        below = below && d <= eps;
        above = above && d >= -eps;
      }
      if (below) planes.push_back(plane);
      else if (above) planes.push_back({-plane.normal, -plane.offset});
    }
  }
  return planes;
}

FocusBodies focus_bodies(const glm::mat4& view_projection, const Light& light, const Box& scene) {
  const ConvexBody view = ConvexBody::from_corners(frustum_corners(view_projection));
  const std::vector<Plane> light_frustum = light_frustum_planes(light);

  FocusBodies bodies{ConvexBody::from_box(scene), ConvexBody::from_box(scene)};
  bodies.receivers.clip(view.face_planes());
  bodies.receivers.clip(light_frustum);
  bodies.casters.clip(hull_with_light(view, light));
  bodies.casters.clip(light_frustum);
  return bodies;
}

FocusBodies or_scene(FocusBodies bodies, const Light& light, const Box& scene) {
  if (bodies.receivers.empty()) {
    bodies.receivers = ConvexBody::from_box(scene);
    bodies.receivers.clip(light_frustum_planes(light));
    bodies.casters = bodies.receivers;
  }
  if (bodies.receivers.empty()) bodies.receivers = bodies.casters = ConvexBody::from_box(scene);
  return bodies;
}

}  // namespace shadow
