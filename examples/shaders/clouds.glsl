// Soft, sun-lit clouds (the default shader of strielad-view; docs/view.md "User shaders").
// Every sub-volume is a pale tint of its palette colour, subvolume_color(id): the first
// sub-volume of the scene white (cloud water in the default scene), the next a pale sky
// blue (cloud ice), pale orange, pale bluish green... so they stay told apart.
// Light: the sun wrapped around the surface (sides turned away from it are dimmer, never
// black), blue light from the sky from above, and a forward-scattering glow where the
// eye looks towards the sun through the cloud. The shading differs little between faces,
// so the mesh's level steps do not read as hard-edged slabs.
// Opacity grows with the distance a ray travels inside the sub-volume (Beer-Lambert,
// 50% after 4 km, 90% after 13 km): thin layers and cloud edges let the terrain show
// through, deep cores turn nearly opaque.

const float kHalfOpacityKm = 4.0;  // the distance that hides half of what lies behind
const float kTint = 0.4;           // how much of the palette colour tints the white

vec4 color(int id, float attributes[MAX_ATTRIBUTES], vec3 normal, vec3 sun,
           vec3 position, vec3 view, float time) {
  vec3 base = mix(vec3(1.0), subvolume_color(id), kTint);
  float day = smoothstep(-0.05, 0.15, sun.z);  // 0 with the sun below the horizon
  float wrap = clamp((dot(normal, sun) + 0.7) / 1.7, 0.0, 1.0);
  vec3 sky = vec3(0.62, 0.70, 0.84) * (0.40 + 0.12 * normal.z) * (0.3 + 0.7 * day);
  vec3 sunlight = vec3(1.0, 0.97, 0.92) * (0.15 + 0.60 * wrap) * day;
  float forward = pow(max(dot(-view, sun), 0.0), 6.0) * 0.30 * day;
  return vec4(base * (sky + sunlight + forward), 1.0);
}

float alpha(int id, float distance) {
  return 1.0 - exp(-distance * (0.693147 / kHalfOpacityKm));
}
