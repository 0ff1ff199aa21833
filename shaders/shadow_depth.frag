#version 450 core
// Depth only: the depth test writes the map, where no alpha mask cuts the surface away.
#ifdef SURFACE_TEXTURES
#include "surface_texture.glsl"
in vec2 surface_uv;
flat in vec2 surface_material;

void main() {
  if (surface_texel(surface_uv, surface_material.x).a < surface_material.y) discard;
}
#else
void main() {}
#endif
