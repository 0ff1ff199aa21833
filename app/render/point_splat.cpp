#include "app/render/point_splat.hpp"

#include "app/errors.hpp"
#include "app/gl/shader_program.hpp"
#include "app/render/buffer_texture_units.hpp"
#include "app/render/plant_pose.hpp"

#include <algorithm>

namespace ecoview {
namespace {


constexpr GLuint draw_points_binding = 1, draw_samples_binding = 10, depths_binding = 6, winners_binding = 7, block_draws_binding = 8,
                 projected_binding = 9, totals_binding = 15, dispatch_binding = 16, points_drawn_binding = 30,
                 map_caps_binding = 35, coverage_binding = 36, centre_depths_binding = 37, centre_winners_binding = 38;
constexpr int coverage_margin = 8;  // point_common.glsl
constexpr std::uint64_t points_per_thread = 16;  // point_threads.glsl
constexpr std::uint64_t points_per_block = 16;   // point_common.glsl
// Point indices are 32-bit in the shaders: the last one marks "no point", and a thread's run of
// points must end below it (point_threads.glsl).
constexpr std::uint64_t max_points = 0xFFFFFFFFu - points_per_thread;

// Makes room for `count` elements of T, with new storage (its content lost) when it is too small,
// and no more than the shaders can address. Whether it made new storage.
template <class T>
bool reserve(gl::Buffer& buffer, std::size_t& capacity, std::size_t count) {
  if (count <= capacity) return false;
  const std::size_t limit = gl::max_storage_block_bytes() / sizeof(T);
  if (count > limit) {
    throw RuntimeFailure("a frame's points need " + std::to_string((count * sizeof(T)) >> 20) + " MiB in one buffer, more than "
                         "this driver's shaders address (" + std::to_string((limit * sizeof(T)) >> 20) + " MiB); lower --k or the frame size");
  }
  buffer = gl::Buffer();
  capacity = std::min(std::max<std::size_t>(count * 3 / 2, 64), limit);
  glNamedBufferStorage(buffer.name(), static_cast<GLsizeiptr>(capacity * sizeof(T)), nullptr, GL_DYNAMIC_STORAGE_BIT);
  return true;
}

// Replaces a buffer's content, growing its storage when it is too small; whether it made new storage.
template <class T>
bool fill(gl::Buffer& buffer, std::size_t& capacity, const std::vector<T>& data) {
  const bool grown = reserve<T>(buffer, capacity, data.size());
  if (!data.empty()) glNamedBufferSubData(buffer.name(), 0, static_cast<GLsizeiptr>(data.size() * sizeof(T)), data.data());
  return grown;
}

// Before the buffers are overwritten. GL orders that after earlier passes that read them, but on
// llvmpipe a clear sometimes overtook the reads of the pass before (a cascade's map reusing the
// buffers of the one before it: 1 capture in 8 to 16 gave other bytes; none in 32 with this
// barrier, nor in 80 with a barrier or glFinish before each cascade).
void overwrite_barrier() { glMemoryBarrier(GL_ALL_BARRIER_BITS); }

constexpr GLuint far_depth_bits = 0x3F800000u;  // 1.0f: a depth buffer's far plane

void clear(const gl::Buffer& buffer, GLuint value) {
  glClearNamedBufferData(buffer.name(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &value);
}

}  // namespace

PointSplat::PointSplat(glm::ivec2 size)
    : size_(size),
      dispatch_program_(gl::build_program({"point_dispatch.comp"})),
      depth_program_(gl::build_program({"point_depth.comp"})),
      keeping_depth_program_(gl::build_program({"point_depth.comp"}, "#define KEEP_PROJECTION\n")),
      capped_depth_program_(gl::build_program({"point_depth.comp"}, "#define MAP_CAP\n")),
      resolve_program_(gl::build_program({"point_resolve.comp"})),
      merge_program_(gl::build_program({"fullscreen.vert", "map_depth_merge.frag"})) {
  glNamedFramebufferDrawBuffer(map_layer_.name(), GL_NONE);
  const auto pixels = static_cast<GLsizeiptr>(size.x) * size.y * static_cast<GLsizeiptr>(sizeof(GLuint));
  glNamedBufferStorage(depths_.name(), pixels, nullptr, GL_DYNAMIC_STORAGE_BIT);
  glNamedBufferStorage(winners_.name(), pixels, nullptr, GL_DYNAMIC_STORAGE_BIT);
  glNamedBufferStorage(centre_depths_.name(), pixels, nullptr, GL_DYNAMIC_STORAGE_BIT);
  glNamedBufferStorage(centre_winners_.name(), pixels, nullptr, GL_DYNAMIC_STORAGE_BIT);
  const auto entries = static_cast<GLsizeiptr>(size.x + coverage_margin) * (size.y + coverage_margin);
  glNamedBufferStorage(coverage_.name(), entries * static_cast<GLsizeiptr>(sizeof(GLuint)), nullptr, GL_DYNAMIC_STORAGE_BIT);
  glNamedBufferStorage(totals_.name(), 4 * sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT);
  glNamedBufferStorage(dispatch_.name(), 3 * sizeof(GLuint), nullptr, 0);
  glNamedBufferStorage(points_drawn_onto_.name(), sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT);
  clear(points_drawn_onto_, 0u);
}

void PointSplat::upload(const std::vector<pointgen::PointDraw>& draws, const pointgen::TableList& tables,
                        const PointSamples& samples) {
  std::vector<glm::uvec2> draw_points, draw_samples;
  std::vector<PlantPose> instances;
  draw_points.reserve(draws.size());
  draw_samples.reserve(draws.size());
  instances.reserve(draws.size());
  std::vector<std::uint32_t> block_draws;  // per block of points, the draw holding its first point
  std::uint64_t first_point = 0;
  for (const pointgen::PointDraw& d : draws) {
    const pointgen::InstanceTable& table = tables[d.table];
    if (first_point + d.count > max_points) {
      throw RuntimeFailure("a frame needs more than " + std::to_string(max_points) + " points; lower --k or the frame size");
    }
    const auto draw = static_cast<std::uint32_t>(draw_points.size());
    draw_points.emplace_back(static_cast<std::uint32_t>(first_point), d.count);
    draw_samples.emplace_back(samples.first_sample(table.mesh) + d.first, static_cast<std::uint32_t>(instances.size()));
    instances.push_back(plant_pose(table, d.instance));
    first_point += d.count;
    while (block_draws.size() * points_per_block < first_point) block_draws.push_back(draw);
  }
  fill(draw_points_, draw_points_capacity_, draw_points);
  fill(draw_samples_, draw_samples_capacity_, draw_samples);
  if (fill(instances_, instances_capacity_, instances)) instance_texels_ = gl::buffer_texels(instances_);
  fill(block_draws_, block_draws_capacity_, block_draws);
  const GLuint totals[4] = {static_cast<GLuint>(first_point), static_cast<GLuint>(draws.size()), 0, static_cast<GLuint>(first_point)};
  glNamedBufferSubData(totals_.name(), 0, sizeof totals, totals);
  use({draw_points_.name(), draw_samples_.name(), instance_texels_.name(), block_draws_.name(), totals_.name(), static_cast<std::size_t>(first_point)}, samples);
}

void PointSplat::use(const PointDrawList& list, const PointSamples& samples) {
  list_ = list;
  samples_ = &samples;
  clear(points_drawn_onto_, 0u);
}

std::size_t PointSplat::points_drawn_onto() const {
  GLuint points = 0;
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(points_drawn_onto_.name(), 0, sizeof points, &points);
  return points;
}

void PointSplat::bind_for(const gl::Program& program) const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, draw_points_binding, list_.draw_points);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, draw_samples_binding, list_.draw_samples);
  glBindTextureUnit(instance_texels_unit, list_.instance_texels);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, block_draws_binding, list_.block_draws);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, totals_binding, list_.totals);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, depths_binding, depths_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, winners_binding, winners_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, coverage_binding, coverage_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, centre_depths_binding, centre_depths_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, centre_winners_binding, centre_winners_.name());
  if (projected_capacity_ > 0) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, projected_binding, projected_.name());
  if (samples_ != nullptr) samples_->bind();
  gl::set_uniform(program, "target_size", size_);
  gl::set_uniform(program, "splat_size", frame_splat_size_);
}

void PointSplat::count_groups(Points points) const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, totals_binding, list_.totals);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, dispatch_binding, dispatch_.name());
  gl::set_uniform(dispatch_program_, "band_only", points == Points::last_band ? 1 : 0);
  gl::set_uniform(dispatch_program_, "map_points", points == Points::all ? 1 : 0);
  glUseProgram(dispatch_program_.name());
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT);
}

void PointSplat::dispatch(const gl::Program& program, const glm::mat4& view_projection, int splat_size,
                          float depth_bias, glm::vec2 paraboloid, Points points) const {
  count_groups(points);
  bind_for(program);
  gl::set_uniform(program, "band_only", points == Points::last_band ? 1 : 0);
  gl::set_uniform(program, "map_points", points == Points::all ? 1 : 0);
  gl::set_uniform(program, "view_projection", view_projection);
  gl::set_uniform(program, "paraboloid", paraboloid);
  gl::set_uniform(program, "splat_size", splat_size);
  gl::set_uniform(program, "depth_bias", depth_bias);
  glUseProgram(program.name());
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, dispatch_.name());
  glDispatchComputeIndirect(0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

void PointSplat::splat(const glm::mat4& view_projection, int splat_size, float depth_bias) {
  begin();
  add(view_projection, splat_size, depth_bias, false, {});
  resolve(view_projection, splat_size, depth_bias);
}

void PointSplat::begin() {
  overwrite_barrier();
  clear(depths_, 0xFFFFFFFFu);
  clear(winners_, 0xFFFFFFFFu);
  clear(coverage_, 0u);
  clear(centre_depths_, 0xFFFFFFFFu);
  clear(centre_winners_, 0xFFFFFFFFu);
  // Only the frame's splat keeps where points went; pass 1 writes every point's entry.
  if (list_.most_points > 0) reserve<glm::uvec2>(projected_, projected_capacity_, list_.most_points);
}

void PointSplat::add(const glm::mat4& view_projection, int splat_size, float depth_bias, bool band_only, const CoverageView& seen) {
  if (list_.most_points == 0) return;
  frame_splat_size_ = splat_size;
  gl::set_uniform(keeping_depth_program_, "eye", seen.eye);
  gl::set_uniform(keeping_depth_program_, "forward", seen.forward);
  gl::set_uniform(keeping_depth_program_, "pixels_per_radian", seen.pixels_per_radian);
  gl::set_uniform(keeping_depth_program_, "polygons_drawn", seen.polygon_depth != 0 ? 1 : 0);
  if (seen.polygon_depth != 0) glBindTextureUnit(5, seen.polygon_depth);
  dispatch(keeping_depth_program_, view_projection, splat_size, depth_bias, glm::vec2(0.0f),
           band_only ? Points::last_band : Points::frame);
}

void PointSplat::resolve(const glm::mat4& view_projection, int splat_size, float depth_bias) {
  if (list_.most_points == 0) return;
  dispatch(resolve_program_, view_projection, splat_size, depth_bias, glm::vec2(0.0f), Points::frame);
}

void PointSplat::splat_onto(GLuint depth_texture, int layer, const glm::mat4& view_projection, int splat_size,
                            float depth_bias, glm::vec2 paraboloid) {
  if (list_.most_points == 0) return;
  const bool capped = list_.map_caps != 0;
  if (capped) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, map_caps_binding, list_.map_caps);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, points_drawn_binding, points_drawn_onto_.name());
  }
  // The points' nearest depths start at the far plane, and the draw back keeps the nearer of them
  // and the layer's: no copy of the layer (a pixel pack took 0.6 ms of an H200's frame).
  overwrite_barrier();
  clear(depths_, far_depth_bits);
  dispatch(capped ? capped_depth_program_ : depth_program_, view_projection, splat_size, depth_bias, paraboloid, Points::all);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  glNamedFramebufferTextureLayer(map_layer_.name(), GL_DEPTH_ATTACHMENT, depth_texture, 0, layer);
  glBindFramebuffer(GL_FRAMEBUFFER, map_layer_.name());
  glViewport(0, 0, size_.x, size_.y);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glUseProgram(merge_program_.name());
  gl::set_uniform(merge_program_, "width", size_.x);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, depths_binding, depths_.name());
  glBindVertexArray(no_vertices_.name());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

Image<std::uint32_t> PointSplat::count_points_on(const Image<float>& surface_depth, const glm::mat4& view_projection,
                                                const glm::mat4& projection, float surface_gap) {
  if (!count_program_) count_program_ = std::make_unique<gl::Program>(gl::build_program({"point_count.comp"}));
  gl::set_uniform(*count_program_, "ndc_to_depth", glm::vec2(projection[2][2], projection[3][2]));
  gl::set_uniform(*count_program_, "surface_gap", surface_gap);
  // Flipping the rows again puts them bottom up, as GL counts pixels.
  const Image<float> rows_up = from_bottom_up(size_.x, size_.y, 1, surface_depth.samples);
  glNamedBufferSubData(depths_.name(), 0, static_cast<GLsizeiptr>(rows_up.samples.size() * sizeof(float)), rows_up.samples.data());
  clear(winners_, 0u);
  if (list_.most_points > 0) {
    dispatch(*count_program_, view_projection, 1, 0.0f, glm::vec2(0.0f), Points::frame);
  }
  std::vector<std::uint32_t> bottom_up(static_cast<std::size_t>(size_.x) * static_cast<std::size_t>(size_.y));
  glGetNamedBufferSubData(winners_.name(), 0, static_cast<GLsizeiptr>(bottom_up.size() * sizeof(std::uint32_t)), bottom_up.data());
  return from_bottom_up(size_.x, size_.y, 1, bottom_up);
}

}  // namespace ecoview
