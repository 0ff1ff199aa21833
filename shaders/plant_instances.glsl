// The drawn plants' poses, five RGBA32F texels a plant in a buffer texture: the columns of its
// model matrix, then its tint. Read by texelFetch rather than from shader storage: llvmpipe loads
// shader storage lane by lane and component by component, about 9.5 ns a vec4 an invocation on
// this machine against 2.6 ns by texelFetch (docs/benchmarks.md); a GPU caches either.
layout(binding = 8) uniform samplerBuffer instances;

mat4 instance_model(uint i) {
  int first = int(i) * 5;
  return mat4(texelFetch(instances, first), texelFetch(instances, first + 1), texelFetch(instances, first + 2),
              texelFetch(instances, first + 3));
}
vec3 instance_tint(uint i) { return texelFetch(instances, int(i) * 5 + 4).rgb; }
