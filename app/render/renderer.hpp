#pragma once
#include "app/gl/gpu_stages.hpp"
#include "app/gl/gpu_timer.hpp"
#include "app/render/depth_pyramid.hpp"
#include "app/render/frame_pass.hpp"
#include "app/render/gpu_sampler.hpp"
#include "app/render/gpu_scene.hpp"
#include "app/render/map_technique.hpp"
#include "app/render/paged_map.hpp"
#include "app/render/mask_technique.hpp"
#include "app/render/point_samples.hpp"
#include "app/render/point_splat.hpp"
#include "app/render/render_settings.hpp"
#include "app/render/shadow_pass.hpp"
#include "app/reference/exact_visibility.hpp"
#include "pointgen/landscape/landscape_pool.hpp"
#include "pointgen/sampling/frustum_culling.hpp"
#include "pointgen/sampling/view_sampler.hpp"
#include "shadow/aliasing.hpp"

#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace ecoview {

// Why this driver cannot render a frame or a shadow map of the settings' sizes (its textures or
// the point buffers would be too large); empty where it can. The Renderer throws it as InputError.
std::string driver_refusal(const RenderSettings& settings);

// What a frame drew, and how long its parts took.
struct FrameStats {
  std::size_t points = 0;     // in the frame pass
  std::size_t triangles = 0;  // in the frame pass
  std::size_t shadow_points = 0;  // in the shadow pass
  std::size_t shadow_triangles = 0;  // in the shadow pass, every view's
  // Points the GPU sampler chose beyond what its buffers hold (a driver's largest buffer): not
  // drawn, in the frame or the maps. 0 but in scenes of millions of plants on such a driver.
  std::size_t points_left_out = 0;
  // The landscapes' pools (pointgen::LandscapePool::Stats), summed: the cells and plants chosen,
  // those made this frame, the cells within reach left out by a full pool, and the plants kept made.
  pointgen::LandscapePool::Stats landscape;
  double sample_ms = 0.0;     // CPU: choosing points or polygons, for both passes
  // CPU time of the program's own threads outside GL calls (docs/figures.md), for the whole frame:
  // posing, sampling, setups, uploads' preparation, read-backs' scans.
  double host_ms = 0.0;
  double shadow_pass_ms = 0.0;  // GPU (timer query)
  double frame_pass_ms = 0.0;   // GPU (timer query): polygons, point splats and their shading
  // GPU (timestamps): both passes by stage (polygons, choice, occlusion, splats, shading; the
  // shadow map's as "map …"), in the order each first ran.
  std::vector<std::pair<std::string, double>> stage_ms;
  // A virtual paged map's pages (--method adaptive): asked for by the frame's pixels, drawn this
  // frame, held drawn from earlier frames, and given no layer (the pool was full); and the tiles
  // (views of up to 4 × 4 pages) that the drawn ones were drawn in.
  struct Pages {
    int requested = 0, drawn = 0, cached = 0, dropped = 0, tiles = 0;
  } pages;
};

// What the view sampler needs for `camera` with these settings; `views` are the matrices to cull
// against (the camera's for a frame, a shadow map's for its pass).
pointgen::SamplerView sampler_view(const shadow::Camera& camera, const RenderSettings& settings, std::vector<glm::mat4> views);

// One frame of a scene: the shadow pass for the chosen method, then the frame pass; with points
// on, both passes draw far instances of point meshes as splats. Needs a current GL context.
class Renderer {
 public:
  Renderer(const Scene& scene, const RenderSettings& settings);
  // The frame at time t (seconds): moving objects are posed for t first.
  void render(const shadow::Camera& camera, const shadow::Light& light, double t = 0.0);
  // Makes the next frame one that follows this camera at time t, as if that frame had been
  // rendered: it is drawn without shadows and kept for what the next frame takes from the last
  // (near plane, surface, receivers; nothing when the method takes nothing). A frame's own depth
  // does not depend on its shadows, so a capture that starts at frame i renders it to the same
  // bytes as one that rendered frame i-1 first.
  void start_after(const shadow::Camera& camera, const shadow::Light& light, double t);
  // Live changes (ecoview view): shadow method, map size and points per pixel, from the next frame on.
  void change(shadow::Method method, int shadow_size, float k);
  const RenderSettings& settings() const { return settings_; }
  bool has_landscapes() const { return !landscape_pools_.empty(); }
  const FramePass& frame() const { return frame_pass_; }
  const ShadowPass& shadow_map() const { return map_.depths(); }
  // The shadow setup of the last frame drawn with shadows.
  const shadow::ShadowSetup& shadow_setup() const { return setup_; }
  // The last frame's figures; those the GPU measures or counts are read back when first asked.
  const FrameStats& stats() const;
  // The instance tables as the last frame posed them.
  const pointgen::TableList& tables() const { return tables_; }
  // Fill the aliasing target (RenderSettings::aliasing) from the next frame on, or stop.
  void set_aliasing(bool wanted) { frame_pass_.set_aliasing(wanted); }
  // Per pixel, the last frame's points on the surface `surface_depth` shows there (linear view depth, of
  // the frame's size, as FramePass::read_depth gives it), within a splat's width at that depth
  // (PointSplat::count_points_on).
  Image<std::uint32_t> count_points_on(const Image<float>& surface_depth);
  // The exact visibility of the last frame's surfaces (ExactVisibility::trace), as the `shadow`
  // AOV encodes it.
  Image8 exact_visibility();

 private:
  float aspect() const;
  // How the frame sees its points, for the share of each pixel they cover.
  PointSplat::CoverageView coverage_view(const shadow::Camera& camera) const;
  // The GL side of the method: what its map needs besides depths, its mask.
  void make_method_passes();
  // Moves the moving objects to time t.
  void pose(double t);
  // Makes each landscape's cells within reach of the eye into its tables and its ground's chunks
  // for the eye into its ground mesh, from the eye alone.
  void place_landscapes(const shadow::Camera& camera);
  void place_ground(std::size_t landscape, const glm::vec3& eye);
  // The landscape's pool's tables in place of its groups', for both samplers.
  void take_landscape_tables(std::size_t landscape);
  // Loads the GPU instance buffers of point meshes with the instances `selection` draws as polygons.
  void upload_polygons(const pointgen::SampledFrame& selection);
  // One frame, with or without shadows.
  void draw(const shadow::Camera& camera, const shadow::Light& light, double t, bool shadows);
  // The frame's time, camera and light; its figures start from nothing.
  void begin_frame(const shadow::Camera& camera, const shadow::Light& light, double t);
  // The map's setup for this frame (setup_); returns the focus body of its casters (planes, normals
  // out).
  std::vector<shadow::Plane> set_up_map(const shadow::Camera& camera, const shadow::Light& light);
  // Throws RuntimeFailure where GL reports an error (an allocation the driver refused).
  static void throw_on_gl_error();
  // What the frame's shadow techniques set up from: the focus bodies, clipped once.
  shadow::ShadowInputs shadow_inputs(const shadow::Camera& camera, const shadow::Light& light) const;
  // The map of the method, or for `auto` the best predicted one.
  shadow::ShadowSetup make_shadow_setup(const shadow::ShadowInputs& inputs) const;
  shadow::ShadowSetup best_predicted_setup(const shadow::ShadowInputs& inputs) const;
  // Whether the shadow sampler skips casters by the last frame's receivers.
  bool culls_casters() const;
  // Whether frames have point passes: not where the GPU sampler holds no plants (a scene without
  // point meshes), whose pyramids and splat passes would run over nothing.
  bool draws_points() const;
  // Whether the next frame takes anything from the last one (near plane, surface, receivers).
  bool needs_last_frame() const;
  // Keeps what the next frame needs of this one: its nearest depth (PSM), its camera (auto predicts
  // from its surfaces, which the frame pass keeps) and its receivers (culls_casters).
  void remember_last_frame();
  // The frame's shadow map (setup_), its plants chosen on the CPU; returns how the frame looks it
  // up.
  FramePass::ShadowLookup render_shadow_map(const shadow::Camera& camera, const shadow::Light& light);
  // The casters the CPU's view sampler chooses for each of `views` (maps of shadow_size texels),
  // timed as sampling; none with points off.
  std::vector<pointgen::SampledFrame> choose_map_casters(const shadow::Camera& camera, const std::vector<shadow::ShadowView>& views);
  // Draws view `layer` of `setup` into that layer of the map: its casters `chosen` (the CPU
  // sampler's), or with points off the polygons in its view.
  void draw_map_view(const shadow::ShadowSetup& setup, int layer, const std::vector<pointgen::SampledFrame>& chosen,
                     const shadow::Light& light);
  // A virtual paged map (pages_) for the surfaces the frame drew: the pages they ask for, drawn
  // tile by tile from the CPU sampler's casters, or from the GPU sampler's (the frame's own
  // plants); returns how the frame looks them up.
  FramePass::ShadowLookup render_pages_on_cpu(const shadow::Camera& camera, const shadow::Light& light);
  FramePass::ShadowLookup render_pages_on_gpu(const shadow::Camera& camera, const shadow::Light& light);
  // The pages this frame's surfaces ask for, given layers (PagedMap::request); first those held
  // are drawn again where moving casters were or are now.
  void request_pages(const shadow::Camera& camera, const shadow::Light& light);
  // The boxes of the moving instances as pose() left them.
  std::vector<shadow::Box> moving_boxes() const;
  // This frame's pages to draw, in tiles of as many as a map of shadow_size texels holds.
  std::vector<shadow::PageTile> page_tiles() const;
  // The setup whose one view draws a tile.
  shadow::ShadowSetup tile_setup(const shadow::PageTile& tile) const;
  // The map of setup_ from the GPU sampler's plants, view by view; returns how the frame looks it up.
  FramePass::ShadowLookup render_map_on_gpu(const shadow::Light& light);
  FramePass::ShadowLookup map_lookup() const;
  MaskFrame mask_frame(const shadow::Camera& camera, const shadow::Light& light) const;
  // A mask in place of a map, made for the frame's surfaces.
  FramePass::ShadowLookup render_mask(const shadow::Camera& camera, const shadow::Light& light);
  // A mask that refines a map (`hybrid`): made for the frame the map lit, which it lights again.
  void shade_with_mask_near_edges(const shadow::Camera& camera, const shadow::Light& light);
  static FramePass::ShadowLookup mask_lookup(GLuint mask);
  ExactVisibility& exact();
  // A frame whose plants the CPU's view sampler chooses, for the frame and for each shadow view;
  // or, with the GPU sampler, one without a shadow map. Returns what the frame drew.
  pointgen::SampledFrame draw_sampled_on_cpu(const shadow::Camera& camera, const shadow::Light& light, bool shadows);
  // The CPU sampler's choice for the frame, and its wall-clock and CPU time.
  struct TimedSelection {
    pointgen::SampledFrame selection;
    double ms = 0.0, cpu_ms = 0.0;
  };
  // The CPU sampler's choice of the frame's points on another thread; none without it.
  std::future<TimedSelection> choose_frame_points(const shadow::Camera& camera) const;
  // The plants the frame draws: those `chosen`, or with points off the polygons in view (and out of
  // view where a mask's casters are the frame's polygons), or with the GPU sampler none from here.
  pointgen::SampledFrame frame_plants(std::future<TimedSelection>& chosen);
  // A frame with a shadow map whose plants the GPU sampler chooses once, for the camera: the frame's
  // surfaces first, then the map from the same plants (and the casters out of view), then the
  // frame's lighting.
  // `casters`: the focus body of the casters (planes, normals out).
  pointgen::SampledFrame draw_sampled_on_gpu(const shadow::Camera& camera, const shadow::Light& light,
                                             const std::vector<shadow::Plane>& casters);
  // The texels of one shadow-map layer.
  float shadow_texels() const { return static_cast<float>(map_.depths().size()) * static_cast<float>(map_.depths().size()); }
  // The GPU sampler's polygon plants that cascade `layer` draws (map_view: its world → clip
  // matrix; earlier: the cascades' before it).
  GpuScene::PlantDraws cascade_casters(int layer, const glm::mat4& map_view, const std::vector<glm::mat4>& earlier);
  // The frame's plants chosen on the GPU band by band, nearest first: each band's polygons and
  // points drawn into the frame before the next band is culled against them; then, for the shadow
  // map alone, the plants in the casters' body (planes, normals out) out of view and the near
  // plants the frame hides.
  void sample_on_gpu(const shadow::Camera& camera, const std::vector<shadow::Plane>& casters);
  // The frame's surfaces: polygons, and with points their nearest depths (the splat's pass 1).
  void draw_surfaces(const shadow::Camera& camera, const std::vector<shadow::Plane>& casters);
  // Then the points' surfaces (the splat's pass 2),
  void resolve_points(const shadow::Camera& camera);
  // and the lighting.
  void shade(const shadow::Camera& camera, const shadow::Light& light, const std::optional<FramePass::ShadowLookup>& lookup);
  void finish_frame(const shadow::Camera& camera, const shadow::Light& light, const std::optional<FramePass::ShadowLookup>& lookup);
  // With every plant as polygons (no points): the instances of point meshes the frusta hold, culled
  // as the sampler culls them, so that points and polygons are timed on the same instances; with
  // none, all of them.
  pointgen::SampledFrame polygons_in(const std::optional<pointgen::ViewFrusta>& frusta) const;
  // The selection as RenderSettings::measure asks.
  pointgen::SampledFrame measured(const pointgen::SampledFrame& selection) const;
  const pointgen::InstanceCells& cells() const;

  const Scene& scene_;
  RenderSettings settings_;
  shadow::Box scene_bounds_;
  pointgen::TableList tables_;  // the scene's groups, read in place but for moving ones posed for this frame
  GpuScene gpu_scene_;
  PointSamples samples_;
  // The cells over tables_, for the CPU sampler, the culled polygon plants and the volumes: made
  // when first asked for (cells(), on whichever thread asks first), as the GPU sampler needs none
  // (10^7 plants: about 1.5 s, 50 MB).
  mutable std::optional<pointgen::InstanceCells> cells_;
  mutable std::once_flag cells_made_;
  MapTechnique map_;
  FramePass frame_pass_;
  PointSplat frame_points_;
  std::unique_ptr<GpuSampler> gpu_sampler_;  // --sampler gpu
  std::unique_ptr<DepthPyramid> occluders_;  // over the frame, for gpu_sampler_
  std::unique_ptr<DepthPyramid> receivers_;  // over the first shadow view: the frame's receivers
  std::unique_ptr<MaskTechnique> mask_;             // the method's, where its lookup is a mask
  std::unique_ptr<PagedMap> pages_;                 // the method's, where its lookup is pages
  std::vector<std::size_t> moving_groups_;          // the tables the scene's animations pose
  std::vector<pointgen::LandscapePool> landscape_pools_;  // per landscape of the scene
  std::vector<pointgen::GroundChunks> grounds_;          // per landscape
  std::vector<std::vector<pointgen::GroundChunkKey>> ground_chunks_;  // per landscape: its ground's now
  std::vector<shadow::Box> mesh_boxes_;             // of the moving groups' meshes, in their own space
  double time_ = 0.0;                               // of the frame being drawn
  // The time of the frame that last asked for pages and its moving instances' boxes then.
  double paged_time_ = -1.0;
  std::vector<shadow::Box> paged_boxes_;
  // The scene's meshes with each landscape's ground as this frame has it; empty: the scene's own.
  std::vector<pointgen::TriangleMesh> meshes_now_;
  std::unique_ptr<ExactVisibility> exact_;          // made when first asked for, and again when a landscape changed
  shadow::Camera camera_;                            // of the last frame
  shadow::Camera last_camera_;  // of the frame before this one, whose surfaces auto predicts from
  shadow::Light light_;                              // of the last frame
  shadow::ShadowSetup setup_;  // of the last frame
  // PSM: the nearest depth the camera saw in the last frame, pushing the near plane of the next
  // (Stamminger and Drettakis 2002, Sect. 6); 0 until a frame was drawn.
  float nearest_visible_ = 0.0f;
  std::vector<glm::vec3> last_receivers_;           // culls_casters: sampled from the last frame
  bool has_last_frame_ = false;
  glm::mat4 view_projection_{1.0f};  // of the last frame
  mutable FrameStats stats_;
  // The frame pass is timed in two pieces: its surfaces (frame_timer_), and after the shadow map or
  // mask made for them, the lighting (finish_timer_).
  gl::GpuTimer shadow_timer_, frame_timer_, finish_timer_;
  gl::GpuStages stages_;
  // What stats() still reads back from the GPU for the last frame.
  struct PendingStats {
    bool frame_timers = false;
    bool shadow_timer = false;
    bool gpu_choice = false;         // the GPU sampler's totals
    std::size_t shadow_views = 0;    // of its shadow map, in those totals
    std::size_t shadow_fixed_triangles = 0;  // of the scene's own meshes, in those views
  };
  mutable PendingStats pending_;
};

}  // namespace ecoview
