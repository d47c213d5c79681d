// confvis conformal warp: a torn piece's limits at the cut, placed where the ray map shows them
// (issue 23, point 5). Include after confvis_warp_rim.glsl.
//
// warp.geom's split (splitAtCut) draws each side of a piece the cut tears up to that side's limit
// of the warp at the crossing. The geom lookup extrapolates that limit from its side's last
// texels; next to a leaf of the cut (where it ends: cave5's ceiling-corner directions) the map
// grows like a square root and the extrapolated limit stays next to the side's own corner, often
// so far inside the display that confvisSnapToRim, which searches outwards along the great circle
// from the corner through the limit, finds no rim within its reach, or one straight above the
// corner: the side is drawn as a thin wedge and the region between it and the leaf's image stays
// black (the right wall's notch at cave5's top corner, BackendCrossCheckCutEnds). The ray map
// (Embree's rays) shows where the crossing's direction lies: where the snap finds no rim and the
// ray map is flat at the limit (its stretch below a quarter: next to a leaf's image, where it
// grows like a square), the limit is first moved by Gauss-Newton on the ray map toward the
// physical direction that shows the crossing (from the limit: its side's preimage, not the other
// side's), then snapped again. Elsewhere the snap alone (doing the descent for every limit put
// BackendCrossCheckRim's unsplit case's back wall 3.5 % off Embree, from 1.3 %).
#ifndef CONFVIS_RIM_LIMIT_GLSL
#define CONFVIS_RIM_LIMIT_GLSL

#ifndef CONFVIS_WARP_RIM_GLSL
#error "include confvis_warp_rim.glsl before confvis_rim_limit.glsl"
#endif

// g lies on the display's rim: the coverage changes across it (by more than a quarter over two
// ray texels).
bool confvisOnRim(vec3 g) {
  float h = 2.0 / float(textureSize(confvisCoverageMap, 0).x);
  vec3 u = normalize(g);
  vec3 t1 = normalize(cross(u, abs(u.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
  vec3 t2 = cross(u, t1);
  float a1 = textureLod(confvisCoverageMap, normalize(u + h * t1), 0.0).w -
             textureLod(confvisCoverageMap, normalize(u - h * t1), 0.0).w;
  float a2 = textureLod(confvisCoverageMap, normalize(u + h * t2), 0.0).w -
             textureLod(confvisCoverageMap, normalize(u - h * t2), 0.0).w;
  return length(vec2(a1, a2)) > 0.25;
}

// limit: a side's limit of the warp at the crossing (relative to c), own: the warp of that side's
// corner, crossing: the crossing's virtual direction (unit). confvisSnapToRim from own; where that
// misses the rim next to a leaf, four Gauss-Newton steps on the ray map first (ten give the same
// images; two leave the left wall's corner worse), without confvisRefineOnRayMap's gates (a limit
// at the cut is where the geom lookup is least like the ray map; gated, the notch kept 306 black
// pixels, 244 without). Loops rather than ifs: lavapipe runs both sides of an if for all lanes,
// so every torn piece pays the descent (the 20k baked frame on lavapipe: a few % more GPU time).
vec3 confvisRimLimit(vec3 crossing, vec3 limit, vec3 own) {
  vec3 snapped = confvisSnapToRim(limit, own);
  vec3 start = normalize(limit);
  float stretch;
  vec3 first = confvisRayNewtonStep(crossing, start, stretch);
  bool missed = !confvisOnRim(snapped) && stretch < 0.25;
  vec3 shown = confvisDescendOnRayMap(crossing, start, first, missed ? 4 : 0);
  for (int once = 0; once < (missed ? 1 : 0); ++once)
    snapped = confvisSnapToRim(length(limit) * shown, own);
  return snapped;
}

#endif  // CONFVIS_RIM_LIMIT_GLSL
