#include "pointgen/sampling/surface_samples.hpp"

#include "pointgen/random.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace pointgen {
namespace {

float triangle_area(const TriangleMesh& m, std::size_t t) {
  const glm::vec3& a = m.positions[m.indices[t]];
  return 0.5f * glm::length(glm::cross(m.positions[m.indices[t + 1]] - a, m.positions[m.indices[t + 2]] - a));
}

// The radical inverse of i in `base`: i's digits mirrored about the point, in [0, 1).
double radical_inverse(std::uint64_t i, std::uint32_t base) {
  double inverse = 0.0, digit_weight = 1.0 / base;
  for (; i > 0; i /= base, digit_weight /= base) inverse += static_cast<double>(i % base) * digit_weight;
  return inverse;
}

// x + shift, wrapped into [0, 1).
double shifted(double x, double shift) {
  const double y = x + shift;
  return y >= 1.0 ? y - 1.0 : y;
}

// Places on a mesh's surface, the i-th from Halton's point i (bases 2 and 3) shifted by a random
// offset per list (Cranley-Patterson): the first coordinate picks a place along the triangles'
// cumulative area, so the triangle that holds it and how far into that triangle's share it lies,
// the second where across. The places of any prefix are within O(log n / n) of even, where
// independent draws leave gaps that show as holes at thin blades and leaf edges
// (docs/point_density.md).
class HaltonPlaces {
 public:
  HaltonPlaces(const TriangleMesh& mesh, std::uint64_t seed) : mesh_(mesh) {
    cumulative_.reserve(mesh.triangle_count());
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      total_ += triangle_area(mesh, t);
      cumulative_.push_back(total_);
    }
    Random rng(seed);
    shift_along_ = rng.uniform_double();
    shift_across_ = rng.uniform_double();
  }

  double total_area() const { return total_; }

  // The surface at place i, or nothing where the mesh's alpha mask cuts it away.
  std::optional<SurfaceSample> at(std::size_t i) const {
    const double pick = shifted(radical_inverse(i, 2), shift_along_) * total_;
    const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), pick);
    const std::size_t index = static_cast<std::size_t>(std::min<std::ptrdiff_t>(it - cumulative_.begin(),
                                                                               static_cast<std::ptrdiff_t>(cumulative_.size()) - 1));
    const double before = index > 0 ? cumulative_[index - 1] : 0.0;
    const double share = cumulative_[index] - before;
    // Uniform barycentric coordinates: fold the unit square onto the triangle.
    float u = share > 0.0 ? static_cast<float>(std::clamp((pick - before) / share, 0.0, 1.0)) : 0.0f;
    float v = static_cast<float>(shifted(radical_inverse(i, 3), shift_across_));
    if (u + v > 1.0f) {
      u = 1.0f - u;
      v = 1.0f - v;
    }
    const std::size_t t = 3 * index;
    const std::uint32_t a = mesh_.indices[t], b = mesh_.indices[t + 1], c = mesh_.indices[t + 2];
    const float w = 1.0f - u - v;
    glm::vec3 color = w * mesh_.colors[a] + u * mesh_.colors[b] + v * mesh_.colors[c];
    const std::optional<glm::vec4> texel = mesh_.kept_texel(t, u, v);
    if (!texel) return std::nullopt;
    color *= glm::vec3(*texel);
    const glm::vec3 normal = w * mesh_.normals[a] + u * mesh_.normals[b] + v * mesh_.normals[c];
    return SurfaceSample{w * mesh_.positions[a] + u * mesh_.positions[b] + v * mesh_.positions[c],
                         glm::length(normal) > 0.0f ? glm::normalize(normal) : glm::vec3(0, 1, 0), color};
  }

 private:
  const TriangleMesh& mesh_;
  std::vector<double> cumulative_;  // area up to and including each triangle
  double total_ = 0.0;
  double shift_along_ = 0.0, shift_across_ = 0.0;
};

// Places tried for each sample asked of a masked mesh, at most: a mask that keeps less than
// 1/64 of its cards gives a shorter list.
constexpr std::size_t max_tries_per_sample = 64;

}  // namespace

float surface_area(const TriangleMesh& mesh) {
  double area = 0.0;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) area += triangle_area(mesh, t);
  if (area <= 0.0 || !mesh.masked()) return static_cast<float>(area);
  // The kept share of a masked surface, from 2^16 places (within about 0.4 % of it).
  const HaltonPlaces places(mesh, 0x4a11);
  constexpr std::size_t tries = std::size_t{1} << 16;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < tries; ++i) kept += places.at(i).has_value();
  return static_cast<float>(area * static_cast<double>(kept) / static_cast<double>(tries));
}

std::vector<SurfaceSample> sample_surface(const TriangleMesh& mesh, std::size_t count, std::uint64_t seed) {
  std::vector<SurfaceSample> samples;
  const HaltonPlaces places(mesh, seed);
  if (places.total_area() <= 0.0) return samples;
  samples.reserve(count);
  // Places where a mask cuts the surface away are passed over: every prefix of the list stays a
  // uniform sample of the kept surface.
  const std::size_t tries = mesh.masked() ? max_tries_per_sample * count : count;
  for (std::size_t i = 0; i < tries && samples.size() < count; ++i) {
    if (std::optional<SurfaceSample> s = places.at(i)) samples.push_back(*s);
  }
  return samples;
}

}  // namespace pointgen
