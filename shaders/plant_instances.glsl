// The drawn plants' poses, four RGBA32F texels a plant in a buffer texture: the three rows of its
// affine model matrix (the translation in w), then its tint (app/render/plant_pose.hpp). Read by
// texelFetch rather than from shader storage: llvmpipe loads shader storage lane by lane and
// component by component, about 9.5 ns a vec4 an invocation on this machine against 2.6 ns by
// texelFetch (docs/benchmarks.md); a GPU caches either.
layout(binding = 8) uniform samplerBuffer instances;

mat4 instance_model(uint i) {
  int first = int(i) * 4;
  vec4 x = texelFetch(instances, first), y = texelFetch(instances, first + 1), z = texelFetch(instances, first + 2);
  return mat4(vec4(x.x, y.x, z.x, 0.0), vec4(x.y, y.y, z.y, 0.0), vec4(x.z, y.z, z.z, 0.0), vec4(x.w, y.w, z.w, 1.0));
}
vec3 instance_tint(uint i) { return texelFetch(instances, int(i) * 4 + 3).rgb; }
