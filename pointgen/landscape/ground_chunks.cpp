#include "pointgen/landscape/ground_chunks.hpp"

#include "pointgen/landscape/landscape_terrain.hpp"
#include "pointgen/placement/height_grid_mesh.hpp"

#include <algorithm>
#include <cmath>

namespace pointgen {
namespace {

// Appends the ground's vertex at (x, z), its height `height`.
void add_vertex(TriangleMesh& mesh, const LandscapeTerrain& terrain, const LandscapeSpec& spec, glm::vec2 p, float height, float step) {
  const glm::vec3 normal = terrain.normal(p.x, p.y, step);
  mesh.positions.emplace_back(p.x, height, p.y);
  mesh.normals.push_back(normal);
  mesh.colors.push_back(ground_color({}, height, spec.terrain.relief, normal));
}

}  // namespace

GroundChunks::GroundChunks(LandscapeSpec spec, Settings settings) : spec_(std::move(spec)), settings_(settings) {
  const float finest_side = static_cast<float>(settings_.cells) * settings_.step;
  finest_level_ = std::max(0, static_cast<int>(std::ceil(std::log2(side(0) / finest_side))));
}

float GroundChunks::side(int level) const { return std::max(spec_.size.x, spec_.size.y) / static_cast<float>(1 << level); }

std::vector<GroundChunkKey> GroundChunks::chosen(const glm::vec3& eye) const {
  const glm::vec2 half = 0.5f * spec_.size;
  // Height above the highest hill counts as distance: from above, the near ground is far too.
  const float above = std::max(0.0f, eye.y - 0.5f * spec_.terrain.relief);
  std::vector<GroundChunkKey> chunks;
  std::vector<GroundChunkKey> open{{0, 0, 0}};
  while (!open.empty()) {
    const GroundChunkKey key = open.back();
    open.pop_back();
    const float s = side(key.level);
    const glm::vec2 min = -half + s * glm::vec2(key.x, key.z);
    if (min.x >= half.x || min.y >= half.y) continue;  // past the area's shorter side
    const glm::vec2 nearest = glm::clamp(glm::vec2(eye.x, eye.z), min, glm::min(min + s, half));
    const float distance = glm::length(glm::vec3(nearest.x - eye.x, above, nearest.y - eye.z));
    if (key.level < finest_level_ && distance < settings_.split_distance * s) {
      for (int child = 0; child < 4; ++child) open.push_back({key.level + 1, 2 * key.x + (child & 1), 2 * key.z + (child >> 1)});
    } else {
      chunks.push_back(key);
    }
  }
  std::sort(chunks.begin(), chunks.end());
  return chunks;
}

std::array<int, 4> GroundChunks::coarser_neighbours(const GroundChunkKey& key, const std::set<GroundChunkKey>& chosen) const {
  const glm::ivec2 steps[4] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
  std::array<int, 4> coarser{-1, -1, -1, -1};
  for (int side = 0; side < 4; ++side) {
    const glm::ivec2 next = glm::ivec2(key.x, key.z) + steps[side];
    for (int up = 1; up <= key.level && next.x >= 0 && next.y >= 0; ++up) {
      if (chosen.count({key.level - up, next.x >> up, next.y >> up})) {
        coarser[side] = key.level - up;
        break;
      }
    }
  }
  return coarser;
}

TriangleMesh GroundChunks::chunk_mesh(const Placed& chunk) const {
  const LandscapeTerrain terrain(spec_.terrain, spec_.seed);
  const int n = settings_.cells;
  const float s = side(chunk.key.level), step = s / static_cast<float>(n);
  const glm::vec2 half = 0.5f * spec_.size;
  const glm::vec2 min = -half + s * glm::vec2(chunk.key.x, chunk.key.z);
  const auto at = [&](float i, float j) { return glm::clamp(min + step * glm::vec2(i, j), -half, half); };
  // On an edge a larger chunk meets, the height along its edge: between its vertices, whose
  // lattice of side(level) / n starts at the area's corner too.
  const auto on_edge = [&](glm::vec2 p, int level, int axis) {
    const float coarse = side(level) / static_cast<float>(n);
    const float from = (p[axis] + half[axis]) / coarse, lower = std::floor(from);
    glm::vec2 a = p, b = p;
    a[axis] = glm::min(-half[axis] + coarse * lower, half[axis]);
    b[axis] = glm::min(-half[axis] + coarse * (lower + 1.0f), half[axis]);
    return glm::mix(terrain.height(a.x, a.y), terrain.height(b.x, b.y), from - lower);
  };
  TriangleMesh mesh;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const glm::vec2 p = at(static_cast<float>(i), static_cast<float>(j));
      float height = terrain.height(p.x, p.y);
      // West and east edges run along z (axis 1), south and north along x (axis 0).
      if (i == 0 && chunk.coarser[0] >= 0) height = on_edge(p, chunk.coarser[0], 1);
      if (i == n && chunk.coarser[1] >= 0) height = on_edge(p, chunk.coarser[1], 1);
      if (j == 0 && chunk.coarser[2] >= 0) height = on_edge(p, chunk.coarser[2], 0);
      if (j == n && chunk.coarser[3] >= 0) height = on_edge(p, chunk.coarser[3], 0);
      add_vertex(mesh, terrain, spec_, p, height, step);
    }
  }
  const auto row = static_cast<std::uint32_t>(n + 1);
  for (std::uint32_t j = 0; j < row - 1; ++j) {
    for (std::uint32_t i = 0; i < row - 1; ++i) {
      const std::uint32_t a = j * row + i, b = a + 1, c = a + row, d = c + 1;
      mesh.indices.insert(mesh.indices.end(), {a, d, b, a, c, d});
    }
  }
  return mesh;
}

GroundChunks::Chunked GroundChunks::mesh(const std::vector<GroundChunkKey>& chunks) {
  const std::set<GroundChunkKey> chosen(chunks.begin(), chunks.end());
  std::map<Placed, TriangleMesh> kept;
  Chunked chunked;
  TriangleMesh& ground = chunked.mesh;
  for (const GroundChunkKey& key : chunks) {
    const Placed placed{key, coarser_neighbours(key, chosen)};
    const auto found = kept_.find(placed);
    TriangleMesh& chunk = kept[placed] = found != kept_.end() ? std::move(found->second) : chunk_mesh(placed);
    const auto first = static_cast<std::uint32_t>(ground.positions.size());
    ground.positions.insert(ground.positions.end(), chunk.positions.begin(), chunk.positions.end());
    ground.normals.insert(ground.normals.end(), chunk.normals.begin(), chunk.normals.end());
    ground.colors.insert(ground.colors.end(), chunk.colors.begin(), chunk.colors.end());
    PolygonPart& part = chunked.chunks.emplace_back();
    part.first_index = static_cast<std::uint32_t>(ground.indices.size());
    part.index_count = static_cast<std::uint32_t>(chunk.indices.size());
    for (std::uint32_t i : chunk.indices) ground.indices.push_back(first + i);
    const Bounds b = chunk.bounds();
    part.center = 0.5f * (b.min + b.max);
    part.half_size = 0.5f * (b.max - b.min);
  }
  kept_ = std::move(kept);
  return chunked;
}

}  // namespace pointgen
