// Iso-altitude lines: every sub-volume in its palette colour (subvolume_color(id),
// docs/view.md "User shaders") with dark contour lines every 1000 m of height on its
// surface, one pixel wide whatever the zoom (fwidth). Lines are drawn more opaque than the
// surface between them.

vec4 color(int id, float attributes[MAX_ATTRIBUTES], vec3 normal, vec3 sun,
           vec3 position, vec3 view, float time) {
  float light = 0.4 + 0.6 * max(dot(normal, sun), 0.0);
  float h = height_m(position) / 1000.0;
  float distance_to_line = abs(fract(h + 0.5) - 0.5) / max(fwidth(h), 1e-6);
  float line = 1.0 - clamp(distance_to_line - 0.5, 0.0, 1.0);
  vec3 surface = subvolume_color(id) * light;
  return vec4(mix(surface, vec3(0.08), line), mix(1.0, 3.0, line));
}

float alpha(int id, float distance) {
  return 1.0 - exp(-distance / 2.0);
}
