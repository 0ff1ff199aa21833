#pragma once
#include "app/scene/scene.hpp"
#include "pointgen/sampling/point_count.hpp"
#include "shadow/techniques.hpp"

#include <array>
#include <string>

// What a Renderer draws and how: plain values the command line fills in, with no GL.
namespace ecoview {

// glPolygonOffset(slope, constant) of the shadow maps: `slope` scales with each triangle's depth
// slope, which removes acne on surfaces the light grazes; `constant` adds that many depth steps
// everywhere. Too little leaves acne, too much lifts shadows off their casters (leak).
struct DepthBias {
  float slope = 2.0f;
  float constant = 4.0f;
};

// The shadow maps' depth format (Kilgard 2001): 16- and 24-bit fixed point spread their steps
// evenly over the window depth 0..1; 32-bit float packs them towards 0. Polygon offset counts in
// the format's own steps, so the same --bias-constant is a larger offset at 16 bits.
enum class ShadowDepth { fixed16, fixed24, float32 };
constexpr std::array<ShadowDepth, 3> shadow_depths = {ShadowDepth::fixed16, ShadowDepth::fixed24, ShadowDepth::float32};
std::string shadow_depth_name(ShadowDepth depth);  // 16, 24, 32f: the --shadow-depth values

struct RenderSettings {
  int width = 1280;
  int height = 720;
  int shadow_size = 2048;
  shadow::Method method = shadow::Method::uniform;
  bool points = true;       // far plants, people and animals as point splats; false: all polygons
  float k = pointgen::PointDensity{}.k;  // points per pixel of projected surface (docs/point_density.md)
  int splat_size = 2;       // pixels per side of one point's splat in the frame
  // Texels per side in the shadow map. One: with k points per texel a splat of 2 x 2 closes the
  // gaps between leaves, and the plants' shadows grow (docs/benchmarks.md, "`ecoview bench`").
  int shadow_splat_size = 1;
  DepthBias shadow_bias{};  // the shadow pass's polygon offset (--bias-slope, --bias-constant)
  ShadowDepth shadow_depth = ShadowDepth::float32;  // --shadow-depth
  float points_per_triangle = 4.0f;  // a point costs 1/this of a triangle (the point-or-polygon choice)
  bool point_meshes_only = false;    // draw nothing else (for the density figures)
  // For the density figures: draw the instances the sampler makes points as polygons instead
  // (their reference), or not at all (what the rest hides); those it makes polygons stay.
  enum class Measure { off, their_polygons, without_them } measure = Measure::off;
  bool aliasing = false;  // fill the frame's aliasing target (the `aliasing` AOV, alias_p95)
  // The CPU sampler skips point casters whose shadows fall on nothing the last frame showed
  // (pointgen::ReceiverMask); the GPU sampler always selects casters by the frame's receivers.
  bool cull_casters = true;
  // The frame's points and polygons chosen on the GPU (GpuSampler); off: by the CPU's view sampler,
  // the GPU sampler's test oracle, which the density figures' measures also use.
  bool gpu_sampler = true;
  // A virtual paged map's pool of pages, in MiB of depths and silhouette points (--page-pool,
  // --method adaptive and adaptive+silhouette).
  int page_pool_mib = 256;
};

// Texels a side of the shadow map's layers: shadow_size, or for a virtual paged map the size of
// the maps its tiles are drawn into.
int map_texels(const RenderSettings& settings);

// The pages a pool of settings.page_pool_mib holds: layers of shadow::VirtualMap's page and guard,
// in the settings' depth format, and their silhouette points where the method has a silhouette map.
int page_pool_layers(const RenderSettings& settings);

// The settings with points off where the scene has no mesh that may be drawn as points: the same
// frames, without the point passes over nothing and their buffers' size limits (the benchmarks'
// settings; capture and view keep what they are given).
RenderSettings for_scene(RenderSettings settings, const Scene& scene);

}  // namespace ecoview
