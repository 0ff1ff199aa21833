#include "app/render/renderer.hpp"

#include "app/clock.hpp"
#include "app/errors.hpp"
#include "app/gl/gl_cpu_time.hpp"
#include "app/render/pixel_rays.hpp"
#include "shadow/aliasing.hpp"
#include "shadow/paraboloid_map.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <future>
#include <numeric>
#include <optional>

namespace ecoview {
namespace {

// The nearest visible depth of a frame is taken with this margin, for surfaces that come nearer
// by the next frame.
constexpr float nearest_visible_margin = 0.8f;

// Texels per side of the GPU sampler's receiver mask over a shadow view: casters are kept where
// their boxes cover a receiver's texel.
constexpr int receiver_mask_size = 256;

// The frusta the sampler culls a shadow view's casters against: a projective view's own, or
// frusta that hold what a paraboloid view maps.
std::vector<glm::mat4> culling_frusta(const shadow::ShadowView& view) {
  if (view.paraboloid) return shadow::enclosing_frusta(view);
  return {view.view_projection()};
}

}  // namespace

pointgen::SamplerView sampler_view(const shadow::Camera& camera, const RenderSettings& settings, std::vector<glm::mat4> views) {
  const float aspect = static_cast<float>(settings.width) / static_cast<float>(settings.height);
  const float tan_half = std::tan(glm::radians(camera.fov_y_deg) / 2.0f);
  pointgen::SamplerView view;
  view.views = std::move(views);
  view.eye = camera.position;
  view.forward = camera.forward();
  view.edge_cos = 1.0f / std::sqrt(1.0f + tan_half * tan_half * (1.0f + aspect * aspect));
  view.density = {0.5f * static_cast<float>(settings.height) / tan_half, settings.k};
  view.points_per_triangle = settings.points_per_triangle;
  view.pixels = glm::ivec2(settings.width, settings.height);
  view.splat_pixels = settings.splat_size;
  return view;
}

std::string driver_refusal(const RenderSettings& s) {
  GLint max_texture = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_texture);
  const auto max_storage_block = static_cast<GLint64>(gl::max_storage_block_bytes());
  auto bytes = [](int w, int h) { return 4 * static_cast<GLint64>(w) * h; };  // one uint per pixel (PointSplat)
  if (std::max(s.width, s.height) > max_texture || (s.points && bytes(s.width, s.height) > max_storage_block)) {
    return "--size: " + std::to_string(s.width) + "x" + std::to_string(s.height) + " is more than this driver "
           "renders (textures up to " + std::to_string(max_texture) + ", point buffers up to " +
           std::to_string(max_storage_block >> 20) + " MiB); use a smaller size";
  }
  if (s.shadow_size > max_texture || (s.points && bytes(s.shadow_size, s.shadow_size) > max_storage_block)) {
    return "--shadow-size: " + std::to_string(s.shadow_size) + " is more than this driver renders (textures up to " +
           std::to_string(max_texture) + ", point buffers up to " + std::to_string(max_storage_block >> 20) +
           " MiB); use a smaller map";
  }
  if (shadow::technique(s.method).lookup == shadow::Lookup::pages && page_pool_layers(s) > PagedMap::most_layers()) {
    return "--page-pool: " + std::to_string(s.page_pool_mib) + " MiB is " + std::to_string(page_pool_layers(s)) +
           " pages, more than this driver holds in one texture (" + std::to_string(PagedMap::most_layers()) + "); use a smaller pool";
  }
  return {};
}

// The settings, checked against what this driver can allocate before anything is.
static RenderSettings within_limits(const RenderSettings& s) {
  if (const std::string refusal = driver_refusal(s); !refusal.empty()) throw InputError(refusal);
  return s;
}

Renderer::Renderer(const Scene& scene, const RenderSettings& settings)
    : scene_(scene),
      settings_(within_limits(settings)),
      scene_bounds_(scene.bounds()),
      tables_(scene.groups),
      gpu_scene_(scene),
      samples_(scene, settings_.points_per_triangle, settings_.points),
      map_(settings, gpu_scene_.has_surface_textures()),
      frame_pass_(settings.width, settings.height, settings.aliasing, gpu_scene_.has_surface_textures()),
      frame_points_({settings.width, settings.height}) {
  make_method_passes();
  // A moving set's groups are its bodies' parts, one mesh each (scene_file.cpp).
  mesh_boxes_.resize(scene.meshes.size());
  for (const Animation& animation : scene.animations) {
    std::size_t parts = 0;
    for (const pointgen::Body& body : animation.set.bodies) parts += body.parts.size();
    for (std::size_t i = 0; i < parts; ++i) {
      moving_groups_.push_back(animation.first_group + i);
      const pointgen::Bounds b = scene.meshes[animation.first_mesh + i].bounds();
      mesh_boxes_[animation.first_mesh + i] = {b.min, b.max};
    }
  }
  if (settings.point_meshes_only) {
    for (std::size_t g = 0; g < tables_.size(); ++g) {
      if (!scene.point_meshes[tables_[g].mesh]) tables_.replace(g, {tables_[g].mesh, {}, {}, {}});
      gpu_scene_.update(g, tables_[g]);
    }
  }
  std::vector<GpuSampler::Pool> pools;
  for (const LandscapeSource& landscape : scene.landscapes) {
    std::vector<std::size_t> meshes;  // per species; its far blocks' table follows them all
    for (std::size_t g = 0; g < landscape.group_count() / 2; ++g) meshes.push_back(scene.groups[landscape.first_group + g].mesh);
    landscape_pools_.emplace_back(landscape.spec, landscape.reach, meshes, landscape.capacity);
    // Drawn by its chunks from the first frame on, as every later ground is.
    grounds_.emplace_back(landscape.spec, landscape.ground);
    ground_chunks_.push_back(grounds_.back().chosen(scene.camera.position));
    const pointgen::GroundChunks::Chunked ground = grounds_.back().mesh(ground_chunks_.back());
    gpu_scene_.replace_mesh(landscape.ground_mesh, ground.mesh, ground.chunks);
    pools.push_back({landscape.first_group, landscape.first_group + landscape.group_count(), landscape.capacity});
  }
  if (settings_.points && settings_.gpu_sampler && settings_.measure == RenderSettings::Measure::off) {
    gpu_sampler_ = std::make_unique<GpuSampler>(tables_, samples_, gpu_scene_.point_mesh_places(), pools);
    occluders_ = std::make_unique<DepthPyramid>(glm::ivec2(settings.width, settings.height));
    receivers_ = std::make_unique<DepthPyramid>(glm::ivec2(receiver_mask_size));
    gpu_scene_.gather_point_meshes();
  }
}

// Made with the renderer, not with the first frame, so that frame times hold no shader compilation.
void Renderer::make_method_passes() {
  map_.use(shadow::technique(settings_.method), settings_.points && scene_.has_point_meshes(), gpu_scene_, scene_);
  const MaskSources sources{scene_, gpu_scene_, frame_pass_, {settings_.width, settings_.height},
                            [this]() -> ExactVisibility& { return exact(); }};
  mask_ = make_mask_technique(settings_.method, sources);
  pages_.reset();
  if (shadow::technique(settings_.method).lookup == shadow::Lookup::pages) {
    pages_ = std::make_unique<PagedMap>(shadow::VirtualMap{}, page_pool_layers(settings_), map_.depths().depth_format(),
                                        shadow::technique(settings_.method).silhouette_map);
  }
}

void Renderer::change(shadow::Method method, int shadow_size, float k) {
  RenderSettings wanted = settings_;
  wanted.method = method;
  wanted.shadow_size = shadow_size;
  wanted.k = k;
  wanted = within_limits(wanted);
  const bool new_map = map_texels(wanted) != map_texels(settings_);
  const bool new_method = wanted.method != settings_.method;
  if (new_map) map_ = MapTechnique(wanted, gpu_scene_.has_surface_textures());
  // What the last frame left (near plane, surface, receivers) depends on the method and k: the next
  // frame starts again from one without shadows, as a fresh renderer's does.
  has_last_frame_ = false;
  settings_ = wanted;
  if (new_map || new_method) make_method_passes();
}

Image<std::uint32_t> Renderer::count_points_on(const Image<float>& surface_depth) {
  const float pixel_width = 2.0f * std::tan(glm::radians(camera_.fov_y_deg) / 2.0f) / static_cast<float>(settings_.height);
  // A point on the same surface, sloped up to 45 degrees, lies within a splat's width in depth.
  return frame_points_.count_points_on(surface_depth, view_projection_, camera_.projection(aspect()),
                                       static_cast<float>(settings_.splat_size) * pixel_width);
}

PointSplat::CoverageView Renderer::coverage_view(const shadow::Camera& camera) const {
  const pointgen::SamplerView seen = sampler_view(camera, settings_, {});
  return {seen.eye, seen.forward, seen.density.pixels_per_radian, frame_pass_.depth_stencil_texture()};
}

float Renderer::aspect() const { return static_cast<float>(settings_.width) / static_cast<float>(settings_.height); }


void Renderer::upload_polygons(const pointgen::SampledFrame& selection) {
  for (std::size_t g = 0; g < tables_.size(); ++g) {
    if (!scene_.point_meshes[tables_[g].mesh]) continue;
    const pointgen::InstanceTable& all = tables_[g];
    pointgen::InstanceTable drawn{all.mesh, {}, {}, {}};
    for (std::uint32_t i : selection.polygons[g]) drawn.add_from(all, i);
    gpu_scene_.update(g, drawn, selection.polygon_parts.empty() ? std::vector<std::uint64_t>{} : selection.polygon_parts[g]);
  }
}

pointgen::SampledFrame Renderer::polygons_in(const std::optional<pointgen::ViewFrusta>& frusta) const {
  pointgen::SampledFrame frame;
  frame.polygons.resize(tables_.size());
  for (std::size_t g = 0; g < tables_.size(); ++g) {
    if (!scene_.point_meshes[tables_[g].mesh]) continue;
    const pointgen::SampledMesh& mesh = samples_.meshes()[tables_[g].mesh];
    std::vector<std::uint32_t>& drawn = frame.polygons[g];
    if (frusta) {
      drawn = pointgen::instances_in_view(*frusta, cells().by_table()[g], tables_[g], mesh);
    } else {
      drawn.resize(tables_[g].size());
      std::iota(drawn.begin(), drawn.end(), 0u);
    }
    frame.triangle_count += drawn.size() * mesh.triangles;
  }
  return frame;
}

pointgen::SampledFrame Renderer::measured(const pointgen::SampledFrame& selection) const {
  pointgen::SampledFrame out;
  out.polygons = selection.polygons;
  if (settings_.measure == RenderSettings::Measure::their_polygons) {
    for (const pointgen::PointDraw& d : selection.points) out.polygons[d.table].push_back(d.instance);
  }
  for (std::size_t g = 0; g < out.polygons.size(); ++g) {
    std::vector<std::uint32_t>& drawn = out.polygons[g];
    std::sort(drawn.begin(), drawn.end());
    drawn.erase(std::unique(drawn.begin(), drawn.end()), drawn.end());  // the band draws some both ways
    out.triangle_count += drawn.size() * scene_.meshes[tables_[g].mesh].triangle_count();
  }
  return out;
}

shadow::ShadowInputs Renderer::shadow_inputs(const shadow::Camera& camera, const shadow::Light& light) const {
  return {camera, aspect(), light, scene_bounds_, settings_.shadow_size, nearest_visible_margin * nearest_visible_};
}

shadow::ShadowSetup Renderer::make_shadow_setup(const shadow::ShadowInputs& inputs) const {
  if (settings_.method == shadow::Method::automatic) return best_predicted_setup(inputs);
  return shadow::technique(settings_.method).setup(inputs);
}

// --method auto: each candidate's median aliasing factor predicted from its matrices on the
// surface the last frame showed; the least wins. The median, not alias_p95: `err` counts pixels,
// and where every method undersamples the typical pixel tells more of it than the worst 5 %
// (docs/benchmarks.md, "What auto chooses by").
shadow::ShadowSetup Renderer::best_predicted_setup(const shadow::ShadowInputs& inputs) const {
  const std::vector<shadow::Method> candidates = shadow::auto_candidates(inputs.light.type);
  std::vector<shadow::ShadowSetup> setups;
  for (shadow::Method method : candidates) setups.push_back(shadow::technique(method).setup(inputs));
  const std::vector<float> predicted = frame_pass_.predict_aliasing(last_camera_, inputs.camera, inputs.light, setups,
                                                                    settings_.shadow_size, shadow::median_fraction);
  const auto best = static_cast<std::size_t>(std::min_element(predicted.begin(), predicted.end()) - predicted.begin());
  char figure[32];
  std::snprintf(figure, sizeof figure, "%.2f", predicted[best]);
  setups[best].description =
      "auto: " + shadow::technique(candidates[best]).name + ", predicted median aliasing " + figure + " (" + setups[best].description + ")";
  return std::move(setups[best]);
}

// The shadow map for this frame; with points on, far instances of point meshes are splatted into
// it. Each view chooses its own points and polygons, so that a view with one frustum keeps the
// sampler's cap and occlusion (cascades, cube faces). Timed from the first GL draw to the last.
FramePass::ShadowLookup Renderer::render_shadow_map(const shadow::Camera& camera, const shadow::Light& light) {
  const std::vector<pointgen::SampledFrame> chosen = choose_map_casters(camera, setup_.views);
  shadow_timer_.start();
  for (std::size_t layer = 0; layer < setup_.views.size(); ++layer) draw_map_view(setup_, static_cast<int>(layer), chosen, light);
  shadow_timer_.stop();
  pending_.shadow_timer = true;
  return map_lookup();
}

std::vector<pointgen::SampledFrame> Renderer::choose_map_casters(const shadow::Camera& camera,
                                                                 const std::vector<shadow::ShadowView>& views) {
  std::vector<pointgen::SampledFrame> chosen;
  if (!settings_.points) return chosen;
  const auto start = std::chrono::steady_clock::now();
  for (const shadow::ShadowView& v : views) {
    pointgen::SamplerView view = sampler_view(camera, settings_, culling_frusta(v));
    view.pixels = glm::ivec2(map_.depths().size());
    view.splat_pixels = settings_.shadow_splat_size;
    view.cap_to_pixels = true;
    // Layer under layer of canopy as the light sees it: counts follow the expected visible share
    // (docs/point_density.md, "Occlusion"; what it costs and saves in docs/benchmarks.md).
    view.full_count_transmittance = 1.0f;
    std::optional<pointgen::ReceiverMask> receivers;
    if (culls_casters() && !v.paraboloid) view.receivers = &receivers.emplace(v.view_projection(), last_receivers_);
    chosen.push_back(pointgen::sample_view(view, tables_, samples_.meshes(), cells()));
    stats_.shadow_points += chosen.back().point_count;
  }
  stats_.sample_ms += ms_since(start);
  return chosen;
}

void Renderer::draw_map_view(const shadow::ShadowSetup& setup, int layer, const std::vector<pointgen::SampledFrame>& chosen,
                             const shadow::Light& light) {
  const shadow::ShadowView& v = setup.views[static_cast<std::size_t>(layer)];
  const pointgen::SampledFrame polygons = settings_.points ? pointgen::SampledFrame{} : polygons_in(pointgen::ViewFrusta(culling_frusta(v)));
  const pointgen::SampledFrame& drawn = settings_.points ? chosen[static_cast<std::size_t>(layer)] : polygons;
  upload_polygons(drawn);
  stats_.shadow_triangles += gpu_scene_.fixed_triangles(v.clip_matrix()) + drawn.triangle_count;
  map_.draw_polygons(gpu_scene_, setup, layer, light, stages_);
  if (!settings_.points) return;
  map_.points().upload(drawn.points, tables_, samples_);
  map_.draw_points(setup, layer, stages_);
}

void Renderer::request_pages(const shadow::Camera& camera, const shadow::Light& light) {
  if (time_ != paged_time_ && !moving_groups_.empty()) {
    std::vector<shadow::Box> boxes = moving_boxes();
    std::vector<std::vector<glm::vec4>> moved(setup_.views.size());
    for (std::size_t v = 0; v < setup_.views.size(); ++v) {
      for (const std::vector<shadow::Box>* posed : {&paged_boxes_, &boxes}) {
        for (const shadow::Box& box : *posed) moved[v].push_back(shadow::image_bounds(setup_.views[v], box));
      }
    }
    pages_->invalidate(moved);
    paged_boxes_ = std::move(boxes);
  }
  paged_time_ = time_;
  pages_->request(frame_pass_, camera, light, setup_, draws_points());
  stages_.end("map pages");
  const shadow::PagePool::Frame& asked = pages_->last_request();
  setup_.description = shadow::technique(settings_.method).name + " over " + setup_.description + ": " + std::to_string(asked.requested) + " pages asked for, " +
                       std::to_string(asked.to_draw.size()) + " drawn, " + std::to_string(asked.dropped) + " dropped";
}

std::vector<shadow::Box> Renderer::moving_boxes() const {
  std::vector<shadow::Box> boxes;
  for (std::size_t g : moving_groups_) {
    const pointgen::InstanceTable& table = tables_[g];
    for (std::size_t i = 0; i < table.size(); ++i) boxes.push_back(shadow::transformed(mesh_boxes_[table.mesh], table.transforms[i]));
  }
  return boxes;
}

std::vector<shadow::PageTile> Renderer::page_tiles() const {
  std::vector<shadow::Page> pages;
  for (const auto& [page, layer] : pages_->last_request().to_draw) pages.push_back(page);
  return shadow::tiles_of(pages, pages_->map().tile_pages(map_.depths().size()));
}

shadow::ShadowSetup Renderer::tile_setup(const shadow::PageTile& tile) const {
  const shadow::ShadowView& base = setup_.views[static_cast<std::size_t>(tile.view)];
  return {{pages_->map().tile_view(base, tile, map_.depths().size())}, shadow::ViewSelection::single, "page tile"};
}

// The pages are asked for and drawn after the frame's surfaces, each tile of them into the map's
// first layer and copied from there; timed as the shadow pass.
FramePass::ShadowLookup Renderer::render_pages_on_cpu(const shadow::Camera& camera, const shadow::Light& light) {
  shadow_timer_.start();
  request_pages(camera, light);
  const std::vector<shadow::PageTile> tiles = page_tiles();
  std::vector<shadow::ShadowSetup> setups;
  std::vector<shadow::ShadowView> views;
  for (const shadow::PageTile& tile : tiles) {
    setups.push_back(tile_setup(tile));
    views.push_back(setups.back().views.front());
  }
  const std::vector<pointgen::SampledFrame> chosen = choose_map_casters(camera, views);
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const std::vector<pointgen::SampledFrame> one = settings_.points ? std::vector{chosen[i]} : std::vector<pointgen::SampledFrame>{};
    draw_map_view(setups[i], 0, one, light);
    pages_->copy_pages(map_.depths().depth_texture(), map_.silhouette_points(), tiles[i]);
    stages_.end("map pages");
  }
  shadow_timer_.stop();
  pending_.shadow_timer = true;
  return pages_->lookup(setup_);
}

FramePass::ShadowLookup Renderer::render_pages_on_gpu(const shadow::Camera& camera, const shadow::Light& light) {
  request_pages(camera, light);
  const std::vector<shadow::PageTile> tiles = page_tiles();
  // A tile draws the polygon plants whose boxes reach its image, whatever receivers this frame
  // shows: its pages are kept for later frames.
  if (draws_points() && !tiles.empty()) receivers_->mark_everywhere();
  for (const shadow::PageTile& tile : tiles) {
    const shadow::ShadowSetup setup = tile_setup(tile);
    std::optional<GpuScene::PlantDraws> plants;
    if (draws_points()) {
      plants = gpu_sampler_->select_casters(0, setup.views.front().view_projection(), map_.depths().size(), *receivers_);
      stages_.end("map choice");
    }
    map_.draw_polygons(gpu_scene_, setup, 0, light, stages_, plants ? &*plants : nullptr);
    pending_.shadow_fixed_triangles += gpu_scene_.fixed_triangles(setup.views.front().clip_matrix());
    if (draws_points()) {
      gpu_sampler_->cap_for_map(setup.views.front().view_projection(), shadow_texels(), settings_.k);
      stages_.end("map choice");
      map_.draw_points(setup, 0, stages_);
    }
    pages_->copy_pages(map_.depths().depth_texture(), map_.silhouette_points(), tile);
    stages_.end("map pages");
  }
  pending_.shadow_views = tiles.size();
  return pages_->lookup(setup_);
}

FramePass::ShadowLookup Renderer::map_lookup() const {
  return map_.lookup(setup_, shadow::technique(settings_.method).lookup == shadow::Lookup::mask);
}

MaskFrame Renderer::mask_frame(const shadow::Camera& camera, const shadow::Light& light) const {
  // The GPU sampler's polygon plants, for a mask whose casters are the frame's polygons (the
  // reference traces every plant as a mesh).
  std::optional<GpuScene::PlantDraws> plants;
  if (gpu_sampler_ && draws_points() && mask_->casts_from_frame_polygons()) {
    plants = gpu_sampler_->polygon_draws(0, gpu_sampler_->band_count());
  }
  return {camera, aspect(), light, view_projection_, scene_bounds_, gpu_scene_, plants, tables_, cells(), frame_pass_};
}

// Timed as the shadow pass, by the wall clock where the mask is CPU work.
FramePass::ShadowLookup Renderer::render_mask(const shadow::Camera& camera, const shadow::Light& light) {
  const auto start = std::chrono::steady_clock::now();
  if (!mask_->made_on_cpu()) shadow_timer_.start();
  const GLuint lit = mask_->render(mask_frame(camera, light));
  stages_.end(mask_->stage());
  if (mask_->made_on_cpu()) {
    stats_.shadow_pass_ms = ms_since(start);
  } else {
    shadow_timer_.stop();
    pending_.shadow_timer = true;
  }
  setup_ = {{}, shadow::ViewSelection::screen_mask, mask_->description()};
  return mask_lookup(lit);
}

// Chan and Durand 2004: where the map's filtered test was all lit or all shadowed its answer
// stands; the mask decides the rest, and the frame is lit again by it. Timed with the frame pass.
void Renderer::shade_with_mask_near_edges(const shadow::Camera& camera, const shadow::Light& light) {
  const GLuint lit = mask_->render(mask_frame(camera, light));
  stages_.end(mask_->stage());
  // setup_ keeps the map's views for the `shadowmap` AOV and the viewer.
  setup_.description += "; " + mask_->description();
  frame_pass_.shade(camera, light, mask_lookup(lit));
  stages_.end("shading");
}

FramePass::ShadowLookup Renderer::mask_lookup(GLuint mask) {
  static const shadow::ShadowSetup screen_mask{{}, shadow::ViewSelection::screen_mask, "mask"};
  return {mask, screen_mask, 0};
}

const pointgen::InstanceCells& Renderer::cells() const {
  std::call_once(cells_made_, [this] { cells_.emplace(tables_, samples_.meshes()); });
  return *cells_;
}

ExactVisibility& Renderer::exact() {
  if (!exact_) exact_ = std::make_unique<ExactVisibility>(meshes_now_.empty() ? scene_.meshes : meshes_now_, tables_);
  exact_->pose(tables_);
  return *exact_;
}

Image8 Renderer::exact_visibility() { return exact().trace(camera_, light_, frame_pass_.read_depth()); }

void Renderer::draw_surfaces(const shadow::Camera& camera, const std::vector<shadow::Plane>& casters) {
  frame_pass_.draw_surfaces(gpu_scene_, camera);
  stages_.end("polygons");
  if (gpu_sampler_) {
    if (draws_points()) sample_on_gpu(camera, casters);
  } else if (settings_.points) {
    frame_points_.begin();
    frame_points_.add(view_projection_, settings_.splat_size, 0.0f, false, coverage_view(camera));
    stages_.end("splats");
  }
}

void Renderer::resolve_points(const shadow::Camera& camera) {
  if (!draws_points()) return;
  frame_points_.resolve(view_projection_, settings_.splat_size, 0.0f);
  frame_pass_.add_points(frame_points_, camera);
  stages_.end("splats");
}

void Renderer::shade(const shadow::Camera& camera, const shadow::Light& light, const std::optional<FramePass::ShadowLookup>& lookup) {
  frame_pass_.shade(camera, light, lookup);
  stages_.end("shading");
}

void Renderer::finish_frame(const shadow::Camera& camera, const shadow::Light& light,
                            const std::optional<FramePass::ShadowLookup>& lookup) {
  resolve_points(camera);
  shade(camera, light, lookup);
}

void Renderer::sample_on_gpu(const shadow::Camera& camera, const std::vector<shadow::Plane>& casters) {
  gpu_sampler_->begin(sampler_view(camera, settings_, {view_projection_}), GpuSampler::bands(camera.far), casters);
  stages_.end("choice");
  const int bands = gpu_sampler_->distance_band_count();
  frame_points_.use(gpu_sampler_->draw_list(), samples_);
  frame_points_.begin();
  // The first band is hidden by the ground alone; each next one by what the bands before drew.
  occluders_->build(frame_pass_.depth_stencil_texture(), frame_points_.depth_buffer());
  for (int b = 0; b < bands; ++b) {
    if (b > 0) occluders_->build_changed(frame_pass_.depth_stencil_texture(), frame_points_.depth_buffer());
    stages_.end("occlusion");
    gpu_sampler_->add_band(b, occluders_.get());
    stages_.end("choice");
    frame_pass_.add_chosen_surfaces(gpu_scene_, *gpu_sampler_, b, camera);
    stages_.end("polygons");
    frame_points_.add(view_projection_, settings_.splat_size, 0.0f, true, coverage_view(camera));
    stages_.end("splats");
  }
  // Casters out of view and near plants the frame hides: for the shadow map alone (the frame's
  // splat passes stop before their points).
  if (!casters.empty()) {
    const glm::mat4 map_view = culling_frusta(setup_.views.front()).front();
    occluders_->build_changed(frame_pass_.depth_stencil_texture(), frame_points_.depth_buffer());
    receivers_->build_receivers(*occluders_, view_projection_, map_view);
    stages_.end("occlusion");
    // A hybrid's map keeps the frame's polygon plants polygons: its volumes count them near the
    // map's edges, which points would not have (street, 1024²: err 1.36 -> 0.99 %). A paged map's
    // casters are counted for its finest level, and each tile takes as many as its level asks
    // (cap_for_map): counted for the tiles' own size, the plants beside and behind the camera cast
    // scattered dots (the ecosystem path at t = 6 s, 640 × 360: 19.6 % of pixels wrong against 6.2 %).
    const float texels = pages_ ? pages_->map().caster_texels * pages_->map().caster_texels : shadow_texels();
    gpu_sampler_->add_casters(map_view, texels, *receivers_, !setup_.views.front().paraboloid && !mask_);
    stages_.end("map choice");
  }
}

void Renderer::pose(double t) {
  for (const Animation& animation : scene_.animations) {
    std::vector<pointgen::InstanceTable> posed = animation.set.pose(t, animation.first_mesh);
    for (std::size_t i = 0; i < posed.size(); ++i) {
      const std::size_t group = animation.first_group + i;
      if (settings_.point_meshes_only && !scene_.point_meshes[posed[i].mesh]) continue;
      tables_.replace(group, std::move(posed[i]));
      if (cells_) cells_->update(group, tables_[group], samples_.meshes()[tables_[group].mesh]);
      // Point meshes get their drawn subset per pass (upload_polygons), or live on the GPU sampler.
      if (!scene_.point_meshes[tables_[group].mesh]) gpu_scene_.update(group, tables_[group]);
      if (gpu_sampler_ && scene_.point_meshes[tables_[group].mesh]) gpu_sampler_->update(group, tables_[group]);
    }
  }
}

void Renderer::place_landscapes(const shadow::Camera& camera) {
  for (std::size_t l = 0; l < landscape_pools_.size(); ++l) {
    place_ground(l, camera.position);
    // A far block's points are drawn as the frame's density asks (sampler_view's), at an average
    // facing of one half; none where the frame draws no points.
    const pointgen::PointDensity density = sampler_view(camera, settings_, {}).density;
    const float points_at_a_metre = settings_.points ? 0.5f * density.k * density.pixels_per_radian * density.pixels_per_radian : 0.0f;
    if (landscape_pools_[l].fill({camera.position, view_projection_, points_at_a_metre})) take_landscape_tables(l);
    stats_.landscape.add(landscape_pools_[l].stats());
  }
}

void Renderer::place_ground(std::size_t landscape, const glm::vec3& eye) {
  std::vector<pointgen::GroundChunkKey> chunks = grounds_[landscape].chosen(eye);
  if (chunks == ground_chunks_[landscape]) return;
  pointgen::GroundChunks::Chunked ground = grounds_[landscape].mesh(chunks);
  const std::size_t mesh = scene_.landscapes[landscape].ground_mesh;
  gpu_scene_.replace_mesh(mesh, ground.mesh, ground.chunks);
  ground_chunks_[landscape] = std::move(chunks);
  if (meshes_now_.empty()) meshes_now_ = scene_.meshes;
  meshes_now_[mesh] = std::move(ground.mesh);
  exact_.reset();  // traced again over this ground
}

void Renderer::take_landscape_tables(std::size_t landscape) {
  exact_.reset();  // traced again over these plants
  std::vector<pointgen::InstanceTable> tables = landscape_pools_[landscape].tables();
  for (std::size_t s = 0; s < tables.size(); ++s) {
    const std::size_t group = scene_.landscapes[landscape].first_group + s;
    tables_.replace(group, std::move(tables[s]));
    if (cells_) cells_->update(group, tables_[group], samples_.meshes()[tables_[group].mesh]);
  }
  if (gpu_sampler_) gpu_sampler_->refill(landscape, tables_);
}

void Renderer::render(const shadow::Camera& camera, const shadow::Light& light, double t) {
  const double host_start = host_cpu_ms();
  // The first frame has no frame before it: it takes one from itself drawn without shadows.
  if (needs_last_frame() && !has_last_frame_) start_after(camera, light, t);
  draw(camera, light, t, shadow::technique(settings_.method).lookup != shadow::Lookup::none);
  if (needs_last_frame()) remember_last_frame();
  // draw() added the sampling thread's. The GL calls' share is an estimate (each call's clock
  // readings are taken out at their least cost), and a frame whose own work is within its error can
  // come out below zero (-0.2 ms on an H200): such a frame counts none.
  stats_.host_ms = std::max(0.0, stats_.host_ms + host_cpu_ms() - host_start);
}

void Renderer::start_after(const shadow::Camera& camera, const shadow::Light& light, double t) {
  if (!needs_last_frame()) return;
  draw(camera, light, t, false);
  remember_last_frame();
}

// The PSM takes its near plane from the last frame, auto its surface, caster culling its receivers.
bool Renderer::needs_last_frame() const {
  return shadow::technique(settings_.method).last_frame != shadow::LastFrame::nothing || culls_casters();
}

bool Renderer::culls_casters() const {
  return settings_.points && !gpu_sampler_ && settings_.cull_casters && shadow::technique(settings_.method).culls_casters;
}

bool Renderer::draws_points() const { return settings_.points && (!gpu_sampler_ || gpu_sampler_->plant_count() > 0); }

// The nearest depth reduced on the GPU (host_ms: a CPU scan of the read-back took 1 ms at 640×360
// and 5 ms at 1920×1080 here); the receivers read back and sampled on the CPU. auto predicts from
// the surfaces the frame pass still holds when the next frame begins.
void Renderer::remember_last_frame() {
  nearest_visible_ = frame_pass_.nearest_depth();
  last_camera_ = camera_;
  has_last_frame_ = true;
  if (!culls_casters()) return;
  const Image<float> depth = frame_pass_.read_depth();
  // Every 4th pixel each way: far denser than the mask's tiles (docs/point_density.md, "Receivers").
  last_receivers_ = surface_positions(depth, PixelRays(camera_, depth.width, depth.height), 4);
}

// Where the GPU sampler chooses the plants, a technique with a map draws the frame's surfaces first
// and its map from the same plants; otherwise the map (or the mask) and the frame take their
// plants from the CPU's choice.
void Renderer::draw(const shadow::Camera& camera, const shadow::Light& light, double t, bool shadows) {
  begin_frame(camera, light, t);
  const shadow::Technique& technique = shadow::technique(settings_.method);
  const bool map = shadows && technique.has_map();
  const std::vector<shadow::Plane> casters = map ? set_up_map(camera, light) : std::vector<shadow::Plane>{};
  const pointgen::SampledFrame selection = gpu_sampler_ && map ? draw_sampled_on_gpu(camera, light, casters)
                                               : draw_sampled_on_cpu(camera, light, shadows);
  stats_.points = selection.point_count;
  stats_.triangles = gpu_scene_.fixed_triangles(view_projection_) + selection.triangle_count;
  throw_on_gl_error();
}

void Renderer::begin_frame(const shadow::Camera& camera, const shadow::Light& light, double t) {
  pose(t);
  stats_ = {};
  pending_ = {};
  stages_.start();
  view_projection_ = camera.projection(aspect()) * camera.view();
  time_ = t;
  camera_ = camera;
  light_ = light;
  place_landscapes(camera);
}

std::vector<shadow::Plane> Renderer::set_up_map(const shadow::Camera& camera, const shadow::Light& light) {
  const shadow::ShadowInputs inputs = shadow_inputs(camera, light);
  setup_ = make_shadow_setup(inputs);
  return inputs.bodies.casters.face_planes();
}

void Renderer::throw_on_gl_error() {
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", error);
    throw RuntimeFailure(std::string("OpenGL error ") + code + " while rendering; try a smaller --size or --shadow-size, "
                         "or another --backend");
  }
}

pointgen::SampledFrame Renderer::draw_sampled_on_cpu(const shadow::Camera& camera, const shadow::Light& light, bool shadows) {
  const shadow::Technique& technique = shadow::technique(settings_.method);
  std::future<TimedSelection> chosen = choose_frame_points(camera);
  std::optional<FramePass::ShadowLookup> lookup;
  if (shadows && technique.has_map() && !pages_) lookup.emplace(render_shadow_map(camera, light));
  const pointgen::SampledFrame selection = frame_plants(chosen);
  upload_polygons(selection);
  const bool mask = shadows && mask_;
  frame_timer_.start();
  draw_surfaces(camera, {});
  resolve_points(camera);
  frame_timer_.stop();
  if (shadows && pages_) lookup.emplace(render_pages_on_cpu(camera, light));
  if (mask && !technique.has_map()) lookup.emplace(render_mask(camera, light));
  finish_timer_.start();
  shade(camera, light, lookup);
  if (mask && technique.has_map()) shade_with_mask_near_edges(camera, light);
  finish_timer_.stop();
  pending_.frame_timers = true;
  pending_.gpu_choice = gpu_sampler_ != nullptr;
  return selection;
}

// The frame's points are chosen on another thread while this one chooses the shadow map's and
// draws it: sampling is CPU work, and on llvmpipe the GL work is too, so the two overlap on two
// cores. The sampler only reads what pose() left.
std::future<Renderer::TimedSelection> Renderer::choose_frame_points(const shadow::Camera& camera) const {
  if (!settings_.points || gpu_sampler_) return {};
  return std::async(std::launch::async, [this, camera] {
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = thread_cpu_ms();
    TimedSelection chosen;
    chosen.selection = pointgen::sample_view(sampler_view(camera, settings_, {view_projection_}), tables_, samples_.meshes(), cells());
    chosen.ms = ms_since(start);
    chosen.cpu_ms = thread_cpu_ms() - cpu_start;
    return chosen;
  });
}

pointgen::SampledFrame Renderer::frame_plants(std::future<TimedSelection>& chosen) {
  pointgen::SampledFrame selection;
  if (gpu_sampler_) {
    selection.polygons.resize(tables_.size());  // the frame's plants come from gpu_sampler_
  } else if (settings_.points) {
    TimedSelection timed = chosen.get();
    stats_.sample_ms += timed.ms;
    stats_.host_ms += timed.cpu_ms;
    selection = settings_.measure != RenderSettings::Measure::off ? measured(timed.selection) : std::move(timed.selection);
    frame_points_.upload(selection.points, tables_, samples_);
  } else {
    // A mask drawn from the frame's polygons needs the casters out of view too.
    const bool every_caster = mask_ && mask_->casts_from_frame_polygons();
    selection = every_caster ? polygons_in(std::nullopt) : polygons_in(pointgen::ViewFrusta({view_projection_}));
  }
  return selection;
}

pointgen::SampledFrame Renderer::draw_sampled_on_gpu(const shadow::Camera& camera, const shadow::Light& light,
                                                    const std::vector<shadow::Plane>& casters) {
  pointgen::SampledFrame selection;
  selection.polygons.resize(tables_.size());
  upload_polygons(selection);  // the point meshes' plants come from gpu_sampler_
  frame_timer_.start();
  draw_surfaces(camera, casters);
  frame_timer_.stop();

  // The shadow map draws the frame's own plants, the casters' band with them (Stamminger and
  // Drettakis 2002, Sect. 5): the camera's points, whose density the perspective map keeps
  // uniform, so one splat size fits. One texel: on the ecosystem's default view with PSM 2048²,
  // err 5.67 % against 6.00 % with 2 × 2 and 6.51 % with 3 × 3, whose shadows grow. Where a map's
  // texels are coarser than the camera's pixels (the uniform map near the eye), each plant is
  // thinned to k points a texel (GpuSampler::cap_for_map), as a sampling for the map would make it
  // (uniform err 13.40 % against 12.52 % thinned; docs/benchmarks.md).
  map_.points().use(gpu_sampler_->draw_list(), samples_);
  // A paged map's pages are asked for by every surface, the points' too.
  if (pages_) resolve_points(camera);
  shadow_timer_.start();
  pending_ = {true, true, true, setup_.views.size()};
  const FramePass::ShadowLookup lookup = pages_ ? render_pages_on_gpu(camera, light) : render_map_on_gpu(light);
  shadow_timer_.stop();

  finish_timer_.start();
  if (!pages_) resolve_points(camera);
  shade(camera, light, lookup);
  if (mask_) shade_with_mask_near_edges(camera, light);
  finish_timer_.stop();
  return selection;
}

FramePass::ShadowLookup Renderer::render_map_on_gpu(const shadow::Light& light) {
  // Every band's polygon plants, listed on the GPU for the first map that draws them all.
  std::optional<GpuScene::PlantDraws> every_band;
  const auto every_band_draws = [&] {
    if (!every_band) every_band = gpu_sampler_->polygon_draws(0, gpu_sampler_->band_count());
    return *every_band;
  };
  // One projective map: the receiver mask over it was built for the casters' band.
  const bool one_map = setup_.views.size() == 1 && !setup_.views.front().paraboloid && gpu_sampler_->casters_band();
  std::vector<glm::mat4> earlier;  // the cascades before this one
  for (std::size_t layer = 0; layer < setup_.views.size(); ++layer) {
    const shadow::ShadowView& v = setup_.views[layer];
    const GpuScene::PlantDraws plants = setup_.selection == shadow::ViewSelection::first_containing
                                            ? cascade_casters(static_cast<int>(layer), v.view_projection(), earlier)
                                        : one_map ? gpu_sampler_->select_casters(0, v.view_projection(), settings_.shadow_size, *receivers_)
                                                  : every_band_draws();
    earlier.push_back(v.view_projection());
    stages_.end("map choice");
    map_.draw_polygons(gpu_scene_, setup_, static_cast<int>(layer), light, stages_, &plants);
    pending_.shadow_fixed_triangles += gpu_scene_.fixed_triangles(v.clip_matrix());
    if (!draws_points()) continue;
    gpu_sampler_->cap_for_map(v.view_projection(), shadow_texels(), v.paraboloid ? 0.0f : settings_.k);
    stages_.end("map choice");
    map_.draw_points(setup_, static_cast<int>(layer), stages_);
  }
  return map_lookup();
}

// A cascade draws the polygon plants that shadow the surfaces that look it up, those in no
// earlier cascade's square: near plants, whose shadows fall in the first cascade, stay out of the
// others (on the ecosystem's default view each cascade otherwise drew every polygon plant).
GpuScene::PlantDraws Renderer::cascade_casters(int layer, const glm::mat4& map_view, const std::vector<glm::mat4>& earlier) {
  if (!draws_points()) return {};
  receivers_->build_receivers(*occluders_, view_projection_, map_view, earlier, static_cast<float>(settings_.shadow_size));
  return gpu_sampler_->select_casters(layer, map_view, settings_.shadow_size, *receivers_);
}

// The GPU's figures of the last frame drawn, read back when asked: nothing in a frame waits for
// them, and a caller that asks after the next frame's commands waits for no more than this one.
const FrameStats& Renderer::stats() const {
  if (pending_.frame_timers) stats_.frame_pass_ms = frame_timer_.ms() + finish_timer_.ms();
  if (pending_.shadow_timer) stats_.shadow_pass_ms = shadow_timer_.ms();
  if (pending_.frame_timers) stats_.stage_ms = stages_.ms();
  if (pending_.gpu_choice) {
    const GpuSampler::Totals chosen = gpu_sampler_->read_totals();
    stats_.points = chosen.frame_points;
    stats_.points_left_out = chosen.points_left_out;
    stats_.triangles = gpu_scene_.fixed_triangles(view_projection_) + chosen.frame_triangles;
    if (pending_.shadow_views > 0) {
      stats_.shadow_points = map_.points_drawn();
      // The views that drew every band's polygon plants, and those that drew a selection.
      const std::size_t unselected = pending_.shadow_views - std::min(chosen.selections, pending_.shadow_views);
      stats_.shadow_triangles = pending_.shadow_fixed_triangles + unselected * chosen.triangles;
      for (const std::size_t triangles : chosen.layer_triangles) stats_.shadow_triangles += triangles;
    }
  }
  if (pages_) {
    const shadow::PagePool::Frame& asked = pages_->last_request();
    stats_.pages = {asked.requested, static_cast<int>(asked.to_draw.size()), asked.cached, asked.dropped, static_cast<int>(page_tiles().size())};
  }
  pending_ = {};
  return stats_;
}

}  // namespace ecoview
