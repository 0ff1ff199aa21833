#version 450 core
// Depth only: the depth test writes the map, where no alpha mask cuts the surface away.
#ifdef SURFACE_TEXTURES
#include "surface_texture.glsl"
in vec2 surface_uv;
flat in vec2 surface_material;
in float surface_keep_scale;

void main() {
  if (masked_away(surface_texel(surface_uv, surface_material.x), fragment_keep_scale(surface_material.y, surface_keep_scale))) discard;
}
#else
void main() {}
#endif
