#version 450 core
// Cuts each edge into pieces of at most 2 degrees as the light sees them (Osman et al. 2006,
// Vanek et al. 2011, Sect. 4): a piece's midpoint then strays well under a texel from the curve the
// paraboloid bends the edge into, in a 2048 map.
layout(vertices = 3) out;

in vec3 world_position[];
out vec3 patch_position[];
#ifdef SURFACE_TEXTURES
in vec4 vertex_surface[];
out vec4 patch_surface[];
#endif

uniform mat4 light_view;

const float piece_angle = radians(2.0);
const float max_pieces = 64.0;  // GL's guaranteed tessellation limit

float pieces(int a, int b) {
  vec3 qa = (light_view * vec4(world_position[a], 1.0)).xyz;
  vec3 qb = (light_view * vec4(world_position[b], 1.0)).xyz;
  float cos_angle = dot(qa, qb) / max(length(qa) * length(qb), 1e-20);
  return clamp(ceil(acos(clamp(cos_angle, -1.0, 1.0)) / piece_angle), 1.0, max_pieces);
}

void main() {
  patch_position[gl_InvocationID] = world_position[gl_InvocationID];
#ifdef SURFACE_TEXTURES
  patch_surface[gl_InvocationID] = vertex_surface[gl_InvocationID];
#endif
  if (gl_InvocationID == 0) {
    // Outer level i is the edge opposite corner i.
    gl_TessLevelOuter[0] = pieces(1, 2);
    gl_TessLevelOuter[1] = pieces(2, 0);
    gl_TessLevelOuter[2] = pieces(0, 1);
    gl_TessLevelInner[0] = max(gl_TessLevelOuter[0], max(gl_TessLevelOuter[1], gl_TessLevelOuter[2]));
  }
}
