// A polygon's base-colour texture and alpha mask (SurfaceTextures::vertex_surfaces). Per vertex:
// its texture coordinate, a code (the texture's layer + 1, 0 for none, plus 256 × (3 × wrap s +
// wrap t), each wrap 0 repeat, 1 clamp, 2 mirror, plus 4096 where it is magnified nearest), and
// the mask's keep scale (pointgen::SurfaceMaterial::keep_scale: -1 for no mask), which varies with
// the vertex colours' alpha. Without a texture the texel is white and opaque.
layout(binding = 15) uniform sampler2DArray surface_textures;

float wrapped(float x, int mode, float half_texel) {
  if (mode == 1) return clamp(x, half_texel, 1.0 - half_texel);
  if (mode == 2) return 1.0 - abs(mod(x, 2.0) - 1.0);
  return x;  // the sampler repeats
}

// The texel at `uv` with the coordinate's derivatives `dx` and `dy` (which pick the level: 0, 0
// the full-size one).
vec4 surface_texel_grad(vec2 uv, float code, vec2 dx, vec2 dy) {
  int c = int(code + 0.5);
  int layer = (c & 255) - 1;
  if (layer < 0) return vec4(1.0);
  int wrap = (c >> 8) & 15;
  vec2 size = vec2(textureSize(surface_textures, 0).xy);
  float half_texel = 0.5 / size.x;
  vec2 w = vec2(wrapped(uv.x, wrap / 3, half_texel), wrapped(uv.y, wrap % 3, half_texel));
  // Magnified (GL's level of detail at most 0: a pixel spans at most a texel), a nearest image
  // shows the texel the coordinate falls in.
  if ((c & 4096) != 0 && max(dot(dx * size, dx * size), dot(dy * size, dy * size)) <= 1.0) {
    return textureLod(surface_textures, vec3((floor(w * size) + 0.5) / size, float(layer)), 0.0);
  }
  return textureGrad(surface_textures, vec3(w, float(layer)), dx, dy);
}

// Whether the mask cuts the surface away where it shows `texel`.
bool masked_away(vec4 texel, float keep_scale) { return keep_scale >= 0.0 && texel.a * keep_scale < 1.0; }

// The keep scale at a fragment from its provoking vertex's and the interpolated one: the
// interpolated where the vertex colours' alpha varies across the triangle, else the provoking
// vertex's exactly. Interpolating equal values can leave them a few units in the last place off,
// which would cut away a texel whose alpha is exactly the cutoff, or a plain opaque surface.
float fragment_keep_scale(float provoking, float interpolated) {
  return abs(interpolated - provoking) <= 1e-5 * abs(provoking) ? provoking : interpolated;
}

// The texel a fragment shows, filtered over its footprint.
vec4 surface_texel(vec2 uv, float code) {
  return surface_texel_grad(uv, code, dFdx(uv), dFdy(uv));  // of the unwrapped coordinate, before any branch
}
