#version 450 core
// Pass 2 of point splatting: per pixel, the point with the nearest depth (the lowest index among
// equals, so the result does not depend on thread order), and the same among the points whose
// centre falls in the pixel, from where pass 1 put each point.
#include "point_common.glsl"
#include "point_threads.glsl"

void main() {
  uvec2 run = thread_points();
  for (uint p = run.x; p < run.y; ++p) {
    uvec2 at = projected[p];
    if (at.y == no_point) continue;
    ivec2 corner = splat_corner(at.x), centre = splat_centre(at.x, splat_size);
    if (all(lessThan(centre, target_size))) {
      uint pixel = uint(centre.y * target_size.x + centre.x);
      if (centre_depths[pixel] == at.y) atomicMin(centre_winners[pixel], p);
    }
    for (int y = 0; y < splat_size; ++y) {
      for (int x = 0; x < splat_size; ++x) {
        uint pixel = splat_pixel(corner, x, y);
        if (pixel != no_point && depths[pixel] == at.y) atomicMin(winners[pixel], p);
      }
    }
  }
}
