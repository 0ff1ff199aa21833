// Whether a polygon's alpha mask may cut it away anywhere, from its material (surface_texture.glsl:
// the code of its texture, then the mask's keep scale): a mask with a texture, or one whose scale
// the white texel of no texture falls short with. Without attribute 11 a vertex reads (0, 0, 0,
// 1): no texture, scale 1, never cut.
bool cut_by_mask(vec2 material) { return material.y >= 0.0 && (material.x >= 0.5 || material.y < 1.0); }
