#version 450 core
// Pass 3 of point splatting: each pixel's point becomes the frame's surface there where the depth
// test finds it in front of the polygons, written as surface.frag writes a polygon's but into the
// points' own targets (frame_surface.glsl picks between the two). The point
// is the nearest of those whose centre falls in the pixel, else the nearest whose splat reaches
// it: a splat's nearest point shows the front of a tuft or crown over its neighbours' pixels too,
// darker than the surface there on the default view (docs/point_density.md). Its albedo's alpha is
// the share of the pixel the points' surfaces cover (point_coverage.glsl); shade.comp blends the
// surface behind into the rest.
#include "point_common.glsl"

layout(location = 0) out vec4 out_normal;
layout(location = 1) out vec4 out_albedo;
layout(location = 2) out float out_depth;

uniform mat4 view;
uniform vec3 camera_position;
uniform int splat_size;

// The image area of the point surfaces in this pixel: the entries of the splats that reach it,
// each spread over its splat's pixels (point_coverage.glsl).
float image_area(ivec2 pixel) {
  float sum = 0.0;
  for (int y = 0; y < splat_size; ++y) {
    for (int x = 0; x < splat_size; ++x) {
      ivec2 entry = pixel - ivec2(x, y) + coverage_margin;
      if (all(greaterThanEqual(entry, ivec2(0)))) sum += float(coverage[coverage_entry(entry)]);
    }
  }
  return sum / (coverage_steps * float(splat_size * splat_size));
}

// That area as the share of the pixel it covers, taking the surfaces as leaves strewn
// independently (Beer-Lambert, as for a canopy's leaf area): area a leaves gaps e^-a. Summing
// areas instead (capped at 1) counted the leaves behind others again and drew foliage denser than
// it is (docs/point_density.md, "Coverage").
float covered_share(ivec2 pixel) { return 1.0 - exp(-image_area(pixel)); }

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  uint index = uint(pixel.y * target_size.x + pixel.x);
  bool centred = centre_winners[index] != no_point;
  uint point = centred ? centre_winners[index] : winners[index];
  if (point == no_point) discard;
  uint draw = draw_of(point);
  uint s = sample_of(point, draw);
  uint instance = draw_samples[draw].y;
  mat4 model = instance_model(instance);
  vec3 position = (model * vec4(sample_position(s), 1.0)).xyz;
  vec3 n = normalize(mat3(model) * sample_normal(s).xyz);
  if (dot(n, camera_position - position) < 0.0) n = -n;
  gl_FragDepth = uintBitsToFloat(centred ? centre_depths[index] : depths[index]);
  out_normal = vec4(n, 0.0);
  out_albedo = vec4(sample_color(s) * instance_tint(instance), covered_share(pixel));
  out_depth = -(view * vec4(position, 1.0)).z;
}
