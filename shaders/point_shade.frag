#version 450 core
// Pass 3 of point splatting: shades each pixel's nearest point like a polygon fragment, at the
// point's depth, so the depth test composites points and polygons.
#include "point_common.glsl"

layout(location = 0) out vec4 out_color;
layout(location = 1) out float out_visibility;
layout(location = 2) out float out_depth;
layout(location = 3) out float out_aliasing;

uniform mat4 view;

#include "lighting.glsl"

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
  Shading shading = shade(position, n, colors[s].rgb * instance.tint.rgb);
  gl_FragDepth = uintBitsToFloat(depths[index]);
  out_color = vec4(linear_to_srgb(shading.color), 1.0);
  out_visibility = shading.visibility;
  out_depth = -(view * vec4(position, 1.0)).z;
  out_aliasing = aliasing_factor(position, n);
}
