#pragma once
#include "app/gl/gpu_stages.hpp"
#include "app/render/frame_pass.hpp"
#include "app/render/gpu_scene.hpp"
#include "app/render/point_splat.hpp"
#include "app/render/render_settings.hpp"
#include "app/render/shadow_pass.hpp"
#include "app/render/silhouette_pass.hpp"
#include "app/scene/scene.hpp"
#include "shadow/techniques.hpp"

#include <memory>

namespace ecoview {

// The GL side of a technique with a shadow map (shadow::Technique::has_map): the depth map's
// layers, one a view of the frame's setup; the point splats drawn onto them; a silhouette map
// beside them where the technique has one; and how the frame looks them up. A map that helps a
// mask (`hybrid`) keeps point splats, where the frame has any, in layers of their own after the
// views': the mask has polygon casters only, so the points' shadows are the map's to decide, and
// only the polygons' edges are the mask's. Which plants each layer draws is the renderer's choice (its sampler's).
class MapTechnique {
 public:
  // `surface_textures`: the scene has textures or alpha masks (GpuScene::has_surface_textures).
  MapTechnique(const RenderSettings& settings, bool surface_textures);
  // From the next layer drawn on, the map of `technique`, in frames with point casters or without;
  // what it needs besides depths is made here, so that frame times hold no shader compilation.
  void use(const shadow::Technique& technique, bool point_casters, GpuScene& polygons, const Scene& scene);
  // Layer `layer` of `setup`: the polygons' depths (with `plants`, also those polygon plants of a
  // GPU sampler), then the silhouettes of the polygons the scene holds; an empty layer for the
  // points where they have their own.
  void draw_polygons(const GpuScene& polygons, const shadow::ShadowSetup& setup, int layer, const shadow::Light& light,
                     gl::GpuStages& stages, const GpuScene::PlantDraws* plants = nullptr);
  // The point draws of the map, uploaded or used (PointSplat), made when first asked for.
  PointSplat& points();
  // The silhouette map's points of the last layer drawn (SilhouettePass::points); 0 without one.
  GLuint silhouette_points() const { return silhouette_map_ ? silhouettes_->points() : 0u; }
  // The points draw_points drew of a list with map caps (PointSplat::points_drawn_onto).
  std::size_t points_drawn() const { return points_ ? points_->points_drawn_onto() : 0; }
  // Splats them onto layer `layer` of `setup`, or onto its points' own.
  void draw_points(const shadow::ShadowSetup& setup, int layer, gl::GpuStages& stages);
  // How the frame's lighting looks the map up. `marks_edges`: the map helps a mask, which decides
  // where its filtered test is neither all lit nor all shadowed (FramePass::ShadowLookup).
  FramePass::ShadowLookup lookup(const shadow::ShadowSetup& setup, bool marks_edges) const;
  const ShadowPass& depths() const { return depths_; }

 private:
  int splat_size_;
  ShadowPass depths_;
  std::unique_ptr<PointSplat> points_;
  std::unique_ptr<SilhouettePass> silhouettes_;  // made for the first technique that has them
  bool silhouette_map_ = false;                  // the technique in use has one
  bool points_apart_ = false;                    // its points have layers of their own
};

}  // namespace ecoview
