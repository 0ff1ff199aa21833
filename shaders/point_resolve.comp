#version 450 core
// Pass 2 of point splatting: per pixel, the point with the nearest depth (the lowest index among
// equals, so the result does not depend on thread order), from where pass 1 put each point; and
// how much of the pixel the points in front of the polygons cover (point_surface.frag).
//
// Coverage: each point stands for its share of its list's surface (the list's area over the
// points drawn of it), which covers rho² share |n·v| d / z³ pixels of the image
// (docs/point_density.md); its splat spreads that over its pixels. A pixel's sum is the image
// area of the surfaces in it, whole where it reaches one. In 1/256 of a pixel, for integer atomics.
#include "point_common.glsl"
#include "point_threads.glsl"

layout(binding = 5) uniform sampler2D polygon_depths;  // window depth of the polygons drawn
uniform bool polygons_drawn;  // otherwise no polygon hides a point
uniform vec3 eye;
uniform vec3 forward;
uniform float pixels_per_radian;

const float coverage_steps = 256.0;  // point_surface.frag

bool in_front_of_polygons(uint pixel, uint depth) {
  if (!polygons_drawn) return true;
  ivec2 at = ivec2(int(pixel % uint(target_size.x)), int(pixel / uint(target_size.x)));
  return depth < floatBitsToUint(texelFetch(polygon_depths, at, 0).r);
}

// The image area point p of draw d stands for, in pixels.
float image_area(uint p, uvec4 d) {
  uint s = d.z + (p - d.x);
  mat4 model = instances[d.w].model;
  vec3 world = (model * vec4(positions[s].xyz, 1.0)).xyz;
  vec3 to_eye = eye - world;
  float distance = length(to_eye);
  float z = max(-dot(to_eye, forward), 1e-3);
  vec3 n = mat3(model) * normals[s].xyz;  // as long as the model's scale
  float share = normals[s].w * dot(n, n) / float(d.y);
  float facing = abs(dot(normalize(n), to_eye)) / max(distance, 1e-6);
  return pixels_per_radian * pixels_per_radian * share * facing * distance / (z * z * z);
}

void main() {
  uvec2 run = thread_points();
  if (run.x >= run.y) return;
  uint draw = draw_of(run.x);
  uvec4 d = draws[draw];
  float spread = 1.0 / float(splat_size * splat_size);
  for (uint p = run.x; p < run.y; ++p) {
    while (p >= d.x + d.y) d = draws[++draw];
    uvec2 at = projected[p];
    if (at.y == no_point) continue;
    uint cover = uint(round(min(image_area(p, d) * spread, 1.0) * coverage_steps));
    ivec2 corner = ivec2(bitfieldExtract(int(at.x), 0, 16), bitfieldExtract(int(at.x), 16, 16));
    for (int y = 0; y < splat_size; ++y) {
      for (int x = 0; x < splat_size; ++x) {
        uint pixel = splat_pixel(corner, x, y);
        if (pixel == no_point) continue;
        if (depths[pixel] == at.y) atomicMin(winners[pixel], p);
        if (in_front_of_polygons(pixel, at.y)) atomicAdd(coverage[pixel], cover);
      }
    }
  }
}
