// Iso-altitude lines: every sub-volume in its own pastel colour with dark contour lines
// every 1000 m of height on its surface, one pixel wide whatever the zoom (fwidth).
// Lines are drawn more opaque than the surface between them.

vec3 pastel(int id) {
  const vec3 colors[6] = vec3[](vec3(0.95, 0.95, 0.95), vec3(0.55, 0.75, 0.95),
                                vec3(0.95, 0.70, 0.45), vec3(0.60, 0.90, 0.60),
                                vec3(0.90, 0.60, 0.85), vec3(0.95, 0.90, 0.50));
  return colors[(id - 1 + 600) % 6];
}

vec4 color(int id, float attributes[MAX_ATTRIBUTES], vec3 normal, vec3 sun,
           vec3 position, vec3 view, float time) {
  float light = 0.4 + 0.6 * max(dot(normal, sun), 0.0);
  float h = height_m(position) / 1000.0;
  float distance_to_line = abs(fract(h + 0.5) - 0.5) / max(fwidth(h), 1e-6);
  float line = 1.0 - clamp(distance_to_line - 0.5, 0.0, 1.0);
  vec3 surface = pastel(id) * light;
  return vec4(mix(surface, vec3(0.08), line), mix(1.0, 3.0, line));
}

float alpha(int id, float distance) {
  return 1.0 - exp(-distance / 2.0);
}
