#version 450 core
// The GPU sampler's pass after a band's draws, for a band the frame shows: which polygon parts of
// each of its polygon plants the frame draws (a mesh's triangles by the cell of a 4 × 4 × 4 grid,
// pointgen::split_triangles, each part with the box of its triangles). A plant whose box covers
// more than pixels_to_split pixels draws the parts on screen that the bands before it leave to be
// seen (the depth pyramid: a part's box holds all of its triangles, so a part left out leaves no
// gap); a smaller one, or one that shows all of its parts, is drawn whole. As pointgen::sample_view
// draws a polygon instance.
#include "sample_common.glsl"
#include "depth_pyramid.glsl"
#include "plant_boxes.glsl"
#include "polygon_parts.glsl"
layout(local_size_x = 256) in;

layout(std430, binding = 26) writeonly buffer PartMasks { uvec2 part_masks[]; };

uniform mat4 view_projection;
uniform bool occlusion;
uniform vec2 pixels;  // the view's image

// The plant's parts the frame draws, a bit each; drawn_whole where that is all of them.
uvec2 parts_drawn(uint i) {
  mat4 model = instances[i].model;
  SampledMesh mesh = meshes[plant_meshes[i].x];
  vec3 lo, hi;
  if (mesh.polygon_parts.y == 0u || !box_rect(view_projection, model, mesh, lo, hi)) return drawn_whole;
  if (!(pixels_in(lo, hi, pixels) > pixels_to_split)) return drawn_whole;
  uvec2 drawn = uvec2(0u);
  for (uint p = 0u; p < mesh.polygon_parts.y; ++p) {
    PolygonPart part = polygon_parts[mesh.polygon_parts.x + p];
    if (!box_hidden(view_projection, model, part.center.xyz, part.half_size.xyz, occlusion)) drawn[p / 32u] |= 1u << (p % 32u);
  }
  uvec2 every = every_part(mesh.polygon_parts.y);
  return drawn == every ? drawn_whole : drawn;
}

void main() {
  uvec2 band = this_band();
  uint place = gl_GlobalInvocationID.x;
  if (place >= band.y) return;
  uint i = band_list[band.x + place];
  if (counts[i].z == 0u) return;
  part_masks[offsets[place].z + group_sums[place / plants_per_group].z] = parts_drawn(i);
}
