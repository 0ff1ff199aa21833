// Plant meshes from species parameters: recursive branching for trees and bushes, whorls for
// conifers, arched strips for palms and grasses, petals for flowers, arms for cacti.
#include "pointgen/mesh_builder.hpp"
#include "pointgen/plants/plant_species.hpp"
#include "pointgen/random.hpp"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace pointgen {
namespace {

const glm::vec3 up(0.0f, 1.0f, 0.0f);
constexpr float golden_angle = 2.39996323f;

glm::vec3 rotate(const glm::vec3& v, const glm::vec3& axis, float angle) {
  return glm::angleAxis(angle, glm::normalize(axis)) * v;
}

glm::vec3 perpendicular(const glm::vec3& v) {
  return glm::normalize(std::abs(v.y) < 0.9f ? glm::cross(v, up) : glm::cross(v, glm::vec3(1, 0, 0)));
}

glm::vec3 random_direction(Random& rng) {
  for (;;) {
    const glm::vec3 p(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    const float l = glm::length(p);
    if (l > 0.1f && l <= 1.0f) return p / l;
  }
}

class PlantBuilder {
 public:
  PlantBuilder(const PlantSpecies& s, std::uint64_t seed) : s_(s), rng_(seed) {}

  TriangleMesh build() {
    switch (s_.kind) {
      case PlantKind::broadleaf: broadleaf(); break;
      case PlantKind::conifer: conifer(); break;
      case PlantKind::palm: palm(); break;
      case PlantKind::bush: bush(); break;
      case PlantKind::grass: grass(); break;
      case PlantKind::flower: flower(); break;
      case PlantKind::cactus: cactus(); break;
    }
    return mesh_.build();
  }

 private:
  glm::vec3 leaf_color() { return rng_.uniform() < s_.bloom_share ? s_.bloom : s_.leaf * rng_.uniform(0.85f, 1.15f); }

  // A leaf hanging from `at`, pointing roughly along `out`.
  void add_leaf(const glm::vec3& at, const glm::vec3& out) {
    glm::vec3 dir = out + 0.6f * random_direction(rng_) - s_.droop * up;
    dir = glm::length(dir) < 1e-3f ? up : glm::normalize(dir);
    const float size = s_.leaf_size * rng_.uniform(0.8f, 1.2f);
    if (at.y + size * dir.y < 0.0f) dir.y = std::abs(dir.y);  // no leaf reaches into the ground
    mesh_.leaf(at, dir, perpendicular(dir), size, 0.55f * size, leaf_color());
  }

  // A branch of `length` from `base` along `dir`: two tube segments bending a little, then
  // children along its outer part, or leaves when it is a twig.
  void branch(const glm::vec3& base, const glm::vec3& dir, float length, float radius, int level) {
    const int sides = std::max(3, 7 - 2 * level);
    glm::vec3 bent = glm::normalize(dir + 0.15f * random_direction(rng_) +
                                    (0.12f - 0.25f * s_.droop * static_cast<float>(level)) * up);
    const glm::vec3 mid = base + 0.5f * length * dir;
    if (mid.y + 0.5f * length * bent.y < 0.1f * s_.height) bent.y = std::abs(bent.y);  // hanging, not digging
    const glm::vec3 tip = mid + 0.5f * length * bent;
    mesh_.tube(base, mid, radius, 0.8f * radius, sides, s_.bark);
    mesh_.tube(mid, tip, 0.8f * radius, 0.55f * radius, sides, s_.bark);
    if (level >= s_.levels) {
      for (int i = 0; i < s_.leaves; ++i) {
        add_leaf(mid + rng_.uniform(0.3f, 1.0f) * (tip - mid), bent);
      }
      return;
    }
    const float ratio = 0.52f + 0.25f * std::min(s_.crown, 1.0f);
    const float spin = rng_.uniform(0.0f, glm::two_pi<float>());
    for (int i = 0; i < s_.branches; ++i) {
      const float t = 0.45f + 0.55f * static_cast<float>(i + 1) / static_cast<float>(s_.branches);
      const glm::vec3 at = t < 0.5f ? base + 2.0f * t * (mid - base) : mid + (2.0f * t - 1.0f) * (tip - mid);
      // The last child leads on almost straight; the others spread out around the branch.
      const bool leader = i == s_.branches - 1;
      const float tilt = glm::radians(leader ? 0.3f * s_.angle_deg : s_.angle_deg * rng_.uniform(0.8f, 1.2f));
      glm::vec3 child = rotate(bent, perpendicular(bent), tilt);
      child = rotate(child, bent, spin + golden_angle * static_cast<float>(i));
      branch(at, child, length * ratio * rng_.uniform(0.85f, 1.1f), radius * 0.55f, level + 1);
    }
  }

  void broadleaf() {
    const float trunk_length = 0.45f * s_.height;
    branch(glm::vec3(0.0f), up, trunk_length, s_.trunk * s_.height, 0);
  }

  void bush() {
    for (int i = 0; i < s_.branches; ++i) {
      const float a = golden_angle * static_cast<float>(i) + rng_.uniform(0.0f, 0.5f);
      const glm::vec3 out(std::cos(a), 0.0f, std::sin(a));
      const glm::vec3 dir = glm::normalize(up + std::tan(glm::radians(s_.angle_deg)) * out * rng_.uniform(0.5f, 1.0f));
      branch(0.05f * s_.height * out, dir, 0.6f * s_.height, s_.trunk * s_.height, 1);
    }
  }

  void conifer() {
    const float h = s_.height;
    mesh_.tube(glm::vec3(0.0f), glm::vec3(0, 0.6f * h, 0), s_.trunk * h, 0.6f * s_.trunk * h, 6, s_.bark);
    mesh_.tube(glm::vec3(0, 0.6f * h, 0), glm::vec3(0, h, 0), 0.6f * s_.trunk * h, 0.1f * s_.trunk * h, 5, s_.bark);
    const int tiers = std::max(2, s_.levels);
    for (int tier = 0; tier < tiers; ++tier) {
      const float f = static_cast<float>(tier) / static_cast<float>(tiers);
      const float y = h * (0.2f + 0.75f * f);
      const float reach = 0.5f * s_.crown * h * std::pow(1.0f - f, 0.9f) + 0.05f * h;
      const float spin = rng_.uniform(0.0f, glm::two_pi<float>());
      for (int arm = 0; arm < s_.branches; ++arm) {
        const float a = spin + glm::two_pi<float>() * static_cast<float>(arm) / static_cast<float>(s_.branches);
        const glm::vec3 out(std::cos(a), 0.0f, std::sin(a));
        const glm::vec3 base(0.0f, y, 0.0f);
        const glm::vec3 tip = base + reach * out - (0.15f + 0.6f * s_.droop) * reach * up;
        mesh_.tube(base, tip, 0.01f * h, 0.003f * h, 3, s_.bark);
        // The needles: a drooping frond along the arm, wider near the trunk.
        const glm::vec3 side = glm::cross(up, out);
        const glm::vec3 sag = -0.12f * reach * up;
        mesh_.strip({base, 0.5f * (base + tip) + sag, tip}, {0.5f * reach, 0.35f * reach, 0.05f * reach}, side,
                    s_.leaf * rng_.uniform(0.85f, 1.1f));
      }
    }
  }

  void palm() {
    const float h = s_.height;
    const glm::vec3 lean = 0.15f * h * glm::vec3(rng_.uniform(-1, 1), 0.0f, rng_.uniform(-1, 1));
    glm::vec3 previous(0.0f);
    const int segments = 6;
    for (int i = 1; i <= segments; ++i) {
      const float t = static_cast<float>(i) / static_cast<float>(segments);
      const glm::vec3 p = t * h * up + t * t * lean;
      mesh_.tube(previous, p, s_.trunk * h * (1.1f - 0.4f * t), s_.trunk * h * (1.1f - 0.4f * (t + 0.1f)), 6, s_.bark);
      previous = p;
    }
    for (int f = 0; f < s_.branches; ++f) {
      const float a = golden_angle * static_cast<float>(f);
      const glm::vec3 out(std::cos(a), 0.0f, std::sin(a));
      const float reach = 0.5f * s_.crown * h * rng_.uniform(0.8f, 1.1f);
      std::vector<glm::vec3> spine;
      std::vector<float> widths;
      for (int k = 0; k <= 5; ++k) {
        const float t = static_cast<float>(k) / 5.0f;
        spine.push_back(previous + reach * t * out + reach * (0.5f * t - (0.6f + s_.droop) * t * t) * up);
        widths.push_back(s_.leaf_size * (1.0f - 0.8f * t) * (0.3f + t));
      }
      mesh_.strip(spine, widths, glm::cross(up, out), leaf_color());
    }
  }

  void grass() {
    const float h = s_.height;
    const int segments = std::max(2, s_.levels);
    for (int b = 0; b < s_.branches; ++b) {
      const glm::vec2 d = rng_.in_disc() * (0.25f * s_.crown * h);
      const glm::vec3 base(d.x, 0.0f, d.y);
      const float a = rng_.uniform(0.0f, glm::two_pi<float>());
      const glm::vec3 out(std::cos(a), 0.0f, std::sin(a));
      const float bend = std::tan(glm::radians(s_.angle_deg)) * rng_.uniform(0.3f, 1.0f);
      const float length = h * rng_.uniform(0.6f, 1.0f);
      std::vector<glm::vec3> spine;
      std::vector<float> widths;
      for (int k = 0; k <= segments; ++k) {
        const float t = static_cast<float>(k) / static_cast<float>(segments);
        spine.push_back(base + length * (t * up + bend * t * t * out));
        widths.push_back(s_.leaf_size * (1.0f - 0.9f * t));
      }
      mesh_.strip(spine, widths, glm::cross(up, out), leaf_color());
    }
  }

  void flower() {
    const int stems = std::max(1, s_.leaves);
    for (int i = 0; i < stems; ++i) {
      const glm::vec2 d = i == 0 ? glm::vec2(0.0f) : rng_.in_disc() * (0.3f * s_.crown * s_.height);
      const glm::vec3 base(d.x, 0.0f, d.y);
      const float h = s_.height * rng_.uniform(0.75f, 1.0f);
      const glm::vec3 top = base + h * up + 0.1f * h * glm::vec3(rng_.uniform(-1, 1), 0.0f, rng_.uniform(-1, 1));
      mesh_.tube(base, top, 0.012f * s_.height + 0.002f, 0.008f * s_.height + 0.0015f, 4, s_.leaf);
      for (int k = 0; k < 2; ++k) {
        add_leaf(base + (0.2f + 0.25f * static_cast<float>(k)) * (top - base),
                 glm::vec3(rng_.uniform(-1, 1), 0.5f, rng_.uniform(-1, 1)));
      }
      const glm::vec3 face = glm::normalize(up + 0.3f * random_direction(rng_));
      const glm::vec3 u = perpendicular(face);
      const float tilt = glm::radians(s_.angle_deg);
      for (int p = 0; p < s_.branches; ++p) {
        const glm::vec3 out = rotate(u, face, glm::two_pi<float>() * static_cast<float>(p) / static_cast<float>(s_.branches));
        const glm::vec3 petal = std::cos(tilt) * out + std::sin(tilt) * face;
        mesh_.leaf(top, petal, glm::cross(face, out), s_.leaf_size, 0.6f * s_.leaf_size, s_.bloom);
      }
      const float r = 0.25f * s_.leaf_size;
      mesh_.ellipsoid(glm::translate(glm::mat4(1.0f), top) * glm::scale(glm::mat4(1.0f), glm::vec3(r, 0.5f * r, r)),
                      s_.bark, 6, 3);
    }
  }

  void cactus() {
    const float h = s_.height;
    const float r = s_.trunk * h;
    mesh_.tube(glm::vec3(0.0f), glm::vec3(0, h - r, 0), r, r, 8, s_.leaf);
    mesh_.ellipsoid(glm::translate(glm::mat4(1.0f), glm::vec3(0, h - r, 0)) * glm::scale(glm::mat4(1.0f), glm::vec3(r)),
                    s_.leaf, 8, 4);
    for (int a = 0; a < s_.branches; ++a) {
      const float angle = golden_angle * static_cast<float>(a) + rng_.uniform(0.0f, 0.6f);
      const glm::vec3 out(std::cos(angle), 0.0f, std::sin(angle));
      const float y = h * rng_.uniform(0.3f, 0.6f);
      const float arm = 0.7f * r;
      const glm::vec3 elbow = glm::vec3(0, y, 0) + (r + 2.0f * arm) * out;
      const glm::vec3 top = elbow + h * rng_.uniform(0.2f, 0.35f) * up;
      mesh_.tube(glm::vec3(0, y, 0), elbow, arm, arm, 6, s_.leaf);
      mesh_.tube(elbow - 0.5f * arm * up, top, arm, arm, 6, s_.leaf);
      mesh_.ellipsoid(glm::translate(glm::mat4(1.0f), top) * glm::scale(glm::mat4(1.0f), glm::vec3(arm)), s_.leaf, 6, 3);
    }
    if (s_.bloom_share > 0.0f) {
      const float f = 0.4f * r;
      mesh_.ellipsoid(glm::translate(glm::mat4(1.0f), glm::vec3(0, h, 0)) * glm::scale(glm::mat4(1.0f), glm::vec3(f)), s_.bloom, 6, 3);
    }
  }

  const PlantSpecies& s_;
  Random rng_;
  MeshBuilder mesh_;
};

}  // namespace

TriangleMesh build_plant(const PlantSpecies& species, std::uint64_t seed) {
  species.check();
  return PlantBuilder(species, seed).build();
}

}  // namespace pointgen
