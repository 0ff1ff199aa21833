#version 450 core
// Where the silhouette edge crosses this cell: the middle of its piece inside the cell, as a
// position in the cell (0..1 each way), at the edge's depth there, so that of the edges crossing
// a cell the one nearest the light is kept (Sen, Cammarano and Hanrahan 2003). Cells the quad
// covers but the edge misses are left alone.
flat in vec2 edge_start, edge_end;  // cell coordinates (silhouette_edges.geom)
flat in float start_depth, end_depth;

layout(location = 0) out vec2 point_in_cell;

void main() {
  vec2 cell = floor(gl_FragCoord.xy);
  vec2 d = edge_end - edge_start;
  // Liang and Barsky: the parameters of the segment inside the cell's square.
  float enter = 0.0, leave = 1.0;
  for (int axis = 0; axis < 2; ++axis) {
    float lo = cell[axis] - edge_start[axis], hi = lo + 1.0;
    if (abs(d[axis]) < 1e-12) {
      if (lo > 0.0 || hi < 0.0) discard;
      continue;
    }
    float t0 = lo / d[axis], t1 = hi / d[axis];
    enter = max(enter, min(t0, t1));
    leave = min(leave, max(t0, t1));
  }
  if (enter > leave) discard;
  float t = 0.5 * (enter + leave);
  point_in_cell = clamp(edge_start + t * d - cell, 0.0, 1.0);
  gl_FragDepth = mix(start_depth, end_depth, t);
}
