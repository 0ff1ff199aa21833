#pragma once
#include "app/render/frame_pass.hpp"
#include "app/render/gpu_scene.hpp"
#include "app/render/shadow_pass.hpp"

#include <string>

namespace ecoview {

enum class ShadowMethod { none, uniform };

// Parses a --method name; throws InputError listing the methods this build renders.
ShadowMethod parse_shadow_method(const std::string& name);

struct RenderSettings {
  int width = 1280;
  int height = 720;
  int shadow_size = 2048;
  ShadowMethod method = ShadowMethod::uniform;
};

// One frame of a scene: the shadow pass for the chosen method, then the frame pass. Needs a
// current GL context.
class Renderer {
 public:
  Renderer(const Scene& scene, const RenderSettings& settings);
  // The frame at time t (seconds): moving objects are posed for t first.
  void render(const shadow::Camera& camera, const shadow::Light& light, double t = 0.0);
  const FramePass& frame() const { return frame_pass_; }

 private:
  const Scene& scene_;
  RenderSettings settings_;
  shadow::Box scene_bounds_;
  GpuScene gpu_scene_;
  ShadowPass shadow_pass_;
  shadow::ShadowSetup setup_;  // of the last frame
  FramePass frame_pass_;
};

}  // namespace ecoview
