// The body of the splat compute passes: each thread projects a run of consecutive points and
// calls VISIT(pixel index, depth, point) for the splat_size x splat_size pixels each covers.
// The including shader defines VISIT first.
layout(local_size_x = 64) in;

uniform mat4 view_projection;  // for a paraboloid shadow view, its world → light space matrix
uniform vec2 paraboloid;        // a paraboloid view's zoom and range; zoom 0 for a projective view
uniform uint total_points;
uniform uint first_thread;  // dispatches are split to stay within the work-group count limit
uniform int splat_size;
uniform float depth_bias;  // added to window depth (shadow maps)

const uint points_per_thread = 16u;

#include "paraboloid.glsl"

void main() {
  uint first = (first_thread + gl_GlobalInvocationID.x) * points_per_thread;
  if (first >= total_points) return;
  uint draw = draw_of(first);
  uvec4 d = draws[draw];
  uint last = min(first + points_per_thread, total_points);
  for (uint p = first; p < last; ++p) {
    while (p >= d.x + d.y) d = draws[++draw];
    vec4 world = instances[d.w].model * vec4(positions[d.z + (p - d.x)].xyz, 1.0);
    vec4 clip = paraboloid.x == 0.0 ? view_projection * world : paraboloid_clip(view_projection, paraboloid, world.xyz);
    if (clip.w <= 0.0) continue;
    vec3 ndc = clip.xyz / clip.w;
    if (any(greaterThan(abs(ndc), vec3(1.0)))) continue;
    // Window depth is a non-negative float, whose bits order like the values: atomicMin on uint.
    uint depth = floatBitsToUint(clamp(ndc.z * 0.5 + 0.5 + depth_bias, 0.0, 1.0));
    ivec2 corner = ivec2(floor((ndc.xy * 0.5 + 0.5) * vec2(target_size) - 0.5 * float(splat_size - 1)));
    for (int y = 0; y < splat_size; ++y) {
      for (int x = 0; x < splat_size; ++x) {
        ivec2 pixel = corner + ivec2(x, y);
        if (any(lessThan(pixel, ivec2(0))) || any(greaterThanEqual(pixel, target_size))) continue;
        VISIT(uint(pixel.y * target_size.x + pixel.x), depth, p);
      }
    }
  }
}
