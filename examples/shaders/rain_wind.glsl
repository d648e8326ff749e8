// Rain coloured by wind speed: the scene's first two attributes are taken as the
// horizontal wind components (e.g. "attributes": ["ua", "va"]). Calm air is blue,
// 15 m/s green-yellow, 30 m/s and more red. Other sub-volumes are drawn in faint white.

vec3 speed_ramp(float t) {
  t = clamp(t, 0.0, 1.0);
  return t < 0.5 ? mix(vec3(0.10, 0.35, 0.95), vec3(0.55, 0.90, 0.25), t * 2.0)
                 : mix(vec3(0.55, 0.90, 0.25), vec3(0.95, 0.15, 0.10), t * 2.0 - 1.0);
}

vec4 color(int id, float attributes[MAX_ATTRIBUTES], vec3 normal, vec3 sun,
           vec3 position, vec3 view, float time) {
  float light = 0.45 + 0.55 * max(dot(normal, sun), 0.0);
  if (id != 1) return vec4(vec3(0.95) * light, 0.5);
  float u = attributes[0], v = attributes[1];
  if (missing(u) || missing(v)) return vec4(vec3(0.6) * light, 1.0);
  return vec4(speed_ramp(length(vec2(u, v)) / 30.0) * light, 1.0);
}

float alpha(int id, float distance) {
  return id == 1 ? 1.0 - exp(-distance / 0.8) : 1.0 - exp(-distance / 4.0);
}
