#include "app/scene/landscape_fields.hpp"

#include "pointgen/random.hpp"
#include "pointgen/sampling/surface_samples.hpp"

#include <stdexcept>

namespace ecoview {
namespace {

pointgen::LandscapeTerrainSpec read_landscape_terrain(const JsonField& field) {
  field.only_keys({"relief", "feature", "octaves", "valley_depth", "valley_width", "valley_meander", "valley_wavelength"});
  pointgen::LandscapeTerrainSpec terrain;
  if (auto f = field.optional("relief")) terrain.relief = f->number_f(0, 1e4);
  if (auto f = field.optional("feature")) terrain.feature = f->number_f(1, 1e6);
  if (auto f = field.optional("octaves")) terrain.octaves = f->integer(1, 12);
  if (auto f = field.optional("valley_depth")) terrain.valley_depth = f->number_f(0, 1e4);
  if (auto f = field.optional("valley_width")) terrain.valley_width = f->number_f(1, 1e6);
  if (auto f = field.optional("valley_meander")) terrain.valley_meander = f->number_f(0, 1e6);
  if (auto f = field.optional("valley_wavelength")) terrain.valley_wavelength = f->number_f(1, 1e6);
  return terrain;
}

// A species of a layer and its mesh: grown from the catalogue (or a species the file defines),
// varying its colours, or the user's, which has colours of its own.
pointgen::LandscapeSpecies read_layer_species(const JsonField& item, const std::vector<pointgen::PlantSpecies>& defined,
                                              std::uint64_t seed, const LoadMesh& load_mesh, pointgen::TriangleMesh& mesh) {
  item.only_keys({"species", "file", "weight", "altitude", "slope_max_deg", "grove", "grove_size", "scale"});
  pointgen::LandscapeSpecies s;
  if (auto file = item.optional("file")) {
    if (item.has("species")) file->fail("a species from a file has no \"species\"");
    s.name = file->string();
    s.tint_spread = 0.0f;
    mesh = load_mesh(*file);
  } else {
    const pointgen::PlantSpecies grown = read_species(item["species"], defined);
    s.name = grown.name;
    mesh = pointgen::build_plant(grown, seed);
  }
  s.surface = pointgen::surface_area(mesh);
  if (const pointgen::Bounds b = mesh.bounds(); !b.empty()) s.height = std::max(b.max.y, 0.0f);
  if (auto f = item.optional("weight")) s.weight = f->number_f(0, 1e6);
  if (auto f = item.optional("altitude")) s.altitude = f->range(-1e6, 1e6);
  if (auto f = item.optional("slope_max_deg")) s.slope_max_deg = f->number_f(0, 90);
  if (auto f = item.optional("grove")) s.grove = f->number_f(0, 1);
  if (auto f = item.optional("grove_size")) s.grove_size = f->number_f(1, 1e6);
  if (auto f = item.optional("scale")) s.scale = f->range(1e-3, 1e3);
  return s;
}

}  // namespace

LandscapeObject read_landscape(const JsonField& field, std::uint64_t scene_seed, const LoadMesh& load_mesh) {
  field.only_keys({"type", "seed", "size", "radius", "ground_cells", "ground_step", "terrain", "species", "layers"});
  LandscapeObject object;
  pointgen::LandscapeSpec& spec = object.spec;
  const int own_seed = field.has("seed") ? field["seed"].integer(0, 2147483647) : 0;
  const std::uint64_t seed = pointgen::derive_seed(scene_seed, static_cast<std::uint64_t>(own_seed) + 0x1a5d);
  spec.seed = static_cast<std::uint32_t>(seed);
  const std::vector<double> size = field["size"].numbers(2, 1, pointgen::LandscapeSpec::max_size);
  spec.size = {size[0], size[1]};
  if (auto f = field.optional("radius")) object.radius = f->number_f(0, 2.0 * pointgen::LandscapeSpec::max_size);
  if (auto f = field.optional("ground_cells")) object.ground.cells = f->integer(1, 256);
  if (auto f = field.optional("ground_step")) object.ground.step = f->number_f(0.1, 1e4);
  if (auto f = field.optional("terrain")) spec.terrain = read_landscape_terrain(*f);

  std::vector<pointgen::PlantSpecies> defined;
  if (auto list = field.optional("species")) {
    for (const JsonField& item : list->items()) defined.push_back(read_species(item, defined));
  }
  for (const JsonField& layer_field : field["layers"].items(1)) {
    layer_field.only_keys({"name", "cell_size", "density", "radius", "species"});
    pointgen::LandscapeLayer layer;
    if (auto f = layer_field.optional("name")) layer.name = f->string();
    object.reach.push_back(object.radius);
    if (auto f = layer_field.optional("radius")) object.reach.back() = f->number_f(0, 2.0 * pointgen::LandscapeSpec::max_size);
    layer.cell_size = layer_field["cell_size"].number_f(0.1, 1e4);
    layer.density = layer_field["density"].number_f(0, 1e4);
    std::vector<pointgen::TriangleMesh>& meshes = object.meshes.emplace_back();
    for (const JsonField& item : layer_field["species"].items(1)) {
      const std::uint64_t mesh_seed = pointgen::derive_seed(seed, 1000 * object.meshes.size() + meshes.size());
      layer.species.push_back(read_layer_species(item, defined, mesh_seed, load_mesh, meshes.emplace_back()));
    }
    spec.layers.push_back(layer);
  }
  try {
    spec.check();
  } catch (const std::invalid_argument& e) {
    field.fail(e.what());
  }
  return object;
}

}  // namespace ecoview
