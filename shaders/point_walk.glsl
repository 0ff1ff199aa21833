// The body of the splat compute passes that project points: each thread projects its points and
// calls VISIT(pixel index, depth, point) for the pixels of each one's splat (with MAP_CAP, only of
// the points a shadow map takes). The including shader defines VISIT first, and may define
// PROJECTED(point, draw, world, ndc, corner, depth), called once per point on the target with its
// draw, world position, normalized device coordinates and splat's lower-left pixel, and
// OUTSIDE(point) once per point off it.
#include "point_threads.glsl"

#ifndef PROJECTED
#define PROJECTED(point, draw, world, ndc, corner, depth)
#endif
#ifndef OUTSIDE
#define OUTSIDE(point)
#endif

uniform mat4 view_projection;  // for a paraboloid shadow view, its world → light space matrix
uniform vec2 paraboloid;        // a paraboloid view's zoom and range; zoom 0 for a projective view
uniform float depth_bias;  // added to window depth (shadow maps)

#include "paraboloid.glsl"

#ifdef MAP_CAP
// A shadow map drawing a GPU sampler's list takes of each draw no more points than its cap
// (map_caps.comp), and sums the points it drew.
layout(std430, binding = 35) readonly buffer MapCaps { uint map_caps[]; };
layout(std430, binding = 30) buffer MapPoints { uint map_points_drawn; };
uint points_drawn(uint draw, uvec4 d) { return map_caps[draw]; }
#define COUNT_DRAWN(points) atomicAdd(map_points_drawn, points)
#else
uint points_drawn(uint draw, uvec4 d) { return d.y; }
#define COUNT_DRAWN(points)
#endif

void main() {
  uvec2 run = thread_points();
  if (run.x >= run.y) return;
  uint draw = draw_of(run.x);
  uvec4 d = draw_at(draw);
  uint drawn = points_drawn(draw, d);
  uint kept = 0u;
  for (uint p = run.x; p < run.y; ++p) {
    while (p >= d.x + d.y) {
      d = draw_at(++draw);
      drawn = points_drawn(draw, d);
    }
    if (p - d.x >= drawn) continue;
    ++kept;
    vec4 world = instance_model(d.w) * vec4(sample_position(d.z + (p - d.x)), 1.0);
    vec4 clip = paraboloid.x == 0.0 ? view_projection * world : paraboloid_clip(view_projection, paraboloid, world.xyz);
    // Written to be false for NaN too (a GPU may turn a NaN corner into pixel 0).
    vec3 ndc = clip.xyz / clip.w;
    if (!(clip.w > 0.0) || !all(lessThanEqual(abs(ndc), vec3(1.0)))) {
      OUTSIDE(p);
      continue;
    }
    // Window depth is a non-negative float, whose bits order like the values: atomicMin on uint.
    uint depth = floatBitsToUint(clamp(ndc.z * 0.5 + 0.5 + depth_bias, 0.0, 1.0));
    ivec2 corner = ivec2(floor((ndc.xy * 0.5 + 0.5) * vec2(target_size) - 0.5 * float(splat_size - 1)));
    PROJECTED(p, d, world.xyz, ndc.xy, corner, depth);
    for (int y = 0; y < splat_size; ++y) {
      for (int x = 0; x < splat_size; ++x) {
        uint pixel = splat_pixel(corner, x, y);
        if (pixel != no_point) VISIT(pixel, depth, p);
      }
    }
  }
  COUNT_DRAWN(kept);
}
