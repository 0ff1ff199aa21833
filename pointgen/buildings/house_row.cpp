#include "pointgen/buildings/buildings.hpp"
#include "pointgen/mesh_builder.hpp"
#include "pointgen/random.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace pointgen {

TriangleMesh build_house_row(const glm::vec2& from, const glm::vec2& to, int front, float depth, std::uint64_t seed) {
  const glm::vec3 walls[] = {{0.75f, 0.62f, 0.45f}, {0.60f, 0.30f, 0.20f}, {0.85f, 0.82f, 0.75f}, {0.45f, 0.50f, 0.55f},
                             {0.80f, 0.70f, 0.40f}};
  const glm::vec3 roofs[] = {{0.35f, 0.10f, 0.06f}, {0.20f, 0.20f, 0.22f}, {0.30f, 0.22f, 0.15f}};
  const glm::vec3 glass(0.08f, 0.10f, 0.14f);
  MeshBuilder b;
  Random rng(seed);
  const glm::vec2 along = glm::normalize(to - from);
  const glm::vec2 out = static_cast<float>(front) * glm::vec2(-along.y, along.x);  // towards the street
  const float angle = std::atan2(along.x, along.y);
  const float total = glm::distance(from, to);
  for (float s = 0.0f; s < total - 4.0f;) {
    const float width = std::min(rng.uniform(8.0f, 16.0f), total - s);
    const float height = rng.uniform(9.0f, 26.0f);
    const glm::vec2 c = from + (s + 0.5f * width) * along - 0.5f * depth * out;
    // The house in its own frame: x along the street, z towards it, then turned and placed.
    const glm::mat4 frame = glm::rotate(glm::translate(glm::mat4(1.0f), {c.x, 0.0f, c.y}), angle - glm::radians(90.0f), {0, 1, 0});
    const float facing = glm::dot(glm::vec2(frame[2][0], frame[2][2]), out) > 0.0f ? 1.0f : -1.0f;
    const glm::vec3 wall = walls[rng.below(5)] * rng.uniform(0.9f, 1.1f);
    b.box(frame * glm::scale(glm::translate(glm::mat4(1.0f), {0.0f, 0.5f * height, 0.0f}), {width - 0.3f, height, depth}), wall);
    if (rng.uniform() < 0.6f) {  // pitched roof, ridge along the street
      const float r = rng.uniform(3.0f, 6.0f);
      const glm::vec3 roof = roofs[rng.below(3)];
      const glm::vec3 p[6] = {{-0.5f * width, height, -0.5f * depth}, {0.5f * width, height, -0.5f * depth},
                              {0.5f * width, height, 0.5f * depth},   {-0.5f * width, height, 0.5f * depth},
                              {-0.5f * width, height + r, 0.0f},      {0.5f * width, height + r, 0.0f}};
      auto at = [&](int i) { return glm::vec3(frame * glm::vec4(p[i], 1.0f)); };
      b.polygon({at(3), at(2), at(5), at(4)}, roof);
      b.polygon({at(1), at(0), at(4), at(5)}, roof);
      b.polygon({at(0), at(3), at(4)}, wall);
      b.polygon({at(2), at(1), at(5)}, wall);
    }
    // Rows of windows on the street front.
    for (float y = 3.0f; y + 2.0f < height; y += 3.2f) {
      for (float x = -0.5f * width + 1.5f; x + 1.5f < 0.5f * width; x += 2.6f) {
        b.box(frame * glm::scale(glm::translate(glm::mat4(1.0f), {x + 0.6f, y + 0.8f, facing * 0.5f * depth}), {1.2f, 1.6f, 0.12f}),
              glass);
      }
    }
    s += width;
  }
  return b.build();
}

}  // namespace pointgen
