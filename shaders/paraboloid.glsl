// shadow::ShadowView::clip for a paraboloid view (shadow/shadow_setup.hpp): `view` takes world
// space to light space, `paraboloid` is (zoom, range). Homogeneous, with w = 1 - d.z.
vec4 paraboloid_clip(mat4 view, vec2 paraboloid, vec3 world) {
  vec3 q = (view * vec4(world, 1.0)).xyz;
  float distance = length(q);
  vec3 d = distance > 0.0 ? q / distance : vec3(0.0, 0.0, -1.0);
  float w = 1.0 - d.z;
  return vec4(d.xy / paraboloid.x, (2.0 * distance / paraboloid.y - 1.0) * w, w);
}
