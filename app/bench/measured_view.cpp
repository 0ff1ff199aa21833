#include "app/bench/measured_view.hpp"

#include "app/bench/shadow_figures.hpp"
#include "shadow/aliasing.hpp"

namespace ecoview {

BenchRun measure_view(Renderer& renderer, const MeasuredView& view, const std::optional<FrameTiming>& timing) {
  BenchRun run;
  if (timing) {
    run.figures.update({{"frame_ms", timing->frame_ms}, {"sample_ms", timing->sample_ms}, {"host_ms", timing->host_ms},
                        {"shadow_pass_ms", timing->shadow_pass_ms}, {"frame_pass_ms", timing->frame_pass_ms},
                        {"frame_ms_spread", timing->frame_ms_spread}, {"sample_ms_spread", timing->sample_ms_spread},
                        {"host_ms_spread", timing->host_ms_spread}, {"shadow_pass_ms_spread", timing->shadow_pass_ms_spread},
                        {"frame_pass_ms_spread", timing->frame_pass_ms_spread}});
    run.params["frames"] = timing->frames;
  } else {
    renderer.render(view.camera, view.light, view.t);
  }
  renderer.set_aliasing(true);
  renderer.render(view.camera, view.light, view.t);
  renderer.set_aliasing(false);
  const Image<float> depth = renderer.frame().read_depth();
  const Image8 visibility = renderer.frame().read_visibility();
  const ShadowErrors e = shadow_errors(visibility, exact_frame(renderer, view, depth), depth);
  run.figures.update({{"err", e.err}, {"err_near", e.err_near}, {"acne", e.acne}, {"leak", e.leak},
                      {"alias_p95", alias_percentile(renderer.frame().read_aliasing(), visibility, shadow::p95_fraction)},
                      {"points", renderer.stats().points}, {"triangles", renderer.stats().triangles},
                      {"shadow_points", renderer.stats().shadow_points}, {"shadow_triangles", renderer.stats().shadow_triangles}});
  run.params["shadow_setup"] = renderer.shadow_setup().description;
  return run;
}

Image8 exact_frame(const Renderer& renderer, const MeasuredView& view, const Image<float>& depth) {
  view.exact.pose(renderer.tables());
  return view.exact.trace(view.camera, view.light, depth);
}

}  // namespace ecoview
