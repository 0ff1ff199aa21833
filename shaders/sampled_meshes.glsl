// What the GPU sampler knows of each point mesh and of which mesh each plant is: for its own
// passes (sample_common.glsl) and for the shadow maps' splat (point_walk.glsl, MAP_CAP).
struct SampledMesh {
  vec4 center_radius;    // of its bounds, in the mesh's frame
  vec4 half_size_area;   // its bounds' half sizes; w: its surface area, square metres
  vec4 moments[3];       // columns of the mean n nᵀ of its samples' normals (zero: facing every way)
  uvec4 sizes;           // triangles, samples, its list's first sample among all meshes', 0
  uvec4 polygon_parts;   // its first polygon part among all meshes', their number (none: drawn whole), 0, 0
};
layout(std430, binding = 10) readonly buffer PlantMeshes { uvec2 plant_meshes[]; };  // mesh, rounding's float bits
layout(std430, binding = 11) readonly buffer SampledMeshes { SampledMesh meshes[]; };

// The uniform scale of a plant's model matrix.
float model_scale(mat4 model) { return pow(abs(determinant(mat3(model))), 1.0 / 3.0); }

// The points a shadow view of `texels` texels through `map_view_projection` asks of a plant whose
// bounds centre is `center` (world) and whose surface is `area` square metres: k per texel of half
// its area (a surface taken as facing every way), by the view's scale at the centre.
float points_a_map_asks(mat4 map_view_projection, float texels, float k, vec3 center, float area) {
  float w = (map_view_projection * vec4(center, 1.0)).w;
  vec3 row_x = vec3(map_view_projection[0][0], map_view_projection[1][0], map_view_projection[2][0]);
  vec3 row_y = vec3(map_view_projection[0][1], map_view_projection[1][1], map_view_projection[2][1]);
  float ndc_per_square_metre = length(row_x) * length(row_y) / (w * w);
  return k * 0.5 * area * ndc_per_square_metre * 0.25 * texels;
}
