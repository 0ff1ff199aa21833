#include "pointgen/placement/ecosystem.hpp"

#include "pointgen/placement/poisson_disk.hpp"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace pointgen {
namespace {

constexpr int layer_count = 3;

// A species' density over the area: Gaussian groves around random centres, on a coarse grid.
class DensityMap {
 public:
  DensityMap(const glm::vec2& min, const glm::vec2& size, int count, Random& rng) : min_(min), size_(size) {
    const int groves = std::clamp(count / 150, 2, 64);
    const float sigma = 0.35f * std::sqrt(size.x * size.y / static_cast<float>(groves));
    std::vector<glm::vec2> centers;
    for (int g = 0; g < groves; ++g) centers.push_back(min + size * glm::vec2(rng.uniform(), rng.uniform()));
    for (int j = 0; j < side; ++j) {
      for (int i = 0; i < side; ++i) {
        const glm::vec2 p = min + size * (glm::vec2(i, j) + 0.5f) / static_cast<float>(side);
        float w = 0.05f;  // a few strays everywhere
        for (const glm::vec2& c : centers) w += std::exp(-glm::dot(p - c, p - c) / (2.0f * sigma * sigma));
        values_[static_cast<std::size_t>(j * side + i)] = w;
      }
    }
  }
  float at(const glm::vec2& p) const {
    const glm::ivec2 c = glm::clamp(glm::ivec2((p - min_) / size_ * static_cast<float>(side)), 0, side - 1);
    return values_[static_cast<std::size_t>(c.y * side + c.x)];
  }

 private:
  static constexpr int side = 64;
  glm::vec2 min_, size_;
  std::vector<float> values_ = std::vector<float>(side * side);
};

bool in_clearing(const glm::vec2& p, const std::vector<glm::vec3>& clearings) {
  return std::any_of(clearings.begin(), clearings.end(), [&](const glm::vec3& c) { return glm::distance(p, glm::vec2(c.x, c.y)) < c.z; });
}

// Poisson-disk points for `count` plants outside the clearings, with some to spare for the density
// maps' picks (about 1.16 per plant at this radius); the radius shrinks until the points suffice.
std::vector<glm::vec2> layer_points(const glm::vec2& min, const glm::vec2& size, int count,
                                    const std::vector<glm::vec3>& clearings, Random& rng, float& radius) {
  radius = std::sqrt(size.x * size.y / (2.0f * static_cast<float>(count)));
  for (int attempt = 0; attempt < 12; ++attempt) {  // the radius may shrink to a third
    std::vector<glm::vec2> points = poisson_disk(min, min + size, radius, rng);
    const auto free = std::count_if(points.begin(), points.end(), [&](const glm::vec2& p) { return !in_clearing(p, clearings); });
    if (free >= count) return points;
    radius *= 0.9f;
  }
  throw std::invalid_argument("the clearings leave too little room for " + std::to_string(count) + " plants");
}

// Picks `count` of the points not yet taken, each with probability growing with its density
// (weighted sampling without replacement: the largest keys u^(1/w)).
std::vector<std::size_t> pick(const std::vector<glm::vec2>& points, std::vector<bool>& taken, const DensityMap& density,
                              int count, Random& rng) {
  std::vector<std::pair<float, std::size_t>> keys;
  keys.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const float u = std::max(rng.uniform(), 1e-12f);
    if (!taken[i]) keys.emplace_back(std::log(u) / density.at(points[i]), i);
  }
  const auto n = static_cast<std::size_t>(count);
  std::nth_element(keys.begin(), keys.begin() + static_cast<std::ptrdiff_t>(n), keys.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first || (a.first == b.first && a.second < b.second); });
  std::vector<bool> picked(points.size(), false);
  for (std::size_t k = 0; k < n; ++k) picked[keys[k].second] = true;
  std::vector<std::size_t> chosen;
  chosen.reserve(n);
  for (std::size_t i = 0; i < points.size(); ++i) {  // in point order
    if (picked[i]) chosen.push_back(i);
  }
  for (std::size_t i : chosen) taken[i] = true;
  return chosen;
}

// Rough triangle counts per plant, for the memory estimate.
std::size_t typical_triangles(PlantKind kind) {
  switch (kind) {
    case PlantKind::broadleaf: return 6000;
    case PlantKind::conifer: return 1500;
    case PlantKind::bush: return 4000;
    default: return 600;
  }
}

}  // namespace

int placement_layer(PlantKind kind) {
  switch (kind) {
    case PlantKind::bush: return 1;
    case PlantKind::grass:
    case PlantKind::flower: return 2;
    default: return 0;
  }
}

int placement_layer(const PlantRequest& request) {
  return request.mesh ? request.layer : placement_layer(request.species.kind);
}

std::size_t estimated_bytes(const EcosystemSpec& spec) {
  // Per instance: its table row, its GPU instance record, placement scratch (the Poisson-disk
  // grid's four cells of 8 bytes, the points twice, the picks' keys).
  constexpr std::size_t per_instance = 64 + 128 + 72;
  constexpr std::size_t per_triangle = 3 * 36 + 12;  // CPU and GPU copies of vertices and indices, about
  std::size_t bytes = static_cast<std::size_t>(spec.terrain.resolution) * static_cast<std::size_t>(spec.terrain.resolution) * 2 * per_triangle;
  for (const PlantRequest& r : spec.plants) {
    const std::size_t triangles = r.mesh ? r.mesh->triangle_count() : static_cast<std::size_t>(r.variants) * typical_triangles(r.species.kind);
    bytes += static_cast<std::size_t>(r.count) * per_instance + triangles * per_triangle * 2;
  }
  return bytes;
}

Ecosystem grow_ecosystem(const EcosystemSpec& spec) {
  Ecosystem eco{Terrain(spec.terrain), {}, {}, {}, std::vector<float>(layer_count, 0.0f)};
  eco.meshes.push_back(eco.terrain.mesh());
  eco.mesh_names.push_back("terrain");
  eco.tables.push_back({0, {}, {}, {}});
  eco.tables[0].add(glm::mat4(1.0f), glm::vec3(1.0f), derive_seed(spec.seed, 0));

  // Each species' variants, grown from seeds of their own.
  std::vector<std::size_t> first_mesh;
  for (std::size_t s = 0; s < spec.plants.size(); ++s) {
    first_mesh.push_back(eco.meshes.size());
    const PlantRequest& r = spec.plants[s];
    if (r.mesh) {
      eco.meshes.push_back(*r.mesh);
      eco.mesh_names.push_back(r.species.name);
      eco.tables.push_back({eco.meshes.size() - 1, {}, {}, {}});
      continue;
    }
    for (int v = 0; v < r.variants; ++v) {
      eco.meshes.push_back(build_plant(r.species, derive_seed(derive_seed(spec.seed, 1000 + s), static_cast<std::uint64_t>(v))));
      eco.mesh_names.push_back(r.species.name + " " + std::to_string(v + 1));
      eco.tables.push_back({eco.meshes.size() - 1, {}, {}, {}});
    }
  }

  const glm::vec2 min = spec.terrain.center - 0.5f * spec.terrain.size;
  const std::uint64_t instance_seeds = derive_seed(spec.seed, 0x1257a9ce);  // apart from the layers' seeds
  std::uint64_t instance_id = 1;  // 0 is the terrain
  for (int layer = 0; layer < layer_count; ++layer) {
    int total = 0;
    for (const PlantRequest& r : spec.plants) total += placement_layer(r) == layer ? r.count : 0;
    if (total == 0) continue;
    Random rng(derive_seed(spec.seed, 100 + static_cast<std::uint64_t>(layer)));
    const std::vector<glm::vec2> points = layer_points(min, spec.terrain.size, total, layer < 2 ? spec.clearings : std::vector<glm::vec3>{},
                                                       rng, eco.layer_radius[static_cast<std::size_t>(layer)]);
    std::vector<bool> taken(points.size(), false);
    if (layer < 2) {  // trees and bushes keep out of the clearings
      for (std::size_t i = 0; i < points.size(); ++i) taken[i] = in_clearing(points[i], spec.clearings);
    }
    for (std::size_t s = 0; s < spec.plants.size(); ++s) {
      const PlantRequest& r = spec.plants[s];
      if (placement_layer(r) != layer || r.count == 0) continue;
      const DensityMap density(min, spec.terrain.size, r.count, rng);
      for (std::size_t i : pick(points, taken, density, r.count, rng)) {
        const std::uint64_t seed = derive_seed(instance_seeds, instance_id++);
        Random own(seed);
        const glm::vec2 p = points[i];
        const glm::mat4 transform =
            glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(p.x, eco.terrain.height(p.x, p.y), p.y)),
                                   own.uniform(0.0f, glm::two_pi<float>()), glm::vec3(0, 1, 0)),
                       glm::vec3(own.uniform(r.scale.x, r.scale.y)));
        const float lo = 1.0f - r.tint, hi = 1.0f + r.tint;  // 0.88f and 1.12f to the bit at the default: the same plants as before
        const glm::vec3 tint(own.uniform(lo, hi), own.uniform(lo, hi), own.uniform(lo, hi));
        const std::uint32_t variants = r.mesh ? 1u : static_cast<std::uint32_t>(r.variants);
        eco.tables[first_mesh[s] + own.below(variants)].add(transform, tint, seed);
      }
    }
  }
  for (InstanceTable& table : eco.tables) table.shrink_to_fit();
  return eco;
}

}  // namespace pointgen
