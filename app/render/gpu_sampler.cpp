#include "app/render/gpu_sampler.hpp"

#include "app/errors.hpp"
#include "app/gl/shader_program.hpp"
#include "app/render/buffer_texture_units.hpp"
#include "app/render/plant_pose.hpp"
#include "pointgen/random.hpp"
#include "pointgen/sampling/frustum_culling.hpp"

#include <algorithm>
#include <cmath>

namespace ecoview {
namespace {

// As shaders/sample_common.glsl and sample_draws.comp read them.
struct GpuMesh {
  glm::vec4 center_radius;
  glm::vec4 half_size_area;
  glm::vec4 moments[3];
  glm::uvec4 sizes;
  glm::uvec4 polygon_parts;
};
struct GpuPolygonPart {
  glm::vec4 center;
  glm::vec4 half_size;
  glm::uvec4 indices;
};
struct GpuTotals {
  GLuint total_points, draw_count, band_first_point, frame_points, all_points, polygon_count, part_plants_used;
};
constexpr std::size_t command_uints = GpuScene::command_bytes / sizeof(GLuint);

constexpr GLuint draw_points_binding = 1, draw_samples_binding = 10, block_draws_binding = 8, counts_binding = 12,
                 offsets_binding = 13, group_sums_binding = 14, totals_binding = 15,
                 polygon_instances_binding = 16, tables_binding = 18, commands_binding = 19, band_list_binding = 20,
                 band_ranges_binding = 21, band_keys_binding = 22, group_bands_binding = 23, band_dispatch_binding = 24,
                 polygon_parts_binding = 25, band_ends_binding = 34, map_caps_binding = 35;
constexpr std::size_t plants_per_group = 1024, threads_per_group = 256;  // shaders/sample_count.comp
constexpr GLuint no_plant = 0xFFFFFFFFu;  // a pool's empty place: its mesh (shaders/sample_common.glsl)
constexpr std::size_t points_per_block = 16;                              // shaders/point_common.glsl
constexpr std::size_t max_planes = 96;                                    // planes[96]

// Bands: the first ends this far from the eye (metres), each next one this many times as far.
// Finer bands hide more of what lies behind a near one, at a pyramid and a few passes each.
constexpr float first_band_end = 12.0f, band_ratio = 1.5f;
// A band of the ladder whose plants in view weigh more than this (a plant drawn as polygons weighs
// one per 128 of its triangles) is cut at its quarters, each cut in the place of a ladder band with
// no plants in view (shaders/band_ends.comp).
constexpr unsigned dense_band_plants = 2048;
constexpr int most_distance_bands = 24;
// The plants the frame hides go into the shadow maps from the bands within this distance (the
// ladder's first four, or the bands cut from them). On the ecosystem's default view with PSM 2048² those beyond change `err` by 0.01
// points; on a dense stand of 10^5 plants they added 0.8 M map triangles (docs/benchmarks.md).
constexpr float hidden_casters_reach = 41.0f;

// The same threshold pointgen::sample_view rounds a whole plant's count at.
float rounding(const pointgen::InstanceTable& table, std::size_t i) {
  if (table.rounds_up) return pointgen::InstanceTable::round_up_threshold;
  return pointgen::Random(table.seeds.size() > i ? table.seeds[i] : i).uniform();
}

// Plants cross to the GL buffers this many at a time: a host copy of 10^7 poses would take 640
// MB and, on llvmpipe, seconds of page faults besides the buffer's own.
constexpr std::size_t plants_per_upload = 1 << 16;

// Writes `count` entries from `first` on, `entry(i)` giving entry i, in chunks.
template <class T, class Entry>
void upload(const gl::Buffer& buffer, std::size_t first, std::size_t count, Entry entry) {
  std::vector<T> chunk;
  chunk.reserve(std::min(count, plants_per_upload));
  for (std::size_t start = 0; start < count; start += plants_per_upload) {
    chunk.clear();
    for (std::size_t i = start; i < std::min(count, start + plants_per_upload); ++i) chunk.push_back(entry(i));
    glNamedBufferSubData(buffer.name(), static_cast<GLintptr>((first + start) * sizeof(T)),
                         static_cast<GLsizeiptr>(chunk.size() * sizeof(T)), chunk.data());
  }
}

template <class T>
void storage(gl::Buffer& buffer, std::size_t count, GLbitfield flags = 0) {
  glNamedBufferStorage(buffer.name(), static_cast<GLsizeiptr>(std::max<std::size_t>(count, 1) * sizeof(T)), nullptr, flags);
}

GLuint groups_for(std::size_t threads, std::size_t per_group) {
  return static_cast<GLuint>(std::max<std::size_t>((threads + per_group - 1) / per_group, 1));
}

// Runs a pass over `groups` work groups; the passes after it see what it wrote.
void run_pass(const gl::Program& program, GLuint groups) {
  glUseProgram(program.name());
  glDispatchCompute(groups, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

}  // namespace

std::vector<glm::vec2> GpuSampler::bands(float far) {
  std::vector<glm::vec2> bands;
  for (float near = 0.0f, end = first_band_end; static_cast<int>(bands.size()) + 1 < most_distance_bands; near = end, end *= band_ratio) {
    if (near >= far) break;
    bands.emplace_back(near, end);
  }
  bands.emplace_back(bands.empty() ? 0.0f : bands.back().y, INFINITY);
  return bands;
}

GpuSampler::GpuSampler(const pointgen::TableList& tables, const PointSamples& samples,
                       const std::vector<GpuScene::DrawPlace>& places, const std::vector<Pool>& pools)
    : histogram_program_(gl::build_program({"sample_bins.comp"}, "#define HISTOGRAM\n")),
      band_ends_program_(gl::build_program({"band_ends.comp"})),
      keys_program_(gl::build_program({"sample_bins.comp"}, "#define KEYS\n")),
      hidden_keys_program_(gl::build_program({"sample_bins.comp"}, "#define HIDDEN_KEYS\n")),
      bin_count_program_(gl::build_program({"sample_bins.comp"}, "#define COUNT\n")),
      bands_program_(gl::build_program({"sample_bands.comp"})),
      place_program_(gl::build_program({"sample_bins.comp"})),
      count_program_(gl::build_program({"sample_count.comp"})),
      groups_program_(gl::build_program({"sample_groups.comp"})),
      draws_program_(gl::build_program({"sample_draws.comp"})),
      commands_program_(gl::build_program({"sample_commands.comp"})),
      map_caps_program_(gl::build_program({"map_caps.comp"})) {
  pools_ = pools;
  const std::vector<pointgen::SampledMesh>& meshes = samples.meshes();
  std::vector<glm::uvec4> table_ranges;  // per table of plants: first plant, end, then (sample_commands.comp)
  std::size_t most_points = 0;  // the draw list's points if every plant took its whole list
  range_of_.resize(tables.size());
  for (std::size_t t = 0; t < tables.size(); ++t) {
    const pointgen::InstanceTable& table = tables[t];
    const Pool* pool = pool_of(t);
    if (pool && t == pool->first) {  // the pool's room, empty until refilled
      pool_rooms_.push_back(static_cast<std::uint32_t>(plant_count_));
      plant_count_ += pool->capacity;
      std::size_t most_samples = 0;
      for (std::size_t p = pool->first; p < pool->end; ++p) most_samples = std::max(most_samples, meshes[tables[p].mesh].samples);
      most_points += pool->capacity * most_samples;
    }
    const pointgen::SampledMesh& mesh = meshes[table.mesh];
    first_plant_.push_back(static_cast<std::uint32_t>(pool ? pool_rooms_.back() : plant_count_));
    holds_plants_.push_back(mesh.samples > 0 && (table.size() > 0 || pool));
    if (!holds_plants_.back()) continue;
    range_of_[t] = table_count_++;
    const std::size_t size = pool ? 0 : table.size();
    table_ranges.emplace_back(first_plant_.back(), static_cast<std::uint32_t>(first_plant_.back() + size), 0u, 0u);
    table_ranges.emplace_back(static_cast<std::uint32_t>(3 * mesh.triangles), places[table.mesh].first_index,
                              static_cast<std::uint32_t>(places[table.mesh].base_vertex), 0u);
    if (pool) continue;
    plant_count_ += table.size();
    most_points += table.size() * mesh.samples;
  }
  std::vector<GpuMesh> gpu_meshes;
  std::vector<GpuPolygonPart> polygon_parts;
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const pointgen::SampledMesh& mesh = meshes[m];
    gpu_meshes.push_back({glm::vec4(mesh.center, mesh.radius), glm::vec4(mesh.half_size, mesh.area),
                          {glm::vec4(mesh.normal_moments[0], 0.0f), glm::vec4(mesh.normal_moments[1], 0.0f),
                           glm::vec4(mesh.normal_moments[2], 0.0f)},
                          glm::uvec4(mesh.triangles, mesh.samples, samples.first_sample(m), 0u),
                          glm::uvec4(polygon_parts.size(), mesh.polygon_parts.size(), 0u, 0u)});
    for (const pointgen::PolygonPart& part : mesh.polygon_parts) {
      polygon_parts.push_back({glm::vec4(part.center, 0.0f), glm::vec4(part.half_size, 0.0f), glm::uvec4(part.first_index, part.index_count, 0u, 0u)});
    }
  }
  group_count_ = (plant_count_ + plants_per_group - 1) / plants_per_group;
  // Room for as many points as every plant's whole list, or as a splat's buffers address (one
  // uvec2 per point where the frame's splat puts it).
  point_capacity_ = std::min(most_points, gl::max_storage_block_bytes() / sizeof(glm::uvec2));
  // A plant's pose is four texels (shaders/plant_instances.glsl); its largest entries in shader
  // storage a uvec2 (offsets_, draw_points_, draw_samples_, two places in band_list_).
  const std::size_t pose_texels = plant_count_ * sizeof(PlantPose) / sizeof(glm::vec4);
  if (plant_count_ * sizeof(glm::uvec2) > gl::max_storage_block_bytes() || pose_texels > gl::max_texel_buffer_texels()) {
    throw RuntimeFailure("the scene's " + std::to_string(plant_count_) + " plants need more than this driver's shaders address (" +
                         std::to_string(gl::max_storage_block_bytes() >> 20) + " MiB a buffer, " +
                         std::to_string(gl::max_texel_buffer_texels()) + " texels a buffer texture); use fewer plants");
  }
  storage<PlantPose>(instances_, plant_count_, GL_DYNAMIC_STORAGE_BIT);  // moving plants are posed each frame
  storage<glm::uvec2>(plant_meshes_, plant_count_, GL_DYNAMIC_STORAGE_BIT);
  for (std::size_t t = 0; t < tables.size(); ++t) {
    if (holds_plants_[t] && !pool_of(t)) place(t, tables[t]);
  }
  for (std::size_t p = 0; p < pools_.size(); ++p) {
    upload<glm::uvec2>(plant_meshes_, pool_rooms_[p], pools_[p].capacity, [](std::size_t) { return glm::uvec2(no_plant, 0u); });
  }
  instance_texels_ = gl::buffer_texels(instances_);
  plant_mesh_texels_ = gl::buffer_texels(plant_meshes_, GL_RG32UI);
  gl::store(meshes_, gpu_meshes);
  mesh_texels_ = gl::buffer_texels(meshes_, GL_RGBA32UI);
  gl::store(polygon_parts_, polygon_parts);
  gl::store(tables_, table_ranges, pools_.empty() ? 0 : GL_DYNAMIC_STORAGE_BIT);
  storage<GLuint>(counts_, plant_count_);
  storage<glm::uvec2>(offsets_, plant_count_);
  storage<glm::uvec4>(group_sums_, group_count_);
  storage<glm::uvec2>(draw_points_, plant_count_);
  storage<glm::uvec2>(draw_samples_, plant_count_);
  storage<GLuint>(map_caps_, plant_count_);
  storage<GLuint>(block_draws_, (point_capacity_ + points_per_block - 1) / points_per_block);
  gl::store(totals_, std::vector<GpuTotals>(1, GpuTotals{}));  // stays so in a scene without plants
  storage<GLuint>(polygon_instances_, plant_count_);
  storage<GLuint>(commands_, command_uints * max_bands * std::max<std::size_t>(table_count_, 1));
  storage<GLuint>(band_keys_, plant_count_);
  storage<GLuint>(group_bands_, group_count_ * max_bands);
  storage<GLuint>(band_list_, 2 * plant_count_);  // the frame's bands, then the band of those hidden in it
  storage<glm::uvec2>(band_ranges_, max_bands);
  gl::store(band_ends_, std::vector<GLuint>(max_bands + 4 * static_cast<std::size_t>(most_distance_bands), 0u));  // ends, quarters' counts
  storage<glm::uvec4>(band_dispatch_, 4 * max_bands);  // shaders/sample_bands.comp
  part_lists_ = std::make_unique<PolygonPartLists>(plant_count_, table_count_, max_bands);
  every_band_drawn_ = std::make_unique<DrawnCommands>(1, max_bands * table_count_);
}

const GpuSampler::Pool* GpuSampler::pool_of(std::size_t table) const {
  const auto pool = std::find_if(pools_.begin(), pools_.end(), [&](const Pool& p) { return table >= p.first && table < p.end; });
  return pool != pools_.end() ? &*pool : nullptr;
}

void GpuSampler::place(std::size_t t, const pointgen::InstanceTable& table) {
  upload<PlantPose>(instances_, first_plant_[t], table.size(), [&](std::size_t i) { return plant_pose(table, i); });
  upload<glm::uvec2>(plant_meshes_, first_plant_[t], table.size(), [&](std::size_t i) {
    return glm::uvec2(static_cast<std::uint32_t>(table.mesh), glm::floatBitsToUint(rounding(table, i)));
  });
}

void GpuSampler::refill(std::size_t pool, const pointgen::TableList& tables) {
  const Pool& p = pools_[pool];
  std::uint32_t at = pool_rooms_[pool];
  const std::uint32_t end = at + static_cast<std::uint32_t>(p.capacity);
  for (std::size_t t = p.first; t < p.end; ++t) {
    if (!holds_plants_[t]) continue;
    if (tables[t].size() > end - at) throw RuntimeFailure("a landscape's plants outgrew their pool");
    first_plant_[t] = at;
    place(t, tables[t]);
    const glm::uvec4 range(at, at + static_cast<std::uint32_t>(tables[t].size()), 0u, 0u);
    glNamedBufferSubData(tables_.name(), static_cast<GLintptr>(2 * range_of_[t] * sizeof(glm::uvec4)), sizeof range, &range);
    at = range.y;
  }
  upload<glm::uvec2>(plant_meshes_, at, end - at, [](std::size_t) { return glm::uvec2(no_plant, 0u); });
}

void GpuSampler::update(std::size_t table, const pointgen::InstanceTable& posed) {
  if (!holds_plants_[table]) return;
  const std::size_t end = table + 1 < first_plant_.size() ? first_plant_[table + 1] : plant_count_;
  if (posed.size() != end - first_plant_[table]) throw RuntimeFailure("a posed table changed its number of instances");
  upload<PlantPose>(instances_, first_plant_[table], posed.size(), [&](std::size_t i) { return plant_pose(posed, i); });
}

void GpuSampler::bind() const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, draw_points_binding, draw_points_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, draw_samples_binding, draw_samples_.name());
  glBindTextureUnit(instance_texels_unit, instance_texels_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, block_draws_binding, block_draws_.name());
  glBindTextureUnit(plant_mesh_texels_unit, plant_mesh_texels_.name());
  glBindTextureUnit(mesh_texels_unit, mesh_texels_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, counts_binding, counts_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, offsets_binding, offsets_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, group_sums_binding, group_sums_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, totals_binding, totals_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, polygon_instances_binding, polygon_instances_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, tables_binding, tables_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, commands_binding, commands_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, band_list_binding, band_list_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, band_ranges_binding, band_ranges_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, band_keys_binding, band_keys_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, group_bands_binding, group_bands_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, band_dispatch_binding, band_dispatch_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, band_ends_binding, band_ends_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, polygon_parts_binding, polygon_parts_.name());
  part_lists_->bind();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, map_caps_binding, map_caps_.name());
}

void GpuSampler::begin(const pointgen::SamplerView& view, const std::vector<glm::vec2>& bands,
                       const std::vector<shadow::Plane>& casters) {
  if (6 * view.views.size() + casters.size() > max_planes) throw RuntimeFailure("the GPU sampler takes at most 96 planes at once");
  if (bands.empty() || static_cast<int>(bands.size()) > most_distance_bands) throw RuntimeFailure("the GPU sampler takes 1 to 24 bands a frame");
  distance_bands_ = static_cast<int>(bands.size());
  bands_used_ = distance_bands_ + (casters.empty() ? 0 : 2);
  casters_band_ = casters.empty() ? std::nullopt : std::optional<int>(distance_bands_);
  hidden_band_ = casters.empty() ? std::nullopt : std::optional<int>(distance_bands_ + 1);
  // The lists are reset by the sort's passes, not by buffer clears: on llvmpipe a clear of the
  // counts at times landed after the count pass that followed it (counts of the first plants lost,
  // differently from run to run).
  if (plant_count_ == 0) return;

  std::vector<glm::vec4> planes;
  const pointgen::ViewFrusta frusta(view.views);
  for (const std::array<glm::vec4, 6>& p : frusta.planes()) planes.insert(planes.end(), p.begin(), p.end());
  for (const shadow::Plane& p : casters) planes.emplace_back(-p.normal, p.offset);  // inside where dot >= 0
  std::vector<float> ladder_ends;
  for (const glm::vec2& band : bands) ladder_ends.push_back(band.y);
  for (const gl::Program* program : {&histogram_program_, &keys_program_}) {
    const GLuint p = program->name();
    glProgramUniform4fv(p, glGetUniformLocation(p, "planes"), static_cast<GLsizei>(planes.size()), &planes.front().x);
    gl::set_uniform(*program, "view_count", static_cast<unsigned>(view.views.size()));
    gl::set_uniform(*program, "caster_plane_count", static_cast<unsigned>(casters.size()));
    gl::set_uniform(*program, "eye", view.eye);
  }
  for (const gl::Program* program : {&histogram_program_, &band_ends_program_}) {
    const GLuint p = program->name();
    glProgramUniform1fv(p, glGetUniformLocation(p, "ladder_ends"), static_cast<GLsizei>(ladder_ends.size()), ladder_ends.data());
    gl::set_uniform(*program, "ladder_count", static_cast<unsigned>(ladder_ends.size()));
  }
  gl::set_uniform(band_ends_program_, "dense_plants", dense_band_plants);
  for (const gl::Program* program : {&count_program_, &histogram_program_}) {
    gl::set_uniform(*program, "forward", view.forward);
    gl::set_uniform(*program, "edge_cos", view.edge_cos);
    gl::set_uniform(*program, "pixels_per_radian", view.density.pixels_per_radian);
    gl::set_uniform(*program, "k", view.density.k);
    gl::set_uniform(*program, "points_per_triangle", view.points_per_triangle);
  }
  gl::set_uniform(count_program_, "view_projection", view.views.front());
  part_lists_->begin(view.views.front(), glm::vec2(view.pixels));
  gl::set_uniform(count_program_, "eye", view.eye);
  gl::set_uniform(hidden_keys_program_, "hidden_reach", hidden_casters_reach);
  gl::set_uniform(hidden_keys_program_, "k", view.density.k);
  gl::set_uniform(hidden_keys_program_, "points_per_triangle", view.points_per_triangle);
  cut_dense_bands();
  sort(keys_program_, distance_bands_ + (casters.empty() ? 0 : 1), 0);
}

// The frame's distance bands from the ladder, on the GPU (shaders/band_ends.comp).
void GpuSampler::cut_dense_bands() {
  bind();
  gl::set_uniform(histogram_program_, "plant_count", static_cast<unsigned>(plant_count_));
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  run_pass(histogram_program_, groups_for(plant_count_, threads_per_group));
  run_pass(band_ends_program_, 1);
}

// The stable counting sort of the plants that `keys` gives a band into `band_count` bands from
// number `first_band` on (shaders/sample_bins.comp): from the start of the band list for the
// frame's bands, after them for the hidden plants' band.
void GpuSampler::sort(const gl::Program& keys, int band_count, int first_band) {
  bind();
  const auto bands = static_cast<unsigned>(band_count);
  for (const gl::Program* program : std::initializer_list<const gl::Program*>{&keys, &bin_count_program_, &bands_program_, &place_program_}) {
    gl::set_uniform(*program, "plant_count", static_cast<unsigned>(plant_count_));
    gl::set_uniform(*program, "group_count", static_cast<unsigned>(group_count_));
    gl::set_uniform(*program, "band_count", bands);
  }
  gl::set_uniform(bands_program_, "list_start", static_cast<unsigned>(first_band == 0 ? 0 : plant_count_));
  gl::set_uniform(bands_program_, "first_band", static_cast<unsigned>(first_band));
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  run_pass(keys, groups_for(plant_count_, threads_per_group));
  run_pass(bin_count_program_, groups_for(group_count_, 64));
  run_pass(bands_program_, 1);
  glUseProgram(place_program_.name());
  glDispatchCompute(groups_for(group_count_, 64), 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

void GpuSampler::add_casters(const glm::mat4& map_view, float texels, const DepthPyramid& receivers, bool to_points) {
  if (!casters_band_) return;
  gl::set_uniform(hidden_keys_program_, "polygons_to_points", to_points ? 1 : 0);
  gl::set_uniform(hidden_keys_program_, "map_view_projection", map_view);
  gl::set_uniform(hidden_keys_program_, "map_texels", texels);
  gl::set_uniform(count_program_, "cap_to_map", 1);
  gl::set_uniform(count_program_, "receivers_only", 1);
  gl::set_uniform(count_program_, "map_view_projection", map_view);
  gl::set_uniform(count_program_, "map_texels", texels);
  receivers.bind_for(count_program_);
  add_band(*casters_band_, nullptr);
  if (plant_count_ > 0) {
    sort(hidden_keys_program_, 1, *hidden_band_);
    add_band(*hidden_band_, nullptr);
  }
  gl::set_uniform(count_program_, "cap_to_map", 0);
  gl::set_uniform(count_program_, "receivers_only", 0);
}

void GpuSampler::add_band(int band, const DepthPyramid* occluders) {
  if (band < 0 || band >= bands_used_) throw RuntimeFailure("the GPU sampler has no band " + std::to_string(band) + " this frame");
  if (plant_count_ == 0) return;
  bind();
  const auto plants = static_cast<unsigned>(plant_count_);
  const auto number = static_cast<unsigned>(band + 1);
  for (const gl::Program* program : {&count_program_, &groups_program_, &draws_program_, &commands_program_}) {
    gl::set_uniform(*program, "plant_count", plants);
    gl::set_uniform(*program, "band_number", number);
  }
  gl::set_uniform(count_program_, "occlusion", occluders ? 1 : 0);
  if (occluders) occluders->bind_for(count_program_);
  const auto dispatch_at = [&](int which) { return static_cast<GLintptr>((4 * band + which) * sizeof(glm::uvec4)); };
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, band_dispatch_.name());
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  glUseProgram(count_program_.name());
  glDispatchComputeIndirect(dispatch_at(0));
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  gl::set_uniform(groups_program_, "point_capacity", static_cast<unsigned>(point_capacity_));
  gl::set_uniform(groups_program_, "in_frame", in_frame(band) ? 1 : 0);
  glUseProgram(groups_program_.name());
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  gl::set_uniform(draws_program_, "block_capacity", static_cast<unsigned>((point_capacity_ + points_per_block - 1) / points_per_block));
  glUseProgram(draws_program_.name());
  glDispatchComputeIndirect(dispatch_at(1));
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);

  gl::set_uniform(commands_program_, "table_count", static_cast<unsigned>(table_count_));
  glUseProgram(commands_program_.name());
  glDispatchCompute(groups_for(table_count_, 64), 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT |
                  GL_BUFFER_UPDATE_BARRIER_BIT);
  if (in_frame(band)) part_lists_->choose(band, occluders, band_dispatch_.name());
}

bool GpuSampler::in_frame(int band) const { return !casters_band_ || band < *casters_band_; }

void GpuSampler::sample(const pointgen::SamplerView& view) {
  begin(view, {glm::vec2(0.0f, INFINITY)});
  add_band(0, nullptr);
}

GpuScene::PlantDraws GpuSampler::polygon_draws(int first, int end) const {
  const std::size_t tables = table_count_;
  const GpuScene::PlantDraws draws{instance_texels_.name(), polygon_instances_.name(), commands_.name(), static_cast<std::size_t>(first) * tables,
                                   static_cast<std::size_t>(std::max(end - first, 0)) * tables};
  if (draws.command_count == 0) return draws;
  every_band_drawn_->keep_drawn(draws.commands, draws.first_command, draws.command_count, 0);
  return every_band_drawn_->from_copy(draws, 0);
}

GpuScene::PlantDraws GpuSampler::frame_polygon_draws(int band) const {
  if (!in_frame(band)) return {};
  return part_lists_->frame_draws(band, instance_texels_.name());
}

GpuScene::PlantDraws GpuSampler::select_casters(int layer, const glm::mat4& map_view, int map_size, const DepthPyramid& receivers) {
  if (plant_count_ == 0 || table_count_ == 0) return {};
  bind();
  return part_lists_->select(layer, map_view, map_size, receivers, instance_texels_.name());
}

void GpuSampler::cap_for_map(const glm::mat4& map_view, float texels, float points_per_texel) {
  if (plant_count_ == 0) return;
  bind();
  gl::set_uniform(map_caps_program_, "map_view_projection", map_view);
  gl::set_uniform(map_caps_program_, "map_texels", texels);
  gl::set_uniform(map_caps_program_, "k", points_per_texel);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  run_pass(map_caps_program_, groups_for(plant_count_, threads_per_group));
}

PointDrawList GpuSampler::draw_list() const {
  return {draw_points_.name(), draw_samples_.name(), instance_texels_.name(), block_draws_.name(), totals_.name(), point_capacity_, map_caps_.name()};
}


std::vector<GpuSampler::Count> GpuSampler::read_counts() const {
  std::vector<GLuint> counts(plant_count_);
  if (!counts.empty()) glGetNamedBufferSubData(counts_.name(), 0, static_cast<GLsizeiptr>(counts.size() * sizeof(GLuint)), counts.data());
  std::vector<Count> out;
  out.reserve(counts.size());
  for (const GLuint c : counts) {  // as shaders/sample_common.glsl packs it
    const GLuint band = (c >> 24) & 63u;
    out.push_back({c & 0xFFFFFFu, (c & (1u << 30)) != 0, band > 0 ? std::optional<int>(static_cast<int>(band) - 1) : std::nullopt});
  }
  return out;
}

std::vector<glm::uvec4> GpuSampler::read_draws() const {
  GpuTotals totals{};
  glGetNamedBufferSubData(totals_.name(), 0, sizeof totals, &totals);
  std::vector<glm::uvec2> points(totals.draw_count), samples(totals.draw_count);
  if (points.empty()) return {};
  glGetNamedBufferSubData(draw_points_.name(), 0, static_cast<GLsizeiptr>(points.size() * sizeof(glm::uvec2)), points.data());
  glGetNamedBufferSubData(draw_samples_.name(), 0, static_cast<GLsizeiptr>(samples.size() * sizeof(glm::uvec2)), samples.data());
  std::vector<glm::uvec4> draws;
  draws.reserve(points.size());
  for (std::size_t d = 0; d < points.size(); ++d) draws.emplace_back(points[d], samples[d]);
  return draws;
}

GpuSampler::Totals GpuSampler::read_totals() const {
  GpuTotals totals{};
  glGetNamedBufferSubData(totals_.name(), 0, sizeof totals, &totals);
  Totals out;
  out.frame_points = totals.frame_points;
  out.points_left_out = totals.all_points - std::min<std::size_t>(totals.all_points, point_capacity_);
  out.triangles = every_band_drawn_->read_triangles().front();
  out.frame_triangles = part_lists_->frame_triangles(casters_band_.value_or(bands_used_));
  out.layer_triangles = part_lists_->layer_triangles();
  out.selections = static_cast<std::size_t>(part_lists_->selections());
  return out;
}

}  // namespace ecoview
