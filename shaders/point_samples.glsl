// The surface samples of the point meshes (app/render/point_samples.hpp) as RGBA32F buffer
// textures, read as the plants' poses are (plant_instances.glsl): position, normal with its list's
// area as w, colour.
layout(binding = 9) uniform samplerBuffer positions;
layout(binding = 10) uniform samplerBuffer normals;
layout(binding = 11) uniform samplerBuffer colors;

vec3 sample_position(uint s) { return texelFetch(positions, int(s)).xyz; }
vec4 sample_normal(uint s) { return texelFetch(normals, int(s)); }
vec3 sample_color(uint s) { return texelFetch(colors, int(s)).rgb; }
