#pragma once
#include "app/render/image.hpp"

#include <vector>

namespace ecoview {

// How close an 8-bit sRGB image (3 channels) is to a reference of the same size, over the pixels
// marked in `pixels` (row by row).

// Colour PSNR (dB): over the marked pixels' red, green and blue samples; 99 where they are equal.
double psnr_over(const std::vector<bool>& pixels, const Image8& reference, const Image8& image);

// The mean structural similarity of Wang, Bovik, Sheikh and Simoncelli (2004) over the marked
// pixels: on 8-bit luminance (0.299 R + 0.587 G + 0.114 B), with an 11 × 11 Gaussian window of
// σ = 1.5 pixels, cut at the image's edges (and its weights scaled up to 1 there), C1 = (0.01 ·
// 255)², C2 = (0.03 · 255)². 1 for equal images.
double ssim_over(const std::vector<bool>& pixels, const Image8& reference, const Image8& image);

// The image made `factor` times smaller in each direction, each pixel the mean light of its
// factor × factor samples (averaged in linear light, as the eye adds light, then sRGB again):
// a render at factor² samples a pixel, resolved. The image's sides must be multiples of `factor`.
Image8 box_filtered(const Image8& image, int factor);

}  // namespace ecoview
