#include "app/render/point_samples.hpp"

#include "app/render/buffer_texture_units.hpp"

#include "app/errors.hpp"

#include "pointgen/random.hpp"
#include "pointgen/sampling/point_count.hpp"
#include "pointgen/sampling/surface_samples.hpp"

#include <cmath>

namespace ecoview {
namespace {

// Longest sample list of one mesh; an instance needing more is drawn as polygons.
constexpr std::size_t max_samples = 1u << 17;
// A list holds this many times the points its polygons cost: enough for a mostly hidden near
// instance's parts in a shadow map, and for the samples that tell which pixels its polygons cover.
constexpr float list_per_polygon_equivalent = 6.0f;

}  // namespace

PointSamples::PointSamples(const Scene& scene, float points_per_triangle, bool points) {
  std::vector<glm::vec4> positions, normals, colors;
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const pointgen::TriangleMesh& mesh = scene.meshes[m];
    const pointgen::Bounds b = mesh.bounds();
    pointgen::SampledMesh info;
    info.area = pointgen::surface_area(mesh);
    if (!b.empty()) {
      info.center = 0.5f * (b.min + b.max);
      info.radius = 0.5f * glm::length(b.max - b.min);
      info.half_size = 0.5f * (b.max - b.min);
    }
    info.triangles = mesh.triangle_count();
    first_.push_back(static_cast<std::uint32_t>(positions.size()));
    if (points && scene.point_meshes[m]) {
      info.samples = std::min(max_samples, static_cast<std::size_t>(std::ceil(list_per_polygon_equivalent * points_per_triangle * static_cast<float>(info.triangles))));
      const std::vector<pointgen::SurfaceSample> samples = pointgen::sample_surface(mesh, info.samples, pointgen::derive_seed(0x5a3, m));
      info.samples = samples.size();  // shorter where an alpha mask keeps little of the mesh
      std::vector<glm::vec3> sample_normals;
      for (const pointgen::SurfaceSample& s : samples) {
        info.sample_positions.push_back(s.position);
        sample_normals.push_back(s.normal);
      }
      info.normal_moments = pointgen::normal_moments(sample_normals);
      pointgen::MeshSplit split = pointgen::split_into_parts(info.sample_positions, sample_normals, info.area);
      info.parts = std::move(split.parts);
      info.polygon_parts = pointgen::split_triangles(mesh).parts;  // as GpuScene orders the triangles
      // A normal's w is the area of the list its sample is in: n points of a list stand for
      // that area over n each (point_coverage.glsl).
      const auto add = [&](const pointgen::SurfaceSample& s, float list_area) {
        positions.emplace_back(s.position, 1.0f);
        normals.emplace_back(s.normal, list_area);
        colors.emplace_back(s.color, 1.0f);
      };
      for (const pointgen::SurfaceSample& s : samples) add(s, info.area);
      for (const pointgen::MeshPart& part : info.parts) {
        for (std::uint32_t j = 0; j < part.samples; ++j) {
          const std::uint32_t i = split.order[part.first - samples.size() + j];
          add(samples[i], part.area);
          info.sample_positions.push_back(samples[i].position);
        }
      }
    }
    meshes_.push_back(std::move(info));
  }
  if (const std::size_t limit = gl::max_texel_buffer_texels(); positions.size() > limit) {
    throw RuntimeFailure("the scene's point samples are " + std::to_string(positions.size()) +
                         ", more than the texels of one of this driver's buffer textures (" + std::to_string(limit) +
                         "); use --geometry polygons");
  }
  gl::store(positions_, positions);
  gl::store(normals_, normals);
  gl::store(colors_, colors);
  position_texels_ = gl::buffer_texels(positions_);
  normal_texels_ = gl::buffer_texels(normals_);
  color_texels_ = gl::buffer_texels(colors_);
}

void PointSamples::bind() const {
  glBindTextureUnit(position_texels_unit, position_texels_.name());
  glBindTextureUnit(normal_texels_unit, normal_texels_.name());
  glBindTextureUnit(color_texels_unit, color_texels_.name());
}

}  // namespace ecoview
