#pragma once
#include "app/render/image.hpp"

#include <cstdint>

namespace ecoview {

// The point-density figures of DESIGN.md, from a polygon render and a point render of the same
// point-rendered objects (nothing else drawn) and the point render's points per pixel.
struct DensityFigures {
  double holes = 0.0;            // covered by polygons, not by points, over covered pixels
  double psnr = 0.0;             // colour PSNR (dB) of points against polygons over covered pixels
  double pts_per_px = 0.0;       // points per covered pixel: mean
  double pts_per_px_cv = 0.0;    // and coefficient of variation over pixels
  double pts_per_px_near = 0.0;  // mean over covered pixels in the nearest third of their depth range
  double pts_per_px_middle = 0.0;
  double pts_per_px_far = 0.0;
  std::size_t covered = 0;
};

struct RenderedFrame {
  Image8 color;        // sRGB
  Image<float> depth;  // linear view depth, negative where nothing is drawn
};

// Colour PSNR (dB) of an image against a reference over the pixels the reference covers.
double psnr_over_covered(const RenderedFrame& reference, const Image8& image);

DensityFigures density_figures(const RenderedFrame& polygons, const RenderedFrame& points,
                               const Image<std::uint32_t>& counts);

}  // namespace ecoview
