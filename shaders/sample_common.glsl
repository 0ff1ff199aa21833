// The GPU sampler's buffers (app/render/gpu_sampler.hpp): the plants resident on the GPU, what it
// knows of their meshes, and per plant its count and its place in the frame's draw list.
struct Instance {
  mat4 model;
  vec4 tint;
};
struct SampledMesh {
  vec4 center_radius;   // of its bounds, in the mesh's frame
  vec4 area;            // x: surface area, square metres
  vec4 moments[3];      // columns of the mean n nᵀ of its samples' normals (zero: facing every way)
  uvec4 sizes;          // triangles, samples, its list's first sample among all meshes', 0
};
layout(std430, binding = 2) readonly buffer Instances { Instance instances[]; };
layout(std430, binding = 10) readonly buffer PlantMeshes { uvec2 plant_meshes[]; };  // mesh, rounding's float bits
layout(std430, binding = 11) readonly buffer SampledMeshes { SampledMesh meshes[]; };
// Per plant: its points and whether it is drawn as polygons; then its exclusive prefix sums of
// points and of plants with points, within its work group until the last pass adds the groups'.
layout(std430, binding = 12) buffer Counts { uvec2 counts[]; };
layout(std430, binding = 13) buffer Offsets { uvec2 offsets[]; };
layout(std430, binding = 14) buffer GroupSums { uvec2 group_sums[]; };

uniform uint plant_count;

const uint plants_per_group = 1024u;  // 256 threads of 4 plants (app/render/gpu_sampler.cpp)
