#include "pointgen/plants/plant_species.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pointgen {
namespace {

// Colours are linear RGB.
const glm::vec3 brown(0.20f, 0.12f, 0.06f), gray_bark(0.30f, 0.28f, 0.25f), white_bark(0.75f, 0.72f, 0.66f),
    red_bark(0.35f, 0.12f, 0.06f);

PlantSpecies tree(const char* name, float height, float crown, float angle, int levels, int branches, float leaf_size,
                  glm::vec3 bark, glm::vec3 leaf, float droop = 0.0f) {
  PlantSpecies s;
  s.name = name;
  s.kind = PlantKind::broadleaf;
  s.height = height;
  s.crown = crown;
  s.angle_deg = angle;
  s.levels = levels;
  s.branches = branches;
  s.leaf_size = leaf_size;
  s.bark = bark;
  s.leaf = leaf;
  s.droop = droop;
  s.leaves = 10;
  return s;
}

PlantSpecies with(PlantSpecies s, PlantKind kind, float trunk, int leaves) {
  s.kind = kind;
  s.trunk = trunk;
  s.leaves = leaves;
  return s;
}

PlantSpecies blooming(PlantSpecies s, glm::vec3 bloom, float share) {
  s.bloom = bloom;
  s.bloom_share = share;
  return s;
}

std::vector<PlantSpecies> make_catalogue() {
  std::vector<PlantSpecies> c;
  // Broadleaf trees.
  c.push_back(with(tree("oak", 14, 0.9f, 55, 3, 4, 1.10f, brown, {0.10f, 0.28f, 0.05f}), PlantKind::broadleaf, 0.04f, 20));
  c.push_back(with(tree("beech", 18, 0.7f, 40, 3, 4, 1.00f, gray_bark, {0.16f, 0.38f, 0.06f}), PlantKind::broadleaf, 0.03f, 20));
  c.push_back(with(tree("birch", 15, 0.45f, 30, 3, 4, 0.60f, white_bark, {0.25f, 0.48f, 0.08f}, 0.3f), PlantKind::broadleaf, 0.02f, 20));
  c.push_back(with(tree("maple", 13, 0.8f, 45, 3, 4, 1.10f, brown, {0.55f, 0.12f, 0.03f}), PlantKind::broadleaf, 0.035f, 20));
  c.push_back(with(tree("willow", 11, 0.9f, 50, 3, 4, 0.90f, gray_bark, {0.28f, 0.42f, 0.10f}, 1.0f), PlantKind::broadleaf, 0.04f, 20));
  c.push_back(with(tree("poplar", 22, 0.25f, 15, 3, 4, 0.80f, gray_bark, {0.14f, 0.36f, 0.08f}), PlantKind::broadleaf, 0.025f, 20));
  c.push_back(blooming(with(tree("cherry", 7, 0.9f, 50, 3, 4, 0.70f, red_bark, {0.20f, 0.40f, 0.08f}), PlantKind::broadleaf, 0.04f, 20),
                       {0.95f, 0.55f, 0.65f}, 0.7f));
  c.push_back(blooming(with(tree("apple", 6, 1.0f, 60, 3, 4, 0.70f, brown, {0.15f, 0.35f, 0.06f}), PlantKind::broadleaf, 0.05f, 20),
                       {0.70f, 0.05f, 0.03f}, 0.12f));
  c.push_back(with(tree("olive", 6, 1.0f, 65, 3, 3, 0.60f, gray_bark, {0.28f, 0.34f, 0.20f}), PlantKind::broadleaf, 0.07f, 20));
  c.push_back(with(tree("acacia", 9, 1.6f, 70, 3, 4, 0.90f, brown, {0.22f, 0.32f, 0.06f}), PlantKind::broadleaf, 0.04f, 8));
  c.push_back(with(tree("linden", 20, 0.8f, 42, 3, 5, 1.10f, brown, {0.12f, 0.33f, 0.05f}), PlantKind::broadleaf, 0.03f, 9));
  // Conifers: levels are whorl tiers, branches the arms per tier.
  c.push_back(with(tree("spruce", 20, 0.40f, 0, 12, 7, 0, brown, {0.03f, 0.14f, 0.05f}, 0.4f), PlantKind::conifer, 0.02f, 0));
  c.push_back(with(tree("pine", 18, 0.45f, 0, 6, 5, 0, red_bark, {0.08f, 0.20f, 0.06f}, 0.0f), PlantKind::conifer, 0.025f, 0));
  c.push_back(with(tree("fir", 16, 0.45f, 0, 10, 8, 0, gray_bark, {0.04f, 0.18f, 0.10f}, 0.15f), PlantKind::conifer, 0.02f, 0));
  c.push_back(with(tree("cypress", 14, 0.18f, 0, 14, 6, 0, brown, {0.06f, 0.17f, 0.07f}, 0.0f), PlantKind::conifer, 0.02f, 0));
  c.push_back(with(tree("larch", 17, 0.35f, 0, 9, 6, 0, brown, {0.35f, 0.42f, 0.10f}, 0.6f), PlantKind::conifer, 0.02f, 0));
  // Palms: branches are fronds.
  c.push_back(with(tree("date palm", 12, 0.7f, 0, 0, 14, 1.2f, brown, {0.18f, 0.30f, 0.08f}, 0.3f), PlantKind::palm, 0.025f, 0));
  c.push_back(with(tree("fan palm", 6, 0.6f, 0, 0, 18, 1.4f, gray_bark, {0.12f, 0.28f, 0.10f}, 0.0f), PlantKind::palm, 0.04f, 0));
  // Bushes: branches are stems from the ground.
  c.push_back(with(tree("hazel", 4, 0.7f, 30, 2, 6, 0.50f, brown, {0.16f, 0.36f, 0.07f}), PlantKind::bush, 0.012f, 10));
  c.push_back(with(tree("holly", 3, 0.7f, 25, 2, 5, 0.40f, gray_bark, {0.02f, 0.13f, 0.03f}), PlantKind::bush, 0.015f, 12));
  c.push_back(blooming(with(tree("rose", 1.5f, 1.0f, 35, 2, 5, 0.22f, {0.12f, 0.20f, 0.05f}, {0.07f, 0.22f, 0.05f}),
                            PlantKind::bush, 0.01f, 12), {0.75f, 0.02f, 0.05f}, 0.25f));
  c.push_back(blooming(with(tree("lilac", 3.5f, 0.9f, 28, 2, 6, 0.45f, gray_bark, {0.12f, 0.30f, 0.06f}),
                            PlantKind::bush, 0.012f, 12), {0.55f, 0.35f, 0.80f}, 0.45f));
  c.push_back(with(tree("juniper", 2, 1.2f, 55, 2, 7, 0.35f, brown, {0.10f, 0.20f, 0.12f}), PlantKind::bush, 0.015f, 14));
  c.push_back(with(tree("boxwood", 1.2f, 1.0f, 45, 2, 6, 0.25f, brown, {0.05f, 0.22f, 0.04f}), PlantKind::bush, 0.015f, 14));
  // Grasses: branches are blades, levels the segments per blade.
  c.push_back(with(tree("meadow grass", 0.5f, 0.6f, 30, 3, 24, 0.05f, brown, {0.20f, 0.45f, 0.06f}), PlantKind::grass, 0, 0));
  c.push_back(with(tree("dry grass", 0.7f, 0.5f, 35, 3, 24, 0.05f, brown, {0.55f, 0.45f, 0.18f}), PlantKind::grass, 0, 0));
  c.push_back(with(tree("reed", 2.2f, 0.25f, 8, 3, 16, 0.06f, brown, {0.30f, 0.40f, 0.12f}), PlantKind::grass, 0, 0));
  c.push_back(with(tree("fern", 0.8f, 1.4f, 60, 4, 9, 0.25f, brown, {0.06f, 0.30f, 0.04f}), PlantKind::grass, 0, 0));
  // Flowers: branches are petals, leaves the stems in a clump, bark the heart.
  c.push_back(blooming(with(tree("poppy", 0.6f, 0.5f, 35, 0, 5, 0.10f, {0.02f, 0.02f, 0.02f}, {0.12f, 0.35f, 0.06f}),
                            PlantKind::flower, 0, 5), {0.85f, 0.03f, 0.01f}, 1.0f));
  c.push_back(blooming(with(tree("daisy", 0.35f, 0.6f, 10, 0, 14, 0.06f, {0.90f, 0.65f, 0.02f}, {0.15f, 0.40f, 0.06f}),
                            PlantKind::flower, 0, 8), {0.92f, 0.92f, 0.88f}, 1.0f));
  c.push_back(blooming(with(tree("sunflower", 1.8f, 0.3f, 5, 0, 16, 0.30f, {0.15f, 0.07f, 0.02f}, {0.15f, 0.38f, 0.06f}),
                            PlantKind::flower, 0, 1), {0.95f, 0.70f, 0.02f}, 1.0f));
  c.push_back(blooming(with(tree("tulip", 0.45f, 0.4f, 70, 0, 6, 0.08f, {0.80f, 0.70f, 0.10f}, {0.18f, 0.40f, 0.10f}),
                            PlantKind::flower, 0, 4), {0.85f, 0.10f, 0.35f}, 1.0f));
  c.push_back(blooming(with(tree("cornflower", 0.5f, 0.6f, 25, 0, 8, 0.05f, {0.10f, 0.05f, 0.30f}, {0.25f, 0.40f, 0.20f}),
                            PlantKind::flower, 0, 6), {0.08f, 0.20f, 0.85f}, 1.0f));
  // Cacti: branches are arms.
  c.push_back(blooming(with(tree("saguaro", 7, 0.4f, 0, 0, 3, 0, brown, {0.12f, 0.30f, 0.10f}), PlantKind::cactus, 0.05f, 0),
                       {0.95f, 0.90f, 0.80f}, 1.0f));
  return c;
}

}  // namespace

void PlantSpecies::check() const {
  auto fail = [&](const char* field) { throw std::invalid_argument(field); };
  auto positive = [](float v) { return std::isfinite(v) && v > 0.0f; };
  if (!positive(height) || height > 200.0f) fail("height");
  if (!(crown >= 0.0f && crown <= 5.0f)) fail("crown");
  if (!(trunk >= 0.0f && trunk <= 0.5f)) fail("trunk");
  if (levels < 0 || levels > 5 + (kind == PlantKind::conifer ? 20 : 0)) fail("levels");
  if (branches < 0 || branches > (kind == PlantKind::broadleaf || kind == PlantKind::bush ? 8 : 64)) fail("branches");
  if (!(angle_deg >= 0.0f && angle_deg <= 90.0f)) fail("angle_deg");
  if (!(leaf_size >= 0.0f && leaf_size <= 10.0f)) fail("leaf_size");
  if (leaves < 0 || leaves > 64) fail("leaves");
  if (!(droop >= 0.0f && droop <= 1.0f)) fail("droop");
  if (!(bloom_share >= 0.0f && bloom_share <= 1.0f)) fail("bloom_share");
}

const std::vector<PlantSpecies>& plant_catalogue() {
  static const std::vector<PlantSpecies> catalogue = make_catalogue();
  return catalogue;
}

const PlantSpecies* find_species(const std::string& name) {
  const auto& c = plant_catalogue();
  const auto it = std::find_if(c.begin(), c.end(), [&](const PlantSpecies& s) { return s.name == name; });
  return it == c.end() ? nullptr : &*it;
}

std::string plant_kind_name(PlantKind kind) {
  switch (kind) {
    case PlantKind::broadleaf: return "broadleaf";
    case PlantKind::conifer: return "conifer";
    case PlantKind::palm: return "palm";
    case PlantKind::bush: return "bush";
    case PlantKind::grass: return "grass";
    case PlantKind::flower: return "flower";
    case PlantKind::cactus: return "cactus";
  }
  return "?";
}

PlantKind parse_plant_kind(const std::string& name) {
  for (PlantKind k : {PlantKind::broadleaf, PlantKind::conifer, PlantKind::palm, PlantKind::bush, PlantKind::grass,
                      PlantKind::flower, PlantKind::cactus}) {
    if (plant_kind_name(k) == name) return k;
  }
  throw std::invalid_argument("broadleaf, conifer, palm, bush, grass, flower, cactus");
}

}  // namespace pointgen
