#pragma once
#include "app/render/image.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace ecoview {

// The point-density figures of docs/figures.md, over the pixels where the frame shows a point-rendered
// object, and the point render's points per pixel there.
struct DensityFigures {
  double holes = 0.0;            // covered by polygons, not by points, over covered pixels
  double pts_per_px = 0.0;       // points per covered pixel (the counts given): mean
  double pts_per_px_cv = 0.0;    // and coefficient of variation over pixels
  double pts_per_px_near = 0.0;  // mean over the nearest third of the covered pixels, by depth
  double pts_per_px_middle = 0.0;
  double pts_per_px_far = 0.0;
  std::array<float, 4> third_depths{};  // where the thirds begin and end: nearest, 1/3, 2/3, farthest
  std::size_t covered = 0;
};

struct RenderedFrame {
  Image8 color;        // sRGB
  Image<float> depth;  // linear view depth, negative where nothing is drawn
};

// The renders the figures compare, all with the instances the sampler draws as polygons: the
// frame (the rest as points), the polygon render (the rest as polygons), and those polygons alone,
// each of the objects drawn as points alone. The plants drawn as polygons hide what lies behind
// them in both renders alike. And the frame and the polygon render of the whole scene (its ground
// and sky behind the plants, as a user sees them), with `reference`: that polygon render at 4 × 4
// samples a pixel, resolved to the frame's size (box_filtered).
struct DensityRenders {
  RenderedFrame points, polygons, occluders;
  RenderedFrame points_in_scene, polygons_in_scene;
  Image8 reference;
};

// The pixels where the reference shows an object the frame draws as points: in front of the
// polygons drawn alone.
std::vector<bool> point_object_pixels(const RenderedFrame& polygons, const RenderedFrame& occluders);

// Where the figures are taken: the polygon render dimmed to a third, covered pixels in it at full
// brightness, holes among them red.
Image8 coverage_map(const DensityRenders& renders);

// `counts`: the point render's points per pixel (Renderer::count_points_on). Of the renders, the
// points, polygons and occluders.
DensityFigures density_figures(const DensityRenders& renders, const Image<std::uint32_t>& counts);

// Colour PSNR (dB) and SSIM of the whole frame against the resolved reference, over the pixels
// where the points or the polygons show an object drawn as points (and the ground does not hide
// it): of the points, and of the polygons at one sample a pixel (what an exact renderer without
// antialiasing scores). Of the renders, all.
struct FidelityFigures {
  double psnr = 0.0, ssim = 0.0;
  double psnr_polygons = 0.0, ssim_polygons = 0.0;
};
FidelityFigures fidelity_figures(const DensityRenders& renders);

}  // namespace ecoview
