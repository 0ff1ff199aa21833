#version 450 core
// Pass 3 of point splatting: each pixel's nearest point becomes the frame's surface there (as
// surface.frag writes a polygon's), at the point's depth, so the depth test composites points and
// polygons. Its albedo's alpha is the share of the pixel the points' surfaces cover
// (point_resolve.comp); shade.frag blends the surface behind into the rest.
#include "point_common.glsl"

layout(location = 0) out vec4 out_normal;
layout(location = 1) out vec4 out_albedo;
layout(location = 2) out float out_depth;

uniform mat4 view;
uniform vec3 camera_position;

// A pixel's image area of point surfaces (point_resolve.comp) as the share of it they cover, taking
// them as leaves strewn independently (Beer-Lambert, as for a canopy's leaf area): a surface
// covers a pixel's area a with gaps e^-a. Summing shares instead (capped at 1) counted the leaves
// behind others again and drew foliage denser than it is (docs/point_density.md, "Coverage").
float covered_share(uint area) { return 1.0 - exp(-float(area) / 256.0); }

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  uint index = uint(pixel.y * target_size.x + pixel.x);
  uint point = winners[index];
  if (point == no_point) discard;
  uint draw = draw_of(point);
  uint s = sample_of(point, draw);
  Instance instance = instances[draws[draw].w];
  vec3 position = (instance.model * vec4(positions[s].xyz, 1.0)).xyz;
  vec3 n = normalize(mat3(instance.model) * normals[s].xyz);
  if (dot(n, camera_position - position) < 0.0) n = -n;
  gl_FragDepth = uintBitsToFloat(depths[index]);
  out_normal = vec4(n, 0.0);
  out_albedo = vec4(colors[s].rgb * instance.tint.rgb, covered_share(coverage[index]));
  out_depth = -(view * vec4(position, 1.0)).z;
}
