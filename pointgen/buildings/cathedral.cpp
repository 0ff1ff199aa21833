#include "pointgen/buildings/buildings.hpp"
#include "pointgen/mesh_builder.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace pointgen {
namespace {

glm::mat4 placed(const glm::vec3& center, const glm::vec3& size) {
  return glm::scale(glm::translate(glm::mat4(1.0f), center), size);
}

// A roof with two slopes over the box [x0, x1] x [z0, z1] at eave height y, ridge h above.
void pitched_roof(MeshBuilder& b, float x0, float x1, float z0, float z1, float y, float h, const glm::vec3& color,
                  const glm::vec3& gable) {
  const float xm = 0.5f * (x0 + x1);
  b.polygon({{x1, y, z1}, {x1, y, z0}, {xm, y + h, z0}, {xm, y + h, z1}}, color);
  b.polygon({{x0, y, z0}, {x0, y, z1}, {xm, y + h, z1}, {xm, y + h, z0}}, color);
  b.polygon({{x0, y, z1}, {x1, y, z1}, {xm, y + h, z1}}, gable);
  b.polygon({{x1, y, z0}, {x0, y, z0}, {xm, y + h, z0}}, gable);
}

// A four-sided spire on the square of side s centred at (x, z), from height y up by h.
void spire(MeshBuilder& b, float x, float z, float s, float y, float h, const glm::vec3& color) {
  const glm::vec3 apex(x, y + h, z);
  const float r = 0.5f * s;
  const glm::vec3 c[4] = {{x - r, y, z + r}, {x + r, y, z + r}, {x + r, y, z - r}, {x - r, y, z - r}};
  for (int i = 0; i < 4; ++i) b.polygon({c[i], c[(i + 1) % 4], apex}, color);
}

}  // namespace

TriangleMesh build_cathedral(const CathedralSpec& spec) {
  MeshBuilder b;
  const float w = spec.width, l = spec.length, h = spec.height;
  const float front = 0.5f * l, back = -0.5f * l;
  // Nave and aisles.
  b.box(placed({0.0f, 0.5f * h, 0.0f}, {0.6f * w, h, l}), spec.stone);
  b.box(placed({0.0f, 0.3f * h, 0.0f}, {w, 0.6f * h, 0.9f * l}), spec.stone);
  pitched_roof(b, -0.3f * w, 0.3f * w, back, front, h, 0.35f * w, spec.roof, spec.stone);
  // West towers with spires.
  const float tower = 0.32f * w;
  for (float side : {-1.0f, 1.0f}) {
    const float x = side * (0.5f * w - 0.5f * tower);
    b.box(placed({x, 0.75f * h, front - 0.5f * tower}, {tower, 1.5f * h, tower}), spec.stone);
    spire(b, x, front - 0.5f * tower, tower, 1.5f * h, 0.9f * h, spec.roof);
  }
  // Buttresses along both sides, leaning against the aisles.
  const int bays = 7;
  for (int i = 0; i < bays; ++i) {
    const float z = back + 0.1f * l + 0.65f * l * (static_cast<float>(i) + 0.5f) / static_cast<float>(bays);
    for (float side : {-1.0f, 1.0f}) {
      b.box(placed({side * (0.5f * w + 1.0f), 0.35f * h, z}, {2.0f, 0.7f * h, 1.2f}), spec.stone);
      b.box(placed({side * (0.5f * w + 0.4f), 0.7f * h, z}, {0.8f, 0.25f * h, 1.0f}), spec.stone);
    }
  }
  // Portal: a deep, dark doorway with a gable above.
  const float door = 0.22f * w;
  b.box(placed({0.0f, 0.22f * h, front + 0.8f}, {door + 2.0f, 0.44f * h, 1.6f}), spec.stone * 0.9f);
  b.box(placed({0.0f, 0.17f * h, front + 1.62f}, {door, 0.34f * h, 0.04f}), glm::vec3(0.05f, 0.04f, 0.03f));
  pitched_roof(b, -0.5f * door - 1.0f, 0.5f * door + 1.0f, front, front + 1.6f, 0.44f * h, 0.15f * h, spec.stone, spec.stone);
  // Rose window.
  b.lathe({{0.0f, 0.0f}, {0.11f * w, 0.0f}}, 16, glm::vec3(0.15f, 0.2f, 0.45f),
          glm::rotate(glm::translate(glm::mat4(1.0f), {0.0f, 0.72f * h, front + 0.01f}), glm::radians(90.0f), {1, 0, 0}));
  // Apse: a half-round end with a conical roof.
  std::vector<glm::vec2> apse = {{0.3f * w, 0.0f}, {0.3f * w, h}, {0.0f, h + 0.3f * w}};
  b.lathe(apse, 16, spec.stone, glm::translate(glm::mat4(1.0f), {0.0f, 0.0f, back}));
  return b.build();
}

}  // namespace pointgen
