// Low-poly bodies from simple parts: people, cows, cars, aeroplanes.
#include "pointgen/mesh_builder.hpp"
#include "pointgen/movers/body.hpp"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <functional>

namespace pointgen {
namespace {

const glm::vec3 white(1.0f);

glm::mat4 placed(const glm::vec3& center, const glm::vec3& size) {
  return glm::scale(glm::translate(glm::mat4(1.0f), center), size);
}

// The radius of a sphere around the origin that holds every pose: a moving part turns about its
// pivot, so its vertices stay within |pivot| + |vertex - pivot| of the origin.
float pose_radius(const Body& body) {
  float radius = 0.0f;
  for (const BodyPart& p : body.parts) {
    for (const glm::vec3& v : p.mesh.positions) {
      radius = std::max(radius, p.motion == PartMotion::fixed ? glm::length(v) : glm::length(p.pivot) + glm::distance(v, p.pivot));
    }
  }
  return radius;
}

Body finished(Body body) {
  body.radius = pose_radius(body);
  return body;
}

BodyPart part(const std::function<void(MeshBuilder&)>& build, int color_slot, PartMotion motion = PartMotion::fixed,
              const glm::vec3& pivot = glm::vec3(0.0f), float amplitude = 0.0f, float phase = 0.0f,
              const glm::vec3& axis = glm::vec3(1, 0, 0)) {
  MeshBuilder b;
  build(b);
  return {b.build(), pivot, axis, motion, amplitude, phase, color_slot};
}

}  // namespace

Body make_person() {
  Body body{"person", {}, 1.4f, 0.0f, true};
  for (float side : {-1.0f, 1.0f}) {
    const glm::vec3 hip(0.1f * side, 0.92f, 0.0f);
    body.parts.push_back(part([&](MeshBuilder& b) { b.tube(hip, {0.1f * side, 0.04f, 0.0f}, 0.075f, 0.06f, 6, white, true); },
                              1, PartMotion::swing, hip, 0.5f, side > 0 ? 0.0f : glm::pi<float>()));
    const glm::vec3 shoulder(0.25f * side, 1.43f, 0.0f);
    body.parts.push_back(part([&](MeshBuilder& b) { b.tube(shoulder, {0.27f * side, 0.86f, 0.0f}, 0.05f, 0.045f, 5, white, true); },
                              0, PartMotion::swing, shoulder, 0.4f, side > 0 ? glm::pi<float>() : 0.0f));
  }
  body.parts.push_back(part([](MeshBuilder& b) { b.box(placed({0.0f, 1.18f, 0.0f}, {0.4f, 0.56f, 0.22f}), white); }, 0));
  body.parts.push_back(part([](MeshBuilder& b) {
    b.ellipsoid(placed({0.0f, 1.6f, 0.0f}, {0.1f, 0.12f, 0.11f}), white, 8, 5);
  }, 2));
  return finished(std::move(body));
}

Body make_cow() {
  Body body{"cow", {}, 1.6f, 0.0f, true};
  body.parts.push_back(part([](MeshBuilder& b) {
    b.ellipsoid(placed({0.0f, 1.0f, 0.0f}, {0.36f, 0.4f, 0.9f}), white, 10, 6);
    b.ellipsoid(placed({0.0f, 1.12f, 1.05f}, {0.17f, 0.2f, 0.32f}), white, 8, 5);
    b.tube({-0.1f, 1.3f, 1.0f}, {-0.22f, 1.42f, 1.0f}, 0.03f, 0.01f, 4, white);
    b.tube({0.1f, 1.3f, 1.0f}, {0.22f, 1.42f, 1.0f}, 0.03f, 0.01f, 4, white);
  }, 0));
  for (float x : {-0.22f, 0.22f}) {
    for (float z : {-0.6f, 0.6f}) {
      const glm::vec3 top(x, 0.8f, z);
      const bool diagonal = (x > 0) == (z > 0);
      body.parts.push_back(part([&](MeshBuilder& b) { b.tube(top, {x, 0.02f, z}, 0.08f, 0.06f, 6, white, true); },
                                1, PartMotion::swing, top, 0.35f, diagonal ? 0.0f : glm::pi<float>()));
    }
  }
  const glm::vec3 root(0.0f, 1.25f, -0.88f);
  body.parts.push_back(part([&](MeshBuilder& b) { b.tube(root, {0.0f, 0.55f, -1.0f}, 0.025f, 0.02f, 4, white); },
                            1, PartMotion::swing, root, 0.3f, 0.5f, glm::vec3(0, 0, 1)));
  return finished(std::move(body));
}

Body make_car() {
  Body body{"car", {}, 1.0f, 0.0f};
  body.parts.push_back(part([](MeshBuilder& b) { b.box(placed({0.0f, 0.6f, 0.0f}, {1.8f, 0.6f, 4.2f}), white); }, 0));
  body.parts.push_back(part([](MeshBuilder& b) { b.box(placed({0.0f, 1.12f, -0.2f}, {1.6f, 0.46f, 2.2f}), white); }, 1));
  const float radius = 0.34f;
  for (float x : {-0.95f, 0.95f}) {
    for (float z : {-1.35f, 1.35f}) {
      const glm::vec3 hub(x, radius, z);
      body.parts.push_back(part([&](MeshBuilder& b) {
        b.tube(hub - glm::vec3(0.12f, 0, 0), hub + glm::vec3(0.12f, 0, 0), radius, radius, 10, white, true);
      }, 2, PartMotion::spin, hub, 1.0f / radius));
    }
  }
  return finished(std::move(body));
}

Body make_aeroplane() {
  Body body{"aeroplane", {}, 1.0f, 0.0f};
  body.parts.push_back(part([](MeshBuilder& b) {
    b.ellipsoid(placed({0.0f, 0.0f, 0.0f}, {1.7f, 1.8f, 15.0f}), white, 12, 8);
    b.box(placed({0.0f, -0.4f, 1.0f}, {30.0f, 0.35f, 4.5f}), white);
    b.box(placed({0.0f, 2.4f, -12.5f}, {0.35f, 4.0f, 3.5f}), white);
    b.box(placed({0.0f, 0.6f, -13.0f}, {10.0f, 0.3f, 2.6f}), white);
  }, 0));
  body.parts.push_back(part([](MeshBuilder& b) {
    for (float x : {-6.0f, 6.0f}) b.tube({x, -1.3f, 3.5f}, {x, -1.3f, -0.5f}, 0.8f, 0.65f, 10, white, true);
  }, 1));
  return finished(std::move(body));
}

}  // namespace pointgen
