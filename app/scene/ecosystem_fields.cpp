#include "app/scene/ecosystem_fields.hpp"

#include "app/scene/scene_fields.hpp"
#include "pointgen/random.hpp"

#include <stdexcept>

namespace ecoview {
namespace {

std::string catalogue_names() {
  std::string names;
  for (const pointgen::PlantSpecies& s : pointgen::plant_catalogue()) names += (names.empty() ? "" : ", ") + s.name;
  return names;
}

const pointgen::PlantSpecies& named_species(const JsonField& field, const std::string& name,
                                            const std::vector<pointgen::PlantSpecies>& defined) {
  for (const pointgen::PlantSpecies& s : defined) {
    if (s.name == name) return s;
  }
  if (const pointgen::PlantSpecies* s = pointgen::find_species(name)) return *s;
  field.fail("unknown species '" + name + "' (define it under \"species\", or use one of: " + catalogue_names() + ")");
}

pointgen::TerrainSpec read_terrain(const JsonField& field, pointgen::TerrainSpec terrain) {
  field.only_keys({"relief", "feature", "resolution", "low_color", "high_color"});
  if (auto f = field.optional("relief")) terrain.relief = f->number_f(0, 1e4);
  if (auto f = field.optional("feature")) terrain.feature = f->number_f(1, 1e6);
  if (auto f = field.optional("resolution")) terrain.resolution = f->integer(1, 2048);
  if (auto f = field.optional("low_color")) terrain.low_color = srgb_to_linear(f->color());
  if (auto f = field.optional("high_color")) terrain.high_color = srgb_to_linear(f->color());
  return terrain;
}

int read_layer(const JsonField& field) {
  const std::string name = field.string();
  if (name == "trees") return 0;
  if (name == "bushes") return 1;
  if (name == "ground") return 2;
  field.fail("unknown layer '" + name + "' (known: trees, bushes, ground)");
}

}  // namespace

pointgen::PlantSpecies read_species(const JsonField& field, const std::vector<pointgen::PlantSpecies>& defined) {
  if (field.is_string()) return named_species(field, field.string(), defined);
  field.only_keys({"name", "like", "kind", "height", "crown", "trunk", "levels", "branches", "angle_deg", "leaf_size",
                   "leaves", "droop", "bark", "leaf", "bloom", "bloom_share"});
  pointgen::PlantSpecies s;
  if (auto like = field.optional("like")) s = named_species(*like, like->string(), defined);
  if (auto f = field.optional("name")) s.name = f->string();
  if (auto f = field.optional("kind")) {
    try {
      s.kind = pointgen::parse_plant_kind(f->string());
    } catch (const std::invalid_argument& known) {
      f->fail("unknown plant kind '" + f->string() + "' (known: " + known.what() + ")");
    }
  }
  if (auto f = field.optional("height")) s.height = f->number_f(0.01, 200);
  if (auto f = field.optional("crown")) s.crown = f->number_f(0, 5);
  if (auto f = field.optional("trunk")) s.trunk = f->number_f(0, 0.5);
  if (auto f = field.optional("levels")) s.levels = f->integer(0, 25);
  if (auto f = field.optional("branches")) s.branches = f->integer(0, 64);
  if (auto f = field.optional("angle_deg")) s.angle_deg = f->number_f(0, 90);
  if (auto f = field.optional("leaf_size")) s.leaf_size = f->number_f(0, 10);
  if (auto f = field.optional("leaves")) s.leaves = f->integer(0, 64);
  if (auto f = field.optional("droop")) s.droop = f->number_f(0, 1);
  if (auto f = field.optional("bark")) s.bark = srgb_to_linear(f->color());
  if (auto f = field.optional("leaf")) s.leaf = srgb_to_linear(f->color());
  if (auto f = field.optional("bloom")) s.bloom = srgb_to_linear(f->color());
  if (auto f = field.optional("bloom_share")) s.bloom_share = f->number_f(0, 1);
  if (s.name.empty()) field.fail("a species needs a \"name\" (or \"like\" a named one)");
  try {
    s.check();
  } catch (const std::invalid_argument& e) {
    field.fail(std::string("field '") + e.what() + "' is out of range for a " + pointgen::plant_kind_name(s.kind));
  }
  return s;
}

pointgen::EcosystemSpec read_ecosystem(const JsonField& field, std::uint64_t scene_seed, const LoadMesh& load_mesh) {
  field.only_keys({"type", "seed", "center", "size", "terrain", "species", "plants", "clearings", "animals"});
  pointgen::EcosystemSpec spec;
  const int own_seed = field.has("seed") ? field["seed"].integer(0, 2147483647) : 0;
  spec.seed = pointgen::derive_seed(scene_seed, static_cast<std::uint64_t>(own_seed) + 0xec0);
  const glm::vec3 center = field.has("center") ? field["center"].vec3() : glm::vec3(0.0f);
  const std::vector<double> size = field["size"].numbers(2, 1, 1e5);
  spec.terrain.center = {center.x, center.z};
  spec.terrain.size = {size[0], size[1]};
  spec.terrain.seed = pointgen::derive_seed(spec.seed, 7);
  if (auto f = field.optional("terrain")) spec.terrain = read_terrain(*f, spec.terrain);

  if (auto list = field.optional("clearings")) {
    for (const JsonField& item : list->items()) {
      const std::vector<double> c = item.numbers(3, -JsonField::max_coordinate, JsonField::max_coordinate);
      if (c[2] <= 0.0) item.fail("the third number, a radius, must be positive");
      spec.clearings.emplace_back(c[0], c[1], c[2]);
    }
  }
  std::vector<pointgen::PlantSpecies> defined;
  if (auto list = field.optional("species")) {
    for (const JsonField& item : list->items()) defined.push_back(read_species(item, defined));
  }
  for (const JsonField& item : field["plants"].items(1)) {
    item.only_keys({"species", "count", "variants", "file", "layer", "scale", "tint"});
    pointgen::PlantRequest request;
    request.count = item["count"].integer(0, 100000000);
    // The user's own mesh keeps its colours unless asked; the catalogue's plants vary as they did.
    if (item.has("file")) request.tint = 0.0f;
    if (auto f = item.optional("tint")) request.tint = f->number_f(0, 1);
    if (auto file = item.optional("file")) {
      if (item.has("species") || item.has("variants")) file->fail("a species from a file has no \"species\" or \"variants\"");
      request.species.name = file->string();
      request.mesh = std::make_shared<const pointgen::TriangleMesh>(load_mesh(*file));
      if (auto f = item.optional("layer")) request.layer = read_layer(*f);
      if (auto f = item.optional("scale")) request.scale = f->range(1e-3, 1e3);
    } else {
      if (item.has("layer") || item.has("scale")) item["species"].fail("\"layer\" and \"scale\" are for species from a \"file\"");
      request.species = read_species(item["species"], defined);
      if (auto f = item.optional("variants")) request.variants = f->integer(1, 16);
    }
    spec.plants.push_back(request);
  }
  return spec;
}

}  // namespace ecoview
