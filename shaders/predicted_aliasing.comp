#version 450 core
// --method auto's prediction (FramePass::predict_aliasing): a candidate setup's aliasing factor
// (shadow_views.glsl, as the `aliasing` AOV has it) at every `pixel_step`-th pixel of the last frame's
// surfaces that face the light, counted into a histogram of log2 of it: `bins_per_octave` bins an
// octave from 2^lowest_octave up, the first bin holding all below, the last all above (where the
// light grazes the surface).
layout(local_size_x = 8, local_size_y = 8) in;
#include "frame_surface.glsl"
layout(std430, binding = 27) buffer Histograms { uint bins[]; };
uniform int pixel_step;
uniform uint first_bin;  // this candidate's histogram in `bins`
uniform uint bin_count;
uniform float bins_per_octave;
uniform float lowest_octave;

#include "shadow_views.glsl"
#include "surface_position.glsl"

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy) * pixel_step + pixel_step / 2;
  if (any(greaterThanEqual(pixel, ivec2(frame_size)))) return;
  Surface surface = frame_surface(pixel);
  float depth = surface.depth;
  if (!(depth > 0.0)) return;
  vec3 position = surface_position(vec2(pixel) + 0.5, depth);
  vec3 n = surface.normal;
  vec3 to_light = direction_to_light(position);
  if (!(dot(n, to_light) > 0.0)) return;
  float octaves = log2(max(aliasing_factor(position, n), 1e-30)) - lowest_octave;
  uint bin = uint(clamp(floor(octaves * bins_per_octave), 0.0, float(bin_count - 1u)));
  atomicAdd(bins[first_bin + bin], 1u);
}
