#include "shadow/convex_body.hpp"

#include <algorithm>
#include <cmath>

namespace shadow {
namespace {

// The largest coordinate of a body's vertices.
float extent(const std::vector<ConvexBody::Polygon>& faces) {
  float scale = 0.0f;
  for (const auto& face : faces) {
    for (const glm::vec3& p : face) scale = std::max({scale, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  }
  return scale;
}

// Tolerance for "on the plane", relative to the size of the numbers in the distances.
float tolerance(float body_extent, const Plane& plane) {
  return 1e-5f * std::max({body_extent, std::abs(plane.offset), 1.0f});
}

void add_distinct(std::vector<glm::vec3>& points, const glm::vec3& p, float eps) {
  for (const glm::vec3& q : points) {
    if (glm::all(glm::lessThanEqual(glm::abs(p - q), glm::vec3(eps)))) return;
  }
  points.push_back(p);
}

// Orders points lying in a plane into a loop around their centroid.
ConvexBody::Polygon loop_in_plane(std::vector<glm::vec3> points, const glm::vec3& normal) {
  glm::vec3 centroid(0.0f);
  for (const glm::vec3& p : points) centroid += p;
  centroid /= static_cast<float>(points.size());
  const glm::vec3 u = glm::normalize(std::abs(normal.x) < 0.9f ? glm::cross(normal, glm::vec3(1, 0, 0))
                                                               : glm::cross(normal, glm::vec3(0, 1, 0)));
  const glm::vec3 v = glm::cross(normal, u);
  std::sort(points.begin(), points.end(), [&](const glm::vec3& a, const glm::vec3& b) {
    return std::atan2(glm::dot(a - centroid, v), glm::dot(a - centroid, u)) <
           std::atan2(glm::dot(b - centroid, v), glm::dot(b - centroid, u));
  });
  return points;
}

// Where the edge a-b crosses the plane, computed from the same end whichever face walks the edge,
// so neighbouring faces get the very same point.
glm::vec3 crossing(const glm::vec3& a, const glm::vec3& b, float da, float db) {
  const bool a_first = a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.z < b.z)));
  return a_first ? a + (b - a) * (da / (da - db)) : b + (a - b) * (db / (db - da));
}

glm::vec3 centroid_of(const std::vector<glm::vec3>& points) {
  glm::vec3 sum(0.0f);
  for (const glm::vec3& p : points) sum += p;
  return points.empty() ? sum : sum / static_cast<float>(points.size());
}

}  // namespace

ConvexBody ConvexBody::from_box(const Box& box) {
  std::array<glm::vec3, 8> corners;
  for (int i = 0; i < 8; ++i) corners[static_cast<std::size_t>(i)] = box.corner(i);
  return from_corners(corners);
}

ConvexBody ConvexBody::from_corners(const std::array<glm::vec3, 8>& corners) {
  ConvexBody body;
  for (int axis = 0; axis < 3; ++axis) {
    const int b = 1 << ((axis + 1) % 3);
    const int c = 1 << ((axis + 2) % 3);
    for (int side = 0; side < 2; ++side) {
      const int base = side << axis;
      body.faces_.push_back({corners[static_cast<std::size_t>(base)], corners[static_cast<std::size_t>(base | b)],
                             corners[static_cast<std::size_t>(base | b | c)], corners[static_cast<std::size_t>(base | c)]});
    }
  }
  return body;
}

void ConvexBody::clip(const Plane& plane) {
  const float body_extent = extent(faces_);
  const float eps = tolerance(body_extent, plane);
  // Points closer than this are one vertex: relative to the body alone, so that a far plane does
  // not merge a small body's vertices.
  const float merge = 1e-5f * std::max(body_extent, 1e-30f);
  std::vector<Polygon> kept_faces;
  std::vector<glm::vec3> cut;  // points on the plane, which become the cap face
  for (const Polygon& face : faces_) {
    Polygon kept;
    for (std::size_t i = 0; i < face.size(); ++i) {
      const glm::vec3& a = face[i];
      const glm::vec3& b = face[(i + 1) % face.size()];
      const float da = plane.distance(a);
      const float db = plane.distance(b);
      if (da <= eps) kept.push_back(a);
      if (std::abs(da) <= eps) add_distinct(cut, a, merge);
      if ((da < -eps && db > eps) || (da > eps && db < -eps)) {
        const glm::vec3 x = crossing(a, b, da, db);
        kept.push_back(x);
        add_distinct(cut, x, merge);
      }
    }
    std::vector<glm::vec3> distinct;
    for (const glm::vec3& p : kept) add_distinct(distinct, p, merge);
    if (distinct.size() >= 3) kept_faces.push_back(std::move(distinct));
  }
  if (cut.size() >= 3 && !kept_faces.empty()) kept_faces.push_back(loop_in_plane(cut, plane.normal));
  faces_ = std::move(kept_faces);
}

void ConvexBody::clip(std::span<const Plane> planes) {
  for (const Plane& plane : planes) {
    if (empty()) return;
    clip(plane);
  }
}

ConvexBody ConvexBody::transformed(const glm::mat4& transform) const {
  ConvexBody body = *this;
  for (Polygon& face : body.faces_) {
    for (glm::vec3& p : face) {
      const glm::vec4 q = transform * glm::vec4(p, 1.0f);
      p = glm::vec3(q) / q.w;
    }
  }
  return body;
}

std::vector<glm::vec3> ConvexBody::vertices() const {
  float scale = 1.0f;
  for (const Polygon& face : faces_) {
    for (const glm::vec3& p : face) scale = std::max({scale, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  }
  std::vector<glm::vec3> points;
  for (const Polygon& face : faces_) {
    for (const glm::vec3& p : face) add_distinct(points, p, 1e-6f * scale);
  }
  return points;
}

glm::vec3 ConvexBody::centroid() const { return centroid_of(vertices()); }

std::vector<Plane> ConvexBody::face_planes() const {
  const glm::vec3 inside = centroid();
  std::vector<Plane> planes;
  for (const Polygon& face : faces_) {
    float face_size = 0.0f;
    for (const glm::vec3& p : face) face_size = std::max(face_size, glm::distance(p, face[0]));
    glm::vec3 normal(0.0f);  // Newell's method: robust for slightly non-planar loops
    for (std::size_t i = 0; i < face.size(); ++i) {
      const glm::vec3& a = face[i];
      const glm::vec3& b = face[(i + 1) % face.size()];
      normal += glm::vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    if (glm::length(normal) <= 1e-6f * face_size * face_size) continue;  // a sliver: no reliable plane
    const glm::vec3 center = centroid_of(face);
    if (glm::dot(normal, inside - center) > 0.0f) normal = -normal;
    planes.push_back(Plane::through(center, normal));
  }
  return planes;
}

}  // namespace shadow
