#include "app/scene/mover_fields.hpp"

#include "pointgen/random.hpp"

namespace ecoview {
namespace {

std::uint64_t object_seed(const JsonField& field, std::uint64_t scene_seed) {
  const int own = field.has("seed") ? field["seed"].integer(0, 2147483647) : 0;
  return pointgen::derive_seed(scene_seed, static_cast<std::uint64_t>(own) + 0x5eed);
}

std::vector<pointgen::Rect> read_rects(const JsonField& field) {
  std::vector<pointgen::Rect> rects;
  for (const JsonField& item : field.items()) rects.push_back(read_rect(item));
  return rects;
}

}  // namespace

pointgen::Rect read_rect(const JsonField& field) {
  const std::vector<double> v = field.numbers(4, -JsonField::max_coordinate, JsonField::max_coordinate);
  if (v[0] >= v[2] || v[1] >= v[3]) field.fail("expected [x0, z0, x1, z1] with x0 < x1 and z0 < z1");
  return {{v[0], v[1]}, {v[2], v[3]}};
}

pointgen::MovingSet read_crowd(const JsonField& field, std::uint64_t scene_seed) {
  field.only_keys({"type", "count", "center", "size", "avoid", "seed"});
  const int count = field["count"].integer(0, 1000000);
  const glm::vec3 center = field["center"].vec3();
  const std::vector<double> size = field["size"].numbers(2, 0.1, 1e5);
  const glm::vec2 half(0.5 * size[0], 0.5 * size[1]);
  const pointgen::Rect region{glm::vec2(center.x, center.z) - half, glm::vec2(center.x, center.z) + half};
  const std::vector<pointgen::Rect> avoid = field.has("avoid") ? read_rects(field["avoid"]) : std::vector<pointgen::Rect>{};
  return pointgen::make_crowd(count, region, avoid, center.y, object_seed(field, scene_seed));
}

pointgen::MovingSet read_traffic(const JsonField& field, std::uint64_t scene_seed) {
  field.only_keys({"type", "seed", "y", "cars", "loops", "aeroplanes", "center", "radius", "altitude"});
  const int cars = field.has("cars") ? field["cars"].integer(0, 100000) : 0;
  const std::vector<pointgen::Rect> loops = field.has("loops") ? read_rects(field["loops"]) : std::vector<pointgen::Rect>{};
  if (cars > 0 && loops.empty()) field["cars"].fail("cars need \"loops\" to drive round");
  const int aeroplanes = field.has("aeroplanes") ? field["aeroplanes"].integer(0, 100) : 0;
  const float y = field.has("y") ? field["y"].number_f(-1e5, 1e5) : 0.0f;
  const glm::vec3 center = field.has("center") ? field["center"].vec3() : glm::vec3(0.0f);
  const float radius = field.has("radius") ? field["radius"].number_f(10, 1e5) : 400.0f;
  const float altitude = field.has("altitude") ? field["altitude"].number_f(0, 1e5) : 150.0f;
  return pointgen::make_traffic(cars, loops, y, aeroplanes, center, radius, altitude, object_seed(field, scene_seed));
}

}  // namespace ecoview
