#include "app/render/map_technique.hpp"

namespace ecoview {
namespace {

// Window-depth offset of point splats in shadow maps, against self-shadowing of point surfaces.
constexpr float shadow_point_bias = 2e-5f;

}  // namespace

MapTechnique::MapTechnique(const RenderSettings& settings, bool surface_textures)
    : splat_size_(settings.shadow_splat_size),
      depths_(map_texels(settings), settings.shadow_bias, settings.shadow_depth, surface_textures) {}

void MapTechnique::use(const shadow::Technique& technique, bool point_casters, GpuScene& polygons, const Scene& scene) {
  silhouette_map_ = technique.silhouette_map;
  points_apart_ = point_casters && technique.lookup == shadow::Lookup::mask;
  if (silhouette_map_ && !silhouettes_) {
    silhouettes_ = std::make_unique<SilhouettePass>(depths_.size());
    polygons.add_adjacency(scene);
  }
}

// The silhouettes are those of every polygon the layer drew: the scene's fixed polygons, and the
// plants drawn as polygons on the CPU's choice or the GPU's (`plants`).
void MapTechnique::draw_polygons(const GpuScene& polygons, const shadow::ShadowSetup& setup, int layer,
                                 const shadow::Light& light, gl::GpuStages& stages, const GpuScene::PlantDraws* plants) {
  const int views = static_cast<int>(setup.views.size());
  if (points_apart_) depths_.reserve_layers(2 * views);
  depths_.render(polygons, setup, layer, plants);
  if (points_apart_) depths_.clear_layer(views + layer);
  stages.end("map polygons");
  if (!silhouette_map_) return;
  silhouettes_->render(polygons, plants, setup, layer, light);
  stages.end("map silhouettes");
}

PointSplat& MapTechnique::points() {
  if (!points_) points_ = std::make_unique<PointSplat>(glm::ivec2(depths_.size()));
  return *points_;
}

void MapTechnique::draw_points(const shadow::ShadowSetup& setup, int layer, gl::GpuStages& stages) {
  const shadow::ShadowView& view = setup.views[static_cast<std::size_t>(layer)];
  const int target = points_apart_ ? static_cast<int>(setup.views.size()) + layer : layer;
  points().splat_onto(depths_.depth_texture(), target, view.view_projection(), splat_size_, shadow_point_bias,
                      view.paraboloid_parameters());
  stages.end("map splats");
}

FramePass::ShadowLookup MapTechnique::lookup(const shadow::ShadowSetup& setup, bool marks_edges) const {
  return {depths_.depth_texture(), setup, depths_.size(), marks_edges, points_apart_,
          silhouette_map_ ? silhouettes_->points() : 0u, silhouette_map_ ? silhouettes_->edge_depths() : 0u};
}

}  // namespace ecoview
