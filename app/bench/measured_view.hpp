#pragma once
#include "app/bench/frame_timing.hpp"
#include "app/bench/results.hpp"
#include "app/reference/exact_visibility.hpp"
#include "app/render/renderer.hpp"
#include "app/scene/scene.hpp"

#include <optional>

namespace ecoview {

// The field's lights turn from along the view (0°: from behind the camera) to into it (180°) in
// steps of this many degrees, one light a step (data/scenes/field.json).
constexpr float field_light_step_deg = 15.0f;

// One view of a scene where `bench` takes its figures, with the scene's exact reference.
struct MeasuredView {
  const Scene& scene;
  ExactVisibility& exact;
  shadow::Camera camera;
  shadow::Light light;
  double t = 0.0;
};

// The figures of one frame of the view (docs/figures.md): err, err_near, acne, leak against the exact
// reference, alias_p95, the points and triangles drawn, and the times, each with its spread
// beside it ("frame_ms_spread"), where `timing` is given
// (else a frame at the same place first: the PSM takes its near plane from the last frame).
// Params: the renderer's shadow_setup, and the timed frames.
BenchRun measure_view(Renderer& renderer, const MeasuredView& view, const std::optional<FrameTiming>& timing = std::nullopt);

// The exact visibility of the frame the renderer last drew, for the view (its depth given).
Image8 exact_frame(const Renderer& renderer, const MeasuredView& view, const Image<float>& depth);

}  // namespace ecoview
