#version 450 core
// The frame's first pass (deferred shading): the nearest polygon surface of each pixel, lit once
// per pixel by shade.comp, which finds its position from the depth. Plants' leaves are many triangles smaller than a pixel, and llvmpipe
// runs a fragment shader on a whole 4x4 block for each: lighting them here made the ecosystem's
// frame pass about 1.5 times as long (docs/benchmarks.md, "Deferred shading").
in vec3 world_normal;
in vec3 albedo;
in float view_depth;

#ifdef SURFACE_TEXTURES
#include "surface_texture.glsl"
in vec2 surface_uv;
flat in vec2 surface_material;
in float surface_keep_scale;
#endif

layout(location = 0) out vec4 out_normal;  // world, facing the viewer
layout(location = 1) out vec4 out_albedo;  // linear RGB
layout(location = 2) out float out_depth;  // linear view depth, metres (the `depth` AOV)

void main() {
  vec3 color = albedo;
#ifdef SURFACE_TEXTURES
  vec4 texel = surface_texel(surface_uv, surface_material.x);
  if (masked_away(texel, fragment_keep_scale(surface_material.y, surface_keep_scale))) discard;
  color *= texel.rgb;
#endif
  vec3 n = normalize(world_normal);
  if (!gl_FrontFacing) n = -n;  // thin surfaces are lit from either side
  out_normal = vec4(n, 0.0);
  out_albedo = vec4(color, 1.0);
  out_depth = view_depth;
}
