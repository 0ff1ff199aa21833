#include "app/scene/scene_file.hpp"

#include "app/errors.hpp"
#include "app/file_io.hpp"
#include "app/resources.hpp"
#include "app/scene/ecosystem_fields.hpp"
#include "app/scene/json_input.hpp"
#include "app/scene/landscape_fields.hpp"
#include "app/scene/mover_fields.hpp"
#include "app/scene/set_piece_fields.hpp"
#include "app/scene/scene_fields.hpp"
#include "pointgen/file_error.hpp"
#include "pointgen/input_file.hpp"
#include "pointgen/landscape/landscape_cells.hpp"
#include "pointgen/landscape/landscape_pool.hpp"
#include "pointgen/placement/height_grid_mesh.hpp"
#include "pointgen/primitives.hpp"
#include "pointgen/random.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <malloc.h>

#include <algorithm>
#include <cstdio>
#include <map>

namespace ecoview {
namespace {

namespace fs = std::filesystem;

const glm::vec3 default_color(0.8f);

// The scene's meshes and instance tables as objects are added: each primitive and each mesh file
// is stored once, and all instances of one mesh share a table.
class SceneBuilder {
 public:
  SceneBuilder(Scene& scene, const InputSource& source, std::uint64_t seed, const LoadLimits& limits)
      : scene_(scene), source_(source), seed_(seed), limits_(limits) {}

  void add_object(const JsonField& object) {
    const std::string type = object["type"].string();
    if (type == "plane") {
      object.only_keys({"type", "center", "size", "color"});
      const glm::vec3 color = color_of(object, default_color);
      const std::vector<double> size = object["size"].numbers(2, 1e-6, 2 * JsonField::max_coordinate);
      const glm::mat4 t = glm::scale(glm::translate(glm::mat4(1.0f), object["center"].vec3()),
                                     glm::vec3(size[0], 1.0, size[1]));
      add_instance(primitive("plane"), t, color);
    } else if (type == "box") {
      object.only_keys({"type", "min", "max", "color"});
      const glm::vec3 color = color_of(object, default_color);
      const glm::vec3 min = object["min"].vec3();
      const glm::vec3 max = object["max"].vec3();
      if (glm::any(glm::greaterThanEqual(min, max))) object["max"].fail("must be greater than min in x, y and z");
      add_instance(primitive("box"), glm::scale(glm::translate(glm::mat4(1.0f), 0.5f * (min + max)), max - min), color);
    } else if (type == "sphere") {
      object.only_keys({"type", "center", "radius", "color"});
      const glm::vec3 color = color_of(object, default_color);
      const float radius = object["radius"].number_f(1e-6, JsonField::max_coordinate);
      add_instance(primitive("sphere"), glm::scale(glm::translate(glm::mat4(1.0f), object["center"].vec3()), glm::vec3(radius)), color);
    } else if (type == "mesh") {
      object.only_keys({"type", "file", "transforms", "color", "points"});
      const glm::vec3 color = color_of(object, default_color);
      const bool points = object.has("points") && object["points"].boolean();
      const std::size_t mesh = mesh_file(object["file"], points);
      if (!object.has("transforms")) {
        add_instance(mesh, glm::mat4(1.0f), color);
        return;
      }
      for (const JsonField& item : object["transforms"].items(1)) add_instance(mesh, read_transform(item), color);
    } else if (type == "plant") {
      add_plants(object);
    } else if (type == "ecosystem") {
      add_ecosystem(object);
    } else if (type == "landscape") {
      add_landscape(object);
    } else if (type == "crowd") {
      reserve_memory(object, bytes_per_mover * (object.has("count") ? object["count"].number(0, 1e6) : 0.0));
      add_moving_set(read_crowd(object, seed_));
    } else if (type == "traffic") {
      reserve_memory(object, bytes_per_mover * (object.has("cars") ? object["cars"].number(0, 1e6) : 0.0));
      add_moving_set(read_traffic(object, seed_));
    } else if (std::vector<PlacedMesh> pieces = read_set_piece(object, type, seed_, [this](const JsonField& field, double bytes) {
                 reserve_memory(field, bytes);
               });
               !pieces.empty()) {
      for (PlacedMesh& piece : pieces) {
        scene_.meshes.push_back(std::move(piece.mesh));
        for (std::size_t i = 0; i < piece.transforms.size(); ++i) {
          add_instance(scene_.meshes.size() - 1, piece.transforms[i], piece.colors[i]);
        }
      }
    } else {
      object["type"].fail("unknown object type '" + type + "' (known: plane, box, sphere, mesh, plant, ecosystem, landscape, "
                          "crowd, traffic, cathedral, houses, chess, lathe)");
    }
  }

 private:
  static glm::vec3 color_of(const JsonField& object, const glm::vec3& fallback) {
    return object.has("color") ? srgb_to_linear(object["color"].color()) : fallback;
  }

  std::size_t primitive(const std::string& kind) {
    const auto it = primitives_.find(kind);
    if (it != primitives_.end()) return it->second;
    scene_.meshes.push_back(kind == "plane" ? pointgen::unit_plane()
                            : kind == "box" ? pointgen::unit_box()
                                            : pointgen::unit_sphere());
    return primitives_[kind] = scene_.meshes.size() - 1;
  }

  // A file's mesh, loaded once for its polygon instances and once for its point instances (a point
  // mesh's far instances are drawn as points: plants, people, animals).
  std::size_t mesh_file(const JsonField& field, bool points) {
    const std::pair<std::string, bool> key(field.string(), points);
    const auto it = files_.find(key);
    if (it != files_.end()) return it->second;
    scene_.meshes.push_back(load_file(field));
    const std::size_t mesh = scene_.meshes.size() - 1;
    if (points) mark_point_meshes(mesh, mesh + 1);
    return files_[key] = mesh;
  }

  pointgen::TriangleMesh load_file(const JsonField& field) {
    pointgen::TriangleMesh mesh;
    try {
      mesh = pointgen::load_mesh_file(field.string(), source_.read_relative,
                                      [this](const std::string& line) { scene_.notes.push_back(line); });
    } catch (const pointgen::FileError& e) {
      field.fail(e.what());
    }
    // Its textures decoded, and again as mipmapped GL textures (4/3 of the image each).
    reserve_memory(field, (1.0 + 4.0 / 3.0) * static_cast<double>(mesh.texture_bytes()));
    return mesh;
  }

  static glm::mat4 read_transform(const JsonField& field) {
    const std::vector<double> v = field.numbers(16, -JsonField::max_coordinate, JsonField::max_coordinate);
    glm::mat4 m;
    for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = static_cast<float>(v[static_cast<std::size_t>(i)]);
    if (m[0][3] != 0.0f || m[1][3] != 0.0f || m[2][3] != 0.0f || m[3][3] != 1.0f) {
      field.fail("not an affine transform: in column-major order, numbers 4, 8, 12 must be 0 and 16 must be 1");
    }
    if (std::abs(glm::determinant(glm::mat3(m))) < 1e-12f) field.fail("the transform is singular");
    return m;
  }

  // {"type": "plant", "species": name or {...}, "seed", "positions": [[x, y, z], ...], "scale"}
  void add_plants(const JsonField& object) {
    object.only_keys({"type", "species", "seed", "positions", "scale", "color"});
    const pointgen::PlantSpecies species = read_species(object["species"], {});
    const auto seed = object.has("seed") ? static_cast<std::uint64_t>(object["seed"].integer(0, 2147483647)) : 1u;
    const float scale = object.has("scale") ? object["scale"].number_f(1e-3, 1e3) : 1.0f;
    const glm::vec3 color = color_of(object, glm::vec3(1.0f));  // plants have their own colours; this tints them
    scene_.meshes.push_back(pointgen::build_plant(species, pointgen::derive_seed(seed_, seed)));
    const std::size_t mesh = scene_.meshes.size() - 1;
    mark_point_meshes(mesh, mesh + 1);
    for (const JsonField& p : object["positions"].items(1)) {
      add_instance(mesh, glm::scale(glm::translate(glm::mat4(1.0f), p.vec3()), glm::vec3(scale)), color);
    }
  }

  void add_ecosystem(const JsonField& object) {
    const pointgen::EcosystemSpec spec = read_ecosystem(object, seed_, [this](const JsonField& file) { return load_file(file); });
    reserve_memory(object, static_cast<double>(pointgen::estimated_bytes(spec)));
    pointgen::Ecosystem eco = grow(object, spec);
    const std::size_t first = scene_.meshes.size();
    for (pointgen::TriangleMesh& mesh : eco.meshes) scene_.meshes.push_back(std::move(mesh));
    mark_point_meshes(first + 1, scene_.meshes.size());  // the plants; the terrain (first) stays polygons
    const float base = object.has("center") ? object["center"].vec3().y : 0.0f;
    for (pointgen::InstanceTable& table : eco.tables) {
      if (table.size() == 0) continue;
      table.mesh += first;
      for (glm::mat4x3& t : table.transforms) t[3].y += base;
      scene_.groups.push_back(std::move(table));
    }
    if (auto animals = object.optional("animals")) {
      std::uint64_t herd = 0;
      for (const JsonField& item : animals->items()) {
        item.only_keys({"kind", "count", "pasture"});
        if (item["kind"].string() != "cow") item["kind"].fail("unknown animal (known: cow)");
        const int count = item["count"].integer(0, 100000);
        reserve_memory(item, bytes_per_mover * count);
        const glm::vec2 center = spec.terrain.center;
        const pointgen::Rect pasture = item.has("pasture") ? read_rect(item["pasture"])
                                                           : pointgen::Rect{center - 20.0f, center + 20.0f};
        add_moving_set(pointgen::make_herd(count, eco.terrain, pasture, base, pointgen::derive_seed(spec.seed, 0xc0 + herd++)));
      }
    }
  }

  static pointgen::Ecosystem grow(const JsonField& object, const pointgen::EcosystemSpec& spec) {
    try {
      return pointgen::grow_ecosystem(spec);
    } catch (const std::invalid_argument& e) {
      object["clearings"].fail(e.what());
    }
  }

  // A landscape's species meshes, an empty table each, and its ground's chunks for the camera:
  // the renderer makes the cells within reach of each frame's eye (LandscapePool) into the tables
  // and the ground's chunks for it (GroundChunks). The pool's plants and the cells it keeps are
  // reserved now.
  void add_landscape(const JsonField& object) {
    LandscapeObject landscape = read_landscape(object, seed_, [this](const JsonField& file) { return load_file(file); });
    LandscapeSource source;
    source.spec = landscape.spec;
    source.reach = landscape.reach;
    const pointgen::LandscapeSpec& spec = source.spec;
    scene_.landscape_plants += pointgen::expected_plant_count(spec);
    // The keys of the cells within reach and the band beyond it are listed each frame: a layer of
    // fine cells under a wide reach is refused by their count before the first is listed.
    for (std::size_t layer = 0; layer < spec.layers.size(); ++layer) {
      const float side = spec.layers[layer].cell_size;
      const double across = std::floor(2.0 * (1.0 + pointgen::LandscapePool::band) * source.reach[layer] / side) + 2.0;
      reserve_memory(object, across * across * (sizeof(pointgen::CellKey) + sizeof(float)));
    }
    const double pool_plants = std::floor(limits_.plant_pool_bytes / bytes_per_plant);
    source.capacity = std::min(pointgen::LandscapePool::most_plants_in_reach(spec, source.reach) + pointgen::LandscapePool::far_plants,
                               static_cast<std::size_t>(pool_plants));
    pointgen::GroundChunks ground(spec, landscape.ground);
    const std::vector<pointgen::GroundChunkKey> chunks = ground.chosen(scene_.camera.position);
    // Its ground's chunks for the camera, each of n² squares: the chunks for any eye are about as
    // many (a few per level of the quadtree).
    const double n = landscape.ground.cells;
    double triangles = static_cast<double>(chunks.size()) * 2.0 * n * n;
    for (const std::vector<pointgen::TriangleMesh>& layer : landscape.meshes) {
      for (const pointgen::TriangleMesh& mesh : layer) triangles += static_cast<double>(mesh.triangle_count());
    }
    // Its plants, and the cells kept made (up to twice as many plants, LandscapePool).
    reserve_memory(object, static_cast<double>(source.capacity) * (bytes_per_plant + 2 * sizeof(pointgen::LandscapePlant)) +
                               triangles * bytes_per_triangle);
    scene_.meshes.push_back(ground.mesh(chunks).mesh);
    source.ground_mesh = scene_.meshes.size() - 1;
    source.ground = landscape.ground;
    add_instance(source.ground_mesh, glm::mat4(1.0f), glm::vec3(1.0f));
    source.first_group = scene_.groups.size();
    for (std::size_t layer = 0; layer < spec.layers.size(); ++layer) {
      for (std::size_t s = 0; s < spec.layers[layer].species.size(); ++s) {
        pointgen::TriangleMesh& mesh = landscape.meshes[layer][s];
        const pointgen::Bounds b = mesh.bounds();
        if (!b.empty()) source.plant_reach = std::max(source.plant_reach, spec.layers[layer].species[s].scale.y * glm::length(glm::max(glm::abs(b.min), glm::abs(b.max))));
        scene_.meshes.push_back(std::move(mesh));
        mark_point_meshes(scene_.meshes.size() - 1, scene_.meshes.size());
        scene_.groups.push_back({scene_.meshes.size() - 1, {}, {}, {}});
      }
    }
    const std::size_t species = scene_.groups.size() - source.first_group;
    for (std::size_t s = 0; s < species; ++s) scene_.groups.push_back({scene_.groups[source.first_group + s].mesh, {}, {}, {}, true});
    scene_.landscapes.push_back(std::move(source));
  }

  // A plant's table row and GPU instance record; a triangle's CPU and GPU copies of its vertices
  // and indices, about.
  static constexpr double bytes_per_plant = 56 + 128;
  static constexpr double bytes_per_triangle = 2 * (3 * 36 + 12);

  // The set's part meshes and its tables posed at t = 0; the renderer poses them per frame.
  void add_moving_set(pointgen::MovingSet set) {
    const std::size_t first_mesh = scene_.meshes.size();
    for (pointgen::TriangleMesh& mesh : set.part_meshes()) scene_.meshes.push_back(std::move(mesh));
    std::size_t mesh = first_mesh;
    for (const pointgen::Body& body : set.bodies) {
      if (body.as_points) mark_point_meshes(mesh, mesh + body.parts.size());
      mesh += body.parts.size();
    }
    const std::size_t first_group = scene_.groups.size();
    for (pointgen::InstanceTable& table : set.pose(0.0, first_mesh)) scene_.groups.push_back(std::move(table));
    scene_.animations.push_back({std::move(set), first_group, first_mesh});
  }

  // A mover's part records (table rows and GPU instances), about.
  static constexpr double bytes_per_mover = 10 * (64 + 128);

  void mark_point_meshes(std::size_t begin, std::size_t end) {
    scene_.point_meshes.resize(scene_.meshes.size(), false);
    std::fill(scene_.point_meshes.begin() + static_cast<std::ptrdiff_t>(begin),
              scene_.point_meshes.begin() + static_cast<std::ptrdiff_t>(end), true);
  }

  void reserve_memory(const JsonField& object, double bytes) {
    reserved_bytes_ += bytes;
    if (reserved_bytes_ > limits_.memory_budget_bytes) {
      const double gib = 1024.0 * 1024.0 * 1024.0;
      char message[160];
      std::snprintf(message, sizeof message, "the scene would need about %.2f GiB, above the memory budget of %.2f GiB "
                    "(raise it with --memory-budget)", reserved_bytes_ / gib, limits_.memory_budget_bytes / gib);
      object.fail(message);
    }
  }

  void add_instance(std::size_t mesh, const glm::mat4& transform, const glm::vec3& color) {
    auto it = group_of_mesh_.find(mesh);
    if (it == group_of_mesh_.end()) {
      scene_.groups.push_back({mesh, {}, {}, {}});
      it = group_of_mesh_.emplace(mesh, scene_.groups.size() - 1).first;
    }
    scene_.groups[it->second].add(transform, color, pointgen::derive_seed(seed_, next_instance_++));
  }

  Scene& scene_;
  const InputSource& source_;
  std::uint64_t seed_;
  const LoadLimits& limits_;
  double reserved_bytes_ = 0.0;
  std::uint64_t next_instance_ = 0;
  std::map<std::string, std::size_t> primitives_;
  std::map<std::pair<std::string, bool>, std::size_t> files_;
  std::map<std::size_t, std::size_t> group_of_mesh_;
};

std::string singular(const std::string& folder) {
  return folder.back() == 's' ? folder.substr(0, folder.size() - 1) : folder;
}

}  // namespace

InputSource open_input(const std::string& name_or_file, const std::string& folder) {
  std::error_code ec;
  const std::string resource = "data/" + folder + "/" + name_or_file + ".json";
  const bool is_shipped = resources::find(resource).has_value();
  // A file wins over a shipped name, but a folder (such as a capture's output) does not.
  if (fs::is_regular_file(name_or_file, ec) || (!is_shipped && fs::exists(name_or_file, ec))) {
    std::string text = read_named_file(name_or_file);
    const fs::path base = fs::path(name_or_file).parent_path();
    return {name_or_file, std::move(text),
            [base](const std::string& relative) { return pointgen::read_input_file(base / relative); }};
  }
  if (const auto text = resources::find(resource)) {
    const fs::path base = "data/" + folder;
    return {resource, std::string(*text), [base](const std::string& relative) -> std::optional<std::string> {
              const auto bytes = resources::find((base / relative).lexically_normal().generic_string());
              if (!bytes) return std::nullopt;
              return std::string(*bytes);
            }};
  }
  std::string shipped;
  for (const std::string& name : resources::names_in("data/" + folder, ".json")) {
    shipped += (shipped.empty() ? "" : ", ") + name;
  }
  throw InputError(name_or_file + ": no such file, and no shipped " + singular(folder) +
                   " of that name (shipped: " + shipped + ")");
}

Scene load_scene(const InputSource& source, const LoadLimits& limits) {
  const nlohmann::json document = parse_json(source.text, source.name);
  const JsonField root(document, source.name);
  root.only_keys({"camera", "lights", "objects", "seed", "comment"});
  Scene scene;
  scene.name = source.name;
  scene.camera = read_camera(root["camera"]);
  for (const JsonField& light : root["lights"].items(1)) scene.lights.push_back(read_light(light));
  const auto seed = root.has("seed") ? static_cast<std::uint64_t>(root["seed"].integer(0, 2147483647)) : 1u;
  SceneBuilder builder(scene, source, seed, limits);
  for (const JsonField& object : root["objects"].items(1)) builder.add_object(object);
  scene.point_meshes.resize(scene.meshes.size(), false);
  // The placement's working buffers, freed, would stay resident in the heap's arenas: 10 M plants
  // kept 10 bytes a plant resident beyond what their tables hold, 3-5 after giving them back.
  malloc_trim(0);
  return scene;
}

}  // namespace ecoview
