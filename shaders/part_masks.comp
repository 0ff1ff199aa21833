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
#include "plant_parts.glsl"
layout(local_size_x = 64) in;  // a part each

layout(std430, binding = 16) readonly buffer PolygonInstances { uint polygon_instances[]; };
layout(std430, binding = 26) writeonly buffer PartMasks { uvec2 part_masks[]; };

uniform mat4 view_projection;
uniform bool occlusion;
uniform vec2 pixels;  // the view's image

// A work group per polygon plant of the band, which sample_draws.comp listed after those of the
// bands before (their end, polygon_count, is this band's too: sample_groups.comp added it).
void main() {
  uint slot = band_polygons().x + group_number();
  if (slot >= polygon_count) return;
  uint i = polygon_instances[slot];
  uvec2 kept = parts_kept(view_projection, pixels, instance_model(i), plant_mesh(i), false, occlusion);
  if (gl_LocalInvocationID.x == 0u) part_masks[slot] = kept;
}
