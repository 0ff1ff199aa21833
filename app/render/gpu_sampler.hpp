#pragma once
#include "app/gl/gl_objects.hpp"
#include "app/render/depth_pyramid.hpp"
#include "app/render/gpu_scene.hpp"
#include "app/render/point_samples.hpp"
#include "app/render/point_splat.hpp"
#include "app/render/polygon_part_lists.hpp"
#include "pointgen/sampling/view_sampler.hpp"
#include "pointgen/table_list.hpp"
#include "shadow/plane.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace ecoview {

// The view sampler's per-plant choice on the GPU. The plants of point meshes stay in GL buffers
// from load on (transform, tint, mesh, rounding threshold). A frame's plants in view are sorted
// into bands of distance from the eye (a dense band cut into several) and sampled band by band,
// nearest first: each band's plants are culled against a depth pyramid of what the bands before
// drew (occluders drawn first in the same frame, so a frame depends on its own view alone),
// counted with the density formula, given points or polygons with the band around break-even, and
// appended to the point draws (as PointSplat reads them) and the list of polygon plants (their
// indices), with indirect draws per table and band and no read-back; the frame draws a large
// polygon plant's parts that it may show. Two last bands, for shadow maps alone, may hold the
// casters out of view and the plants the frame hides that shadow what it shows; a cascade or a
// single map draws the polygon plants, and of a large one the parts, that shadow its receivers.
// Without occlusion it chooses as pointgen::sample_view does, by whole plants and without cells'
// aggregates: the CPU sampler is its test oracle. docs/point_density.md, "On the GPU".
class GpuSampler {
 public:
  // Tables [first, end) whose plants change with the eye (a landscape's species): they share
  // room for `capacity` plants, laid out anew by refill.
  struct Pool {
    std::size_t first = 0, end = 0;
    std::size_t capacity = 0;
  };
  // `tables` are the scene's groups; those of point meshes (`samples` has lists for them) become
  // plants, in table order, each pool's in its room. `places`: where each mesh's triangles lie for
  // the polygon draws.
  GpuSampler(const pointgen::TableList& tables, const PointSamples& samples,
             const std::vector<GpuScene::DrawPlace>& places, const std::vector<Pool>& pools = {});

  // The distance bands for a view whose far plane is `far` metres away: the first to
  // first_band_end, each next one `band_ratio` times as far, the last to infinity.
  static std::vector<glm::vec2> bands(float far);
  static constexpr int max_bands = 32;

  // Moves a table's plants (posed people, animals, vehicles): their transforms and tints alone
  // cross the bus. `table` has as many instances as at load.
  void update(std::size_t table, const pointgen::InstanceTable& posed);
  // Lays the pool's tables out in its room, one after the other, as `tables` now holds them (at
  // most its capacity in all); the rest of the room holds no plant.
  void refill(std::size_t pool, const pointgen::TableList& tables);

  // Starts a frame's lists for the view, and sorts the plants in its frusta into the bands (from
  // bands()): the view's frusta, eye, density and point cost are used; its occlusion, cap and
  // receivers are not. With `casters` (the planes of a convex body, normals out: all that may
  // shadow what the view sees), the plants in it but outside the view's frusta are a band of their
  // own after the others, the casters', counted as the view's density asks (their shadows are seen
  // in it); the band of hidden plants follows it (add_casters).
  void begin(const pointgen::SamplerView& view, const std::vector<glm::vec2>& bands,
             const std::vector<shadow::Plane>& casters = {});
  // The bands of this frame, the casters' among them; those of distance, nearest first, as many
  // as the ladder's from begin(): the GPU cuts a dense one into several in the places of empty ones.
  int band_count() const { return bands_used_; }
  int distance_band_count() const { return distance_bands_; }
  // The number of the casters' band in this frame; none without caster views.
  std::optional<int> casters_band() const { return casters_band_; }
  // Adds the plants of a band (numbered from 0, nearest first); hidden ones are left out where
  // `occluders` is given (built over the first view's image).
  void add_band(int band, const DepthPyramid* occluders);
  // The casters' band, then a band of the plants within a few tens of metres that the frame's
  // bands left out as hidden (their shadows may fall on what the frame shows) and of those the
  // frame draws as polygons that the map asks too few points of to be polygons there (the maps
  // then draw them as points alone), each counted for a shadow map of `texels` texels through
  // `map_view` (its first view's world → clip matrix): only plants whose boxes cover a receiver
  // farther from the light in `receivers` (a mask over that view's image,
  // DepthPyramid::build_receivers), none with more points than k per texel it covers there. Their
  // points are for the maps alone. Polygon plants are moved to points only where `to_points`: a
  // paraboloid map draws every band's polygon plants, and so does a hybrid's, whose volumes count them.
  void add_casters(const glm::mat4& map_view, float texels, const DepthPyramid& receivers, bool to_points);
  // One band holding every plant, without occlusion.
  void sample(const pointgen::SamplerView& view);

  // The point draws so far, for PointSplat::use.
  PointDrawList draw_list() const;
  // Caps each point draw for a shadow view of `texels` texels through `map_view` (its world → clip
  // matrix), before the view's splat: of a plant, no more points than `points_per_texel` a texel
  // of half its surface there, the first of its list (shaders/map_caps.comp); 0 (a paraboloid
  // view): every point.
  void cap_for_map(const glm::mat4& map_view, float texels, float points_per_texel);
  // The plants chosen as polygons in bands `first` to `end` - 1, one command per table of point
  // meshes and band (the non-empty ones copied on the GPU; valid until the next call).
  GpuScene::PlantDraws polygon_draws(int first, int end) const;
  // Those of a band the frame shows as the frame draws them: a large one's parts that nearer bands
  // leave to be seen, the others whole (per table, a command per polygon part and one for those
  // drawn whole). Nothing for the shadow maps' own bands.
  GpuScene::PlantDraws frame_polygon_draws(int band) const;
  // Those of every band this frame (the casters' too) that shadow what shadow view `layer` (below
  // max_layers) serves: whose bounds box through `map_view` (its world → clip matrix) covers a
  // receiver in `receivers` (a mask over its image, DepthPyramid::build_receivers), and of a plant
  // covering more than 1,024 of the view's `map_size`² texels, the parts whose boxes do (per table,
  // a command per polygon part and one for those drawn whole). Valid until the next call; the
  // lists are made on the GPU.
  GpuScene::PlantDraws select_casters(int layer, const glm::mat4& map_view, int map_size, const DepthPyramid& receivers);
  static constexpr int max_layers = PolygonPartLists::max_layers;

  std::size_t plant_count() const { return plant_count_; }
  // The plant index of a table's first instance.
  std::uint32_t first_plant(std::size_t table) const { return first_plant_[table]; }

  // Read back, for tests and figures: per plant its points, whether drawn as polygons and its band
  // this frame (none: not in view), the draws (first point, count, first sample, plant), and the
  // totals: the polygon plants' triangles of every band (as polygon_draws last listed them), the points and triangles of the bands the
  // frame shows (all but the casters'), and the triangles of the plants selected for each layer
  // this frame (select_casters; none where its views drew them all), in that many selections.
  struct Count {
    std::uint32_t points = 0;
    bool polygons = false;
    std::optional<int> band;
  };
  std::vector<Count> read_counts() const;
  std::vector<glm::uvec4> read_draws() const;
  struct Totals {
    std::size_t triangles = 0, frame_points = 0, frame_triangles = 0;
    std::size_t points_left_out = 0;  // chosen beyond what the splat's buffers hold: not drawn
    std::vector<std::size_t> layer_triangles;
    std::size_t selections = 0;
  };
  Totals read_totals() const;

 private:
  void bind() const;
  const Pool* pool_of(std::size_t table) const;  // none: a table of its own
  void place(std::size_t table, const pointgen::InstanceTable& plants);  // at first_plant_[table]
  void sort(const gl::Program& keys, int band_count, int first_band);
  void cut_dense_bands();
  bool in_frame(int band) const;  // a band the frame shows: not the casters' nor the hidden plants'
  std::size_t plant_count_ = 0;
  std::size_t group_count_ = 0;
  std::size_t point_capacity_ = 0;  // points the draw list has room for
  int bands_used_ = 0;
  int distance_bands_ = 0;
  std::optional<int> casters_band_, hidden_band_;
  std::vector<std::uint32_t> first_plant_;
  std::vector<bool> holds_plants_;  // per table
  std::vector<std::size_t> range_of_;  // per table holding plants: its entry in tables_
  std::vector<Pool> pools_;
  std::vector<std::uint32_t> pool_rooms_;  // per pool: its room's first plant
  std::size_t table_count_ = 0;  // tables holding plants: a polygon draw each per band or lane
  gl::Buffer instances_, plant_meshes_, meshes_, counts_, offsets_, group_sums_, draw_points_, draw_samples_, block_draws_, totals_;
  gl::Buffer polygon_instances_, tables_, commands_;
  gl::Texture instance_texels_{GL_TEXTURE_BUFFER};  // instances_ for the compute passes
  gl::Texture plant_mesh_texels_{GL_TEXTURE_BUFFER}, mesh_texels_{GL_TEXTURE_BUFFER};  // plant_meshes_, meshes_
  gl::Buffer band_keys_, group_bands_, band_list_, band_ranges_, band_dispatch_, band_ends_;
  gl::Program histogram_program_, band_ends_program_, keys_program_, hidden_keys_program_, bin_count_program_, bands_program_, place_program_;
  gl::Program count_program_, groups_program_, draws_program_, commands_program_;
  gl::Buffer map_caps_;
  gl::Program map_caps_program_;
  gl::Buffer polygon_parts_;  // every point mesh's parts (shaders/polygon_parts.glsl)
  std::unique_ptr<PolygonPartLists> part_lists_;  // the frame's and the maps' polygon plants by part
  std::unique_ptr<DrawnCommands> every_band_drawn_;  // polygon_draws'
};

}  // namespace ecoview
