#include "app/render/gpu_sampler.hpp"

#include "app/errors.hpp"
#include "app/gl/shader_program.hpp"
#include "pointgen/random.hpp"
#include "pointgen/sampling/frustum_culling.hpp"

#include <algorithm>

namespace ecoview {
namespace {

// As shaders/sample_common.glsl declares them.
struct GpuInstance {
  glm::mat4 model;
  glm::vec4 tint;
};
struct GpuMesh {
  glm::vec4 center_radius;
  glm::vec4 area;
  glm::vec4 moments[3];
  glm::uvec4 sizes;
};

constexpr GLuint draws_binding = 1, instances_binding = 2, block_draws_binding = 8, plant_meshes_binding = 10,
                 meshes_binding = 11, counts_binding = 12, offsets_binding = 13, group_sums_binding = 14, totals_binding = 15;
constexpr std::size_t plants_per_group = 1024, threads_per_group = 256;  // shaders/sample_count.comp
constexpr std::size_t points_per_block = 16;                              // shaders/point_common.glsl
constexpr std::size_t max_views = 6;                                      // planes[36]

// The same threshold pointgen::sample_view rounds a whole plant's count at.
float rounding(const pointgen::InstanceTable& table, std::size_t i) {
  return pointgen::Random(table.seeds.size() > i ? table.seeds[i] : i).uniform();
}

template <class T>
void storage(gl::Buffer& buffer, std::size_t count) {
  glNamedBufferStorage(buffer.name(), static_cast<GLsizeiptr>(std::max<std::size_t>(count, 1) * sizeof(T)), nullptr, 0);
}

}  // namespace

GpuSampler::GpuSampler(const std::vector<pointgen::InstanceTable>& tables, const PointSamples& samples)
    : count_program_(gl::build_program({"sample_count.comp"})),
      groups_program_(gl::build_program({"sample_groups.comp"})),
      draws_program_(gl::build_program({"sample_draws.comp"})) {
  const std::vector<pointgen::SampledMesh>& meshes = samples.meshes();
  std::vector<GpuInstance> instances;
  std::vector<glm::uvec2> plant_meshes;
  std::size_t most_points = 0;  // the draw list's points if every plant took its whole list
  for (const pointgen::InstanceTable& table : tables) {
    first_plant_.push_back(static_cast<std::uint32_t>(instances.size()));
    if (meshes[table.mesh].samples == 0) continue;
    for (std::size_t i = 0; i < table.size(); ++i) {
      instances.push_back({table.transforms[i], glm::vec4(table.tints[i], 1.0f)});
      plant_meshes.emplace_back(static_cast<std::uint32_t>(table.mesh), glm::floatBitsToUint(rounding(table, i)));
    }
    most_points += table.size() * meshes[table.mesh].samples;
  }
  std::vector<GpuMesh> gpu_meshes;
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const pointgen::SampledMesh& mesh = meshes[m];
    gpu_meshes.push_back({glm::vec4(mesh.center, mesh.radius), glm::vec4(mesh.area, 0.0f, 0.0f, 0.0f),
                          {glm::vec4(mesh.normal_moments[0], 0.0f), glm::vec4(mesh.normal_moments[1], 0.0f),
                           glm::vec4(mesh.normal_moments[2], 0.0f)},
                          glm::uvec4(mesh.triangles, mesh.samples, samples.first_sample(m), 0u)});
  }
  plant_count_ = instances.size();
  group_count_ = (plant_count_ + plants_per_group - 1) / plants_per_group;
  // Room for as many points as every plant's whole list, or as a splat's buffers address (one
  // uvec2 per point where the frame's splat puts it).
  point_capacity_ = std::min(most_points, gl::max_storage_block_bytes() / sizeof(glm::uvec2));
  gl::store(instances_, instances);
  gl::store(plant_meshes_, plant_meshes);
  gl::store(meshes_, gpu_meshes);
  storage<glm::uvec2>(counts_, plant_count_);
  storage<glm::uvec2>(offsets_, plant_count_);
  storage<glm::uvec2>(group_sums_, group_count_);
  storage<glm::uvec4>(draws_, plant_count_);
  storage<GLuint>(block_draws_, (point_capacity_ + points_per_block - 1) / points_per_block);
  storage<GLuint>(totals_, 2);
}

void GpuSampler::sample(const pointgen::SamplerView& view) {
  if (view.views.size() > max_views) throw RuntimeFailure("the GPU sampler takes at most 6 views at once");
  const pointgen::ViewFrusta frusta(view.views);
  std::vector<glm::vec4> planes;
  for (const std::array<glm::vec4, 6>& p : frusta.planes()) planes.insert(planes.end(), p.begin(), p.end());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, draws_binding, draws_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, instances_binding, instances_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, block_draws_binding, block_draws_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, plant_meshes_binding, plant_meshes_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, meshes_binding, meshes_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, counts_binding, counts_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, offsets_binding, offsets_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, group_sums_binding, group_sums_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, totals_binding, totals_.name());
  const auto plants = static_cast<unsigned>(plant_count_);

  const GLuint count = count_program_.name();
  glProgramUniform4fv(count, glGetUniformLocation(count, "planes"), static_cast<GLsizei>(planes.size()), &planes.front().x);
  gl::set_uniform(count_program_, "view_count", static_cast<unsigned>(view.views.size()));
  gl::set_uniform(count_program_, "eye", view.eye);
  gl::set_uniform(count_program_, "forward", view.forward);
  gl::set_uniform(count_program_, "edge_cos", view.edge_cos);
  gl::set_uniform(count_program_, "pixels_per_radian", view.density.pixels_per_radian);
  gl::set_uniform(count_program_, "k", view.density.k);
  gl::set_uniform(count_program_, "points_per_triangle", view.points_per_triangle);
  gl::set_uniform(count_program_, "plant_count", plants);
  glUseProgram(count);
  glDispatchCompute(static_cast<GLuint>(std::max<std::size_t>(group_count_, 1)), 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  gl::set_uniform(groups_program_, "group_count", static_cast<unsigned>(group_count_));
  gl::set_uniform(groups_program_, "plant_count", plants);
  gl::set_uniform(groups_program_, "point_capacity", static_cast<unsigned>(point_capacity_));
  glUseProgram(groups_program_.name());
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  gl::set_uniform(draws_program_, "plant_count", plants);
  gl::set_uniform(draws_program_, "block_capacity", static_cast<unsigned>((point_capacity_ + points_per_block - 1) / points_per_block));
  glUseProgram(draws_program_.name());
  glDispatchCompute(static_cast<GLuint>(std::max<std::size_t>((plant_count_ + threads_per_group - 1) / threads_per_group, 1)), 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

std::vector<glm::uvec2> GpuSampler::read_counts() const {
  std::vector<glm::uvec2> counts(plant_count_);
  if (!counts.empty()) glGetNamedBufferSubData(counts_.name(), 0, static_cast<GLsizeiptr>(counts.size() * sizeof(glm::uvec2)), counts.data());
  return counts;
}

std::vector<glm::uvec4> GpuSampler::read_draws() const {
  glm::uvec2 totals(0u);
  glGetNamedBufferSubData(totals_.name(), 0, sizeof totals, &totals);
  std::vector<glm::uvec4> draws(totals.y);
  if (!draws.empty()) glGetNamedBufferSubData(draws_.name(), 0, static_cast<GLsizeiptr>(draws.size() * sizeof(glm::uvec4)), draws.data());
  return draws;
}

}  // namespace ecoview
