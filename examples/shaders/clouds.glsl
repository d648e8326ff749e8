// Clouds in the sub-volumes' own colours (the default shader of strielad-view).
// Every sub-volume is drawn in its palette colour, subvolume_color(id) (docs/view.md,
// "User shaders"): the first sub-volume of the scene white (cloud water in the
// default scene), the next sky blue, orange, bluish green... so no two look alike.
// Surfaces facing the sun are bright, those turned away are darker, as in the paper's
// cloud figures. Opacity grows with the distance a ray travels inside the sub-volume
// (Beer-Lambert, 50% after 1.5 km), so thin cloud edges stay translucent and deep cores
// turn opaque.

vec4 color(int id, float attributes[MAX_ATTRIBUTES], vec3 normal, vec3 sun,
           vec3 position, vec3 view, float time) {
  vec3 base = subvolume_color(id);
  float lit = max(dot(normal, sun), 0.0);
  // A little light from the sky and from the view direction keeps shaded sides legible.
  float light = 0.35 + 0.55 * lit + 0.10 * max(dot(normal, view), 0.0);
  return vec4(base * light, 1.0);
}

float alpha(int id, float distance) {
  return 1.0 - exp(-distance * (0.693 / 1.5));
}
