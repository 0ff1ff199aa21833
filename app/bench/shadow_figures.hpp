#pragma once
#include "app/render/image.hpp"

namespace ecoview {

// A percentile (`fraction`) of the aliasing factor over the lit receiver pixels (a surface drawn,
// visibility >= 0.5); 0 where there are none. At shadow::p95_fraction, alias_p95 (docs/figures.md).
double alias_percentile(const Image<float>& aliasing, const Image8& visibility, float fraction);

// The shadow's errors against the exact reference (docs/figures.md), as fractions of the pixels that
// show a surface (linear view depth > 0): `err` where the binary states (visibility < 0.5)
// differ, `acne` where the reference is lit and the frame shadowed, `leak` the other way round
// (err = acne + leak); `err_near` is err over the pixels in the nearest 20 % of the frame's
// view-depth range (nearest to farthest surface).
struct ShadowErrors {
  double err = 0.0, err_near = 0.0, acne = 0.0, leak = 0.0;
};
ShadowErrors shadow_errors(const Image8& visibility, const Image8& reference, const Image<float>& depth);

// The fraction of surface pixels whose binary shadow state changed from one frame to the next:
// the part of `flicker` (docs/figures.md) of one frame pair (flicker subtracts the reference's).
double changed_shadow(const Image8& before, const Image8& after, const Image<float>& depth);

// `temporal_err`: the fraction of surface pixels whose shadow state changed from one frame to the
// next where the reference's did not, or stayed where the reference's changed. `flicker` nets the
// two rates, so a method that changes as often as the reference, in other pixels, scores 0 there;
// this counts each pixel that changes otherwise than the truth.
double temporal_err(const Image8& before, const Image8& after, const Image8& reference_before, const Image8& reference_after,
                    const Image<float>& depth);

}  // namespace ecoview
