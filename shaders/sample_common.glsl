// The GPU sampler's buffers (app/render/gpu_sampler.hpp): the plants resident on the GPU, what it
// knows of their meshes, the frame's plants in view sorted into distance bands, and per plant its
// count and its place in the frame's lists.
struct SampledMesh {
  vec4 center_radius;    // of its bounds, in the mesh's frame
  vec4 half_size_area;   // its bounds' half sizes; w: its surface area, square metres
  vec4 moments[3];       // columns of the mean n nᵀ of its samples' normals (zero: facing every way)
  uvec4 sizes;           // triangles, samples, its list's first sample among all meshes', 0
  uvec4 polygon_parts;   // its first polygon part among all meshes', their number (none: drawn whole), 0, 0
};
#include "plant_instances.glsl"
// The meshes, seven RGBA32UI texels each (SampledMesh's fields in order, floats as their bits), and
// per plant its mesh and the threshold its count is rounded at (the float's bits), one RG32UI
// texel: buffer textures, read as the poses are (plant_instances.glsl) and for the same reason.
layout(binding = 12) uniform usamplerBuffer mesh_texels;
layout(binding = 13) uniform usamplerBuffer plant_mesh_texels;

SampledMesh sampled_mesh(uint m) {
  int first = int(m) * 7;
  SampledMesh mesh;
  mesh.center_radius = uintBitsToFloat(texelFetch(mesh_texels, first));
  mesh.half_size_area = uintBitsToFloat(texelFetch(mesh_texels, first + 1));
  for (int c = 0; c < 3; ++c) mesh.moments[c] = uintBitsToFloat(texelFetch(mesh_texels, first + 2 + c));
  mesh.sizes = texelFetch(mesh_texels, first + 5);
  mesh.polygon_parts = texelFetch(mesh_texels, first + 6);
  return mesh;
}
SampledMesh plant_mesh(uint i) { return sampled_mesh(texelFetch(plant_mesh_texels, int(i)).x); }
// A place in a landscape's pool that holds no plant this frame (GpuSampler::refill) has this mesh.
const uint no_plant = 0xFFFFFFFFu;
bool holds_plant(uint i) { return texelFetch(plant_mesh_texels, int(i)).x != no_plant; }
float plant_rounding(uint i) { return uintBitsToFloat(texelFetch(plant_mesh_texels, int(i)).y); }
// Per plant, once counted, in one uint (count_of): its points (bits 0-23; a mesh's list holds at
// most 2^17 samples), the number of its band from 1 (bits 24-29), whether drawn as polygons (bit
// 30) and whether hidden (bit 31: its box is behind what nearer bands drew); zero before.
layout(std430, binding = 12) buffer Counts { uint counts[]; };
struct Count {
  uint points;
  uint band;  // its number from 1; 0: not counted this frame
  bool polygons;
  bool hidden;
};
uint packed_count(uint points, uint band, bool polygons, bool hidden) {
  return points | (band << 24) | (polygons ? 1u << 30 : 0u) | (hidden ? 1u << 31 : 0u);
}
Count count_of(uint plant) {
  uint c = counts[plant];
  return Count(c & 0xFFFFFFu, (c >> 24) & 63u, (c & (1u << 30)) != 0u, (c >> 31) != 0u);
}
// Per place in the band being added: the exclusive prefix sums of (points, plants with points,
// plants as polygons) within its work group (in_group_offset; the plants' two in 16 bits each, a
// group holding 1,024), until the groups' sums (after the bands before) are added.
layout(std430, binding = 13) buffer Offsets { uvec2 offsets[]; };
void set_in_group_offset(uint place, uvec4 offset) { offsets[place] = uvec2(offset.x, offset.y | (offset.z << 16)); }
uvec4 in_group_offset(uint place) {
  uvec2 o = offsets[place];
  return uvec4(o.x, o.y & 0xFFFFu, o.y >> 16, 0u);
}
layout(std430, binding = 14) buffer GroupSums { uvec4 group_sums[]; };
// The lists' sizes: the points a splat draws (no more than its buffers hold), the point draws,
// where this band's points begin, the points of the bands the frame shows (the others are for
// shadow maps alone), all points, the polygon plants.
layout(std430, binding = 15) buffer Totals {
  uint total_points;
  uint draw_count;
  uint band_first_point;
  uint frame_points;
  uint all_points;
  uint polygon_count;
  uint part_plants_used;  // of the frame's lists of polygon plants by part (part_lists.comp)
};
// The plants in view, band after band, each band's in plant order; per band its first place in
// that list and its plants.
layout(std430, binding = 20) buffer BandList { uint band_list[]; };
layout(std430, binding = 21) buffer BandRanges { uvec2 band_ranges[]; };

uniform uint plant_count;
uniform uint band_number;  // the band being counted, from 1

const uint plants_per_group = 1024u;  // 256 threads of 4 plants (app/render/gpu_sampler.cpp)
const uint no_band = 0xFFFFFFFFu;

// The band's first place in the band list, and its plants.
uvec2 this_band() { return band_ranges[band_number - 1u]; }

// The band around break-even of points against polygons (pointgen/sampling/view_sampler.cpp).
const float band_low = 0.8, band_high = 1.25;

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

float facing(SampledMesh mesh, vec3 v) {
  mat3 moments = mat3(mesh.moments[0].xyz, mesh.moments[1].xyz, mesh.moments[2].xyz);
  if (!(moments[0][0] + moments[1][1] + moments[2][2] > 0.0)) return 0.5;
  return sqrt(max(dot(v, moments * v), 0.0));
}

// The points the view asks of a plant (docs/point_density.md): k per pixel of its surface as seen
// from the eye, by its bounds centre's distance and depth along `forward`.
float points_needed(mat4 model, SampledMesh mesh, vec3 eye, vec3 forward, float edge_cos, float pixels_per_radian, float k) {
  vec3 center = (model * vec4(mesh.center_radius.xyz, 1.0)).xyz;
  float scale = model_scale(model);
  float radius = mesh.center_radius.w * scale;
  float distance = max(length(eye - center), max(0.5 * radius, 1e-3));
  float depth = max(dot(center - eye, forward), distance * edge_cos);
  vec3 to_eye = inverse(mat3(model)) * (eye - center);
  float facing_eye = dot(to_eye, to_eye) > 0.0 ? facing(mesh, normalize(to_eye)) : 0.5;
  float z = max(depth, 1e-3);
  float area = mesh.half_size_area.w * scale * scale;
  return k * pixels_per_radian * pixels_per_radian * area * facing_eye * max(distance, z) / (z * z * z);
}

// A plant the view asks `needed` points of is drawn as polygons (too, within the band around
// break-even) where they would cost more than band_low times its triangles, or where its samples
// do not suffice.
float triangles_ratio(float needed, SampledMesh mesh, float points_per_triangle) {
  return needed / (points_per_triangle * float(mesh.sizes.x));
}
bool as_polygons(float needed, SampledMesh mesh, float points_per_triangle) {
  return triangles_ratio(needed, mesh, points_per_triangle) > band_low || needed > float(mesh.sizes.y);
}
