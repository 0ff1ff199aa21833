#include "pointgen/movers/moving_set.hpp"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace pointgen {
namespace {

glm::vec3 pick(Random& rng, std::initializer_list<glm::vec3> palette) {
  return *(palette.begin() + rng.below(static_cast<std::uint32_t>(palette.size())));
}

glm::vec3 shade(Random& rng, const glm::vec3& c) { return c * rng.uniform(0.85f, 1.15f); }

// Linear RGB palettes.
const std::initializer_list<glm::vec3> shirts = {{0.60f, 0.05f, 0.05f}, {0.05f, 0.15f, 0.50f}, {0.70f, 0.70f, 0.68f},
                                                 {0.10f, 0.35f, 0.10f}, {0.75f, 0.50f, 0.05f}, {0.30f, 0.08f, 0.40f},
                                                 {0.05f, 0.05f, 0.05f}, {0.80f, 0.35f, 0.45f}};
const std::initializer_list<glm::vec3> trousers = {{0.05f, 0.07f, 0.18f}, {0.20f, 0.15f, 0.10f}, {0.04f, 0.04f, 0.04f},
                                                   {0.35f, 0.33f, 0.30f}};
const std::initializer_list<glm::vec3> skins = {{0.80f, 0.55f, 0.40f}, {0.55f, 0.33f, 0.20f}, {0.30f, 0.16f, 0.09f},
                                                {0.90f, 0.68f, 0.52f}};
const std::initializer_list<glm::vec3> coats = {{0.85f, 0.82f, 0.78f}, {0.30f, 0.15f, 0.06f}, {0.05f, 0.04f, 0.04f},
                                                {0.55f, 0.30f, 0.12f}};
const std::initializer_list<glm::vec3> paints = {{0.65f, 0.02f, 0.02f}, {0.02f, 0.10f, 0.45f}, {0.80f, 0.80f, 0.80f},
                                                 {0.03f, 0.03f, 0.03f}, {0.75f, 0.55f, 0.02f}, {0.05f, 0.30f, 0.10f},
                                                 {0.40f, 0.42f, 0.45f}};

// `travelled` is the distance since t = 0, not wrapped round the loop, so walk cycles and wheels
// turn on smoothly where the loop closes.
glm::mat4 part_motion(const BodyPart& part, double travelled, float stride) {
  float angle = 0.0f;
  if (part.motion == PartMotion::swing) {
    const auto cycle = static_cast<float>(std::fmod(travelled, static_cast<double>(stride)) / stride);
    angle = part.amplitude * std::sin(glm::two_pi<float>() * cycle + part.phase);
  } else if (part.motion == PartMotion::spin) {
    const double turn = glm::two_pi<double>() / static_cast<double>(part.amplitude);  // metres per revolution
    angle = static_cast<float>(static_cast<double>(part.amplitude) * std::fmod(travelled, turn));
  } else {
    return glm::mat4(1.0f);
  }
  return glm::translate(glm::rotate(glm::translate(glm::mat4(1.0f), part.pivot), angle, part.axis), -part.pivot);
}

}  // namespace

std::vector<TriangleMesh> MovingSet::part_meshes() const {
  std::vector<TriangleMesh> meshes;
  for (const Body& body : bodies) {
    for (const BodyPart& part : body.parts) meshes.push_back(part.mesh);
  }
  return meshes;
}

std::vector<InstanceTable> MovingSet::pose(double t, std::size_t first_mesh) const {
  std::vector<std::size_t> first_table;
  std::vector<InstanceTable> tables;
  for (const Body& body : bodies) {
    first_table.push_back(tables.size());
    for (std::size_t p = 0; p < body.parts.size(); ++p) tables.push_back({first_mesh + tables.size(), {}, {}, {}});
  }
  for (const Mover& m : movers) {
    const Body& body = bodies[m.body];
    const LoopPath& path = paths[m.path];
    // Distance is taken in double, then wrapped, so long captures keep their precision.
    const double travelled = static_cast<double>(m.speed) * t;
    const auto distance = static_cast<float>(std::fmod(m.offset + travelled, path.length()));
    glm::vec3 position = path.position(distance);
    if (ground) position.y += ground->height(position.x, position.z);
    const glm::vec3 heading = path.heading(distance, 1.5f * body.radius);
    const float yaw = std::atan2(heading.x, heading.z);
    const glm::mat4 placed = glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), position), yaw, glm::vec3(0, 1, 0)),
                                        glm::vec3(m.scale));
    for (std::size_t p = 0; p < body.parts.size(); ++p) {
      const BodyPart& part = body.parts[p];
      tables[first_table[m.body] + p].add(placed * part_motion(part, travelled, body.stride),
                                          m.colors[static_cast<std::size_t>(part.color_slot)], derive_seed(m.seed, p));
    }
  }
  return tables;
}

Bounds MovingSet::bounds() const {
  Bounds b;
  for (const Mover& m : movers) {
    const float r = bodies[m.body].radius * m.scale;
    for (const glm::vec3& p : paths[m.path].points()) {
      glm::vec3 q = p;
      if (ground) q.y += ground->height(p.x, p.z);
      b.add(q - glm::vec3(r));
      b.add(q + glm::vec3(r));
    }
  }
  if (ground && !b.empty()) {  // between waypoints movers follow the ground, within ±relief/2 of its centre
    const float half = 0.5f * ground->spec().relief;
    b.add(glm::vec3(b.min.x, b.min.y - half, b.min.z));
    b.add(glm::vec3(b.max.x, b.max.y + half, b.max.z));
  }
  return b;
}

MovingSet make_crowd(int count, const Rect& region, const std::vector<Rect>& obstacles, float y, std::uint64_t seed) {
  MovingSet set;
  set.bodies.push_back(make_person());
  for (int i = 0; i < count; ++i) {
    const std::uint64_t own_seed = derive_seed(seed, static_cast<std::uint64_t>(i));
    Random rng(own_seed);
    set.paths.push_back(wander_loop(rng, region, obstacles, 6, y));
    Mover m;
    m.path = set.paths.size() - 1;
    m.speed = rng.uniform(0.8f, 1.6f);
    m.offset = rng.uniform(0.0f, set.paths.back().length());
    m.scale = rng.uniform(0.9f, 1.1f);
    m.colors = {shade(rng, pick(rng, shirts)), shade(rng, pick(rng, trousers)), pick(rng, skins)};
    m.seed = own_seed;
    set.movers.push_back(m);
  }
  return set;
}

MovingSet make_herd(int count, const Terrain& ground, const Rect& pasture, float y, std::uint64_t seed) {
  MovingSet set;
  set.bodies.push_back(make_cow());
  set.ground = ground;
  for (int i = 0; i < count; ++i) {
    const std::uint64_t own_seed = derive_seed(seed, static_cast<std::uint64_t>(i));
    Random rng(own_seed);
    set.paths.push_back(wander_loop(rng, pasture, {}, 5, y));
    Mover m;
    m.path = set.paths.size() - 1;
    m.speed = rng.uniform(0.3f, 0.7f);
    m.offset = rng.uniform(0.0f, set.paths.back().length());
    m.colors = {pick(rng, coats), pick(rng, coats) * 0.7f, glm::vec3(1.0f)};
    m.seed = own_seed;
    set.movers.push_back(m);
  }
  return set;
}

MovingSet make_traffic(int cars, const std::vector<Rect>& loops, float y, int aeroplanes, const glm::vec3& center,
                       float radius, float altitude, std::uint64_t seed) {
  MovingSet set;
  set.bodies.push_back(make_car());
  set.bodies.push_back(make_aeroplane());
  for (const Rect& r : loops) {
    set.paths.emplace_back(std::vector<glm::vec3>{{r.min.x, y, r.min.y}, {r.max.x, y, r.min.y}, {r.max.x, y, r.max.y},
                                                  {r.min.x, y, r.max.y}});
  }
  for (int i = 0; i < cars && !loops.empty(); ++i) {
    const std::uint64_t own_seed = derive_seed(seed, static_cast<std::uint64_t>(i));
    Random rng(own_seed);
    Mover m;
    m.path = static_cast<std::size_t>(i) % loops.size();
    m.speed = rng.uniform(6.0f, 12.0f);
    m.offset = rng.uniform(0.0f, set.paths[m.path].length());
    m.colors = {pick(rng, paints), glm::vec3(0.05f, 0.06f, 0.08f), glm::vec3(0.02f)};
    m.seed = own_seed;
    set.movers.push_back(m);
  }
  for (int i = 0; i < aeroplanes; ++i) {
    const std::uint64_t own_seed = derive_seed(seed, 1000000 + static_cast<std::uint64_t>(i));
    Random rng(own_seed);
    set.paths.push_back(circle_loop(center + glm::vec3(0.0f, altitude + 40.0f * static_cast<float>(i), 0.0f),
                                    radius * rng.uniform(0.8f, 1.2f)));
    Mover m;
    m.body = 1;
    m.path = set.paths.size() - 1;
    m.speed = rng.uniform(50.0f, 70.0f);
    m.offset = rng.uniform(0.0f, set.paths.back().length());
    m.colors = {glm::vec3(0.85f), glm::vec3(0.3f), glm::vec3(1.0f)};
    m.seed = own_seed;
    set.movers.push_back(m);
  }
  return set;
}

}  // namespace pointgen
