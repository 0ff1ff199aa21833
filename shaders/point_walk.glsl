// The body of the splat compute passes that project points: each thread projects its points and
// calls VISIT(pixel index, depth, point) for the pixels of each one's splat (with MAP_CAP, only of
// the points a shadow map asks). The including shader defines VISIT first, and may define
// PROJECTED(point, corner, depth), called once per point on the target with its splat's lower-left
// pixel, and OUTSIDE(point) once per point off it.
#include "point_threads.glsl"

#ifndef PROJECTED
#define PROJECTED(point, corner, depth)
#endif
#ifndef OUTSIDE
#define OUTSIDE(point)
#endif

uniform mat4 view_projection;  // for a paraboloid shadow view, its world → light space matrix
uniform vec2 paraboloid;        // a paraboloid view's zoom and range; zoom 0 for a projective view
uniform float depth_bias;  // added to window depth (shadow maps)

#include "paraboloid.glsl"

#ifdef MAP_CAP
// A projective shadow map drawing a GPU sampler's list (made for the camera): of each plant, no
// more points than the map asks (points_a_map_asks, k a texel), the first ones of its list,
// which are a uniform subset. Near the eye a coarse map's texel holds many of the camera's points,
// and a texel that any point of a leaf falls in is shadowed whole; thinned to the map's density, a
// texel is shadowed about as often as leaves cover it, as by a sampling made for the map.
#include "sampled_meshes.glsl"
layout(std430, binding = 30) buffer MapPoints { uint map_points_drawn; };  // the points drawn, summed
uniform float map_texels;
uniform float k;  // none: every point (a paraboloid view)
uint points_drawn(uvec4 draw) {
  if (k <= 0.0) return draw.y;
  mat4 model = instances[draw.w].model;
  SampledMesh mesh = meshes[plant_meshes[draw.w].x];
  vec3 center = (model * vec4(mesh.center_radius.xyz, 1.0)).xyz;
  float scale = model_scale(model);
  float asked = points_a_map_asks(view_projection, map_texels, k, center, mesh.half_size_area.w * scale * scale);
  return min(draw.y, uint(floor(asked + uintBitsToFloat(plant_meshes[draw.w].y))));
}
#define COUNT_DRAWN(points) atomicAdd(map_points_drawn, points)
#else
uint points_drawn(uvec4 draw) { return draw.y; }
#define COUNT_DRAWN(points)
#endif

void main() {
  uvec2 run = thread_points();
  if (run.x >= run.y) return;
  uint draw = draw_of(run.x);
  uvec4 d = draws[draw];
  uint drawn = points_drawn(d);
  uint kept = 0u;
  for (uint p = run.x; p < run.y; ++p) {
    while (p >= d.x + d.y) drawn = points_drawn(d = draws[++draw]);
    if (p - d.x >= drawn) continue;
    ++kept;
    vec4 world = instances[d.w].model * vec4(positions[d.z + (p - d.x)].xyz, 1.0);
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
    PROJECTED(p, corner, depth);
    for (int y = 0; y < splat_size; ++y) {
      for (int x = 0; x < splat_size; ++x) {
        uint pixel = splat_pixel(corner, x, y);
        if (pixel != no_point) VISIT(pixel, depth, p);
      }
    }
  }
  COUNT_DRAWN(kept);
}
