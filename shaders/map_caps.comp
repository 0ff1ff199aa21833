#version 450 core
// Per point draw of the GPU sampler's list (made for the camera), the most points a shadow view
// takes of it: of a plant, no more than the view asks (points_a_map_asks, k a texel), the first
// ones of its list, which are a uniform subset. Near the eye a coarse map's texel holds many of
// the camera's points, and a texel any point of a leaf falls in is shadowed whole; thinned to the
// map's density, a texel is shadowed about as often as leaves cover it, as by a sampling made for
// the map (the casters' bands are counted so: sample_count.comp, cap_to_map).
#include "sample_common.glsl"
#include "point_draws.glsl"
layout(local_size_x = 256) in;

layout(std430, binding = 35) writeonly buffer MapCaps { uint map_caps[]; };
uniform mat4 map_view_projection;
uniform float map_texels;
uniform float k;  // none: every point (a paraboloid view)

void main() {
  uint d = gl_GlobalInvocationID.x;
  if (d >= draw_count) return;
  uvec4 draw = draw_at(d);
  if (k <= 0.0) {
    map_caps[d] = draw.y;
    return;
  }
  mat4 model = instance_model(draw.w);
  SampledMesh mesh = plant_mesh(draw.w);
  vec3 center = (model * vec4(mesh.center_radius.xyz, 1.0)).xyz;
  float scale = model_scale(model);
  float asked = points_a_map_asks(map_view_projection, map_texels, k, center, mesh.half_size_area.w * scale * scale);
  map_caps[d] = min(draw.y, uint(floor(asked + plant_rounding(draw.w))));
}
