// A point list's draws (app/render/point_splat.hpp) in two lists of uvec2 rather than one of uvec4,
// so that each stays within the 128 MiB a buffer llvmpipe's shaders address at 10^7 plants: per
// draw its points (first point, count) and its samples (first sample, instance).
layout(std430, binding = 1) buffer DrawPoints { uvec2 draw_points[]; };
layout(std430, binding = 10) buffer DrawSamples { uvec2 draw_samples[]; };

// (first point, count, first sample, instance) of draw d.
uvec4 draw_at(uint d) { return uvec4(draw_points[d], draw_samples[d]); }
