// Surfaces coloured by a scalar (the built-in "scalar on surface" look of strielad-view:
// --look scalar --color-by VAR; docs/view.md "Looks"). Every sub-volume is an opaque
// surface whose colour is a colour map at the value of an attribute, as in the paper's
// figure of cloud surfaces coloured by wind speed; a missing value is grey. Lighting is
// light (80 to 100% of the map's colour), so the colour stays readable against the
// legend. The viewer defines SCALAR_VALUE, SCALAR_RANGE and kColormap from its
// flags before this file; as a plain --shader file it colours by the first attribute
// over [0, 1] with viridis.

#ifndef SCALAR_VALUE
#define SCALAR_VALUE(a) (a[0])
#endif
#ifndef SCALAR_RANGE
#define SCALAR_RANGE vec2(0.0, 1.0)
#endif
// Control points of the colour map, evenly spaced from the range's low to its high end
// (here viridis).
#ifndef SCALAR_COLORMAP_GIVEN
const vec3 kColormap[] = vec3[](vec3(0.267004, 0.004874, 0.329415),
    vec3(0.282327, 0.140926, 0.457517), vec3(0.253935, 0.265254, 0.529983),
    vec3(0.206756, 0.371758, 0.553117), vec3(0.163625, 0.471133, 0.558148),
    vec3(0.127568, 0.566949, 0.550556), vec3(0.134692, 0.658636, 0.517649),
    vec3(0.266941, 0.748751, 0.440573), vec3(0.993248, 0.906157, 0.143936));
#endif

vec3 colormap(float value) {
  vec2 range = SCALAR_RANGE;
  float t = clamp((value - range.x) / (range.y - range.x), 0.0, 1.0);
  float f = t * float(kColormap.length() - 1);
  int i = min(int(f), kColormap.length() - 2);
  return mix(kColormap[i], kColormap[i + 1], f - float(i));
}

vec4 color(int id, float attributes[MAX_ATTRIBUTES], vec3 normal, vec3 sun,
           vec3 position, vec3 view, float time) {
  float value = SCALAR_VALUE(attributes);
  vec3 base = missing(value) ? vec3(0.5) : colormap(value);
  float light = 0.8 + 0.2 * max(dot(normal, sun), 0.0);
  return vec4(base * light, 1.0);
}

// Opaque: the nearest surface along a ray hides what lies behind it.
float alpha(int id, float distance) { return 1.0; }
