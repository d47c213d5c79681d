// confvis conformal warp, the display's rim (issue 23): the part of the warp interface that the
// pieces torn by the source's cut need to reach the rim. Include after confvis_warp.glsl.
//
// T_geom takes the source's cut onto the display's rim, but next to the cut the map grows like a
// square root of the distance, and the lookup's extrapolation from the last texel
// (confvisSampleGeomAcrossCutToward) falls short of the rim by a band (some 5 degrees at 128
// texels a face on cave3). confvisSnapToRim moves such a limit out to the rim as the backward
// path (Embree) sees it: where the ray map's alpha, the display's coverage, ends.
//
// Descriptor layout (a second binding of the warp set):
//   layout(set = CONFVIS_WARP_SET, binding = CONFVIS_COVERAGE_BINDING) uniform samplerCube
//   - image: the `ray` map (indexed by physical direction; alpha: where the display shows it),
//     uploaded as the geom map (confvis/backends/vulkan/warp_interface.hpp: rayMapUploadData,
//     coverageLayoutBinding), the same format and sampler settings (warpSamplerInfo).
// Define CONFVIS_COVERAGE_BINDING before including this file to move the binding (default 1,
// kCoverageBinding). Every stage that calls confvisSnapToRim or confvisRefineOnRayMap needs it
// (the backend: the conformal pre-pass, the geometry shader, warp.geom, and the tessellation
// evaluation, confvis_warp_tese.glsl).
#ifndef CONFVIS_WARP_RIM_GLSL
#define CONFVIS_WARP_RIM_GLSL

#ifndef CONFVIS_WARP_GLSL
#error "include confvis_warp.glsl before confvis_warp_rim.glsl"
#endif
#ifndef CONFVIS_COVERAGE_BINDING
#define CONFVIS_COVERAGE_BINDING 1
#endif

layout(set = CONFVIS_WARP_SET, binding = CONFVIS_COVERAGE_BINDING) uniform samplerCube
    confvisCoverageMap;

// The display shows physical direction d (the ray map's alpha at least 0.5).
bool confvisDisplayShows(vec3 d) { return textureLod(confvisCoverageMap, d, 0.0).w >= 0.5; }

// The limit g of the warp at the cut (relative to c), moved out to the display's rim: along the
// great circle from own's warp (wOwn, a point of the limit's side) through g, outwards, in up to
// 32 steps, then 10 bisection steps on the coverage (within a tenth of a ray-map texel). g as it
// was where the display does not show it or no rim lies within the search (16 geom texels, at
// most 0.3 radians). Loops rather than ifs: lavapipe runs both sides of an if for all SIMD lanes.
vec3 confvisSnapToRimWithin(vec3 g, vec3 wOwn, float reach);

vec3 confvisSnapToRim(vec3 g, vec3 wOwn) {
  return confvisSnapToRimWithin(g, wOwn, min(16.0 * 2.0 / float(textureSize(confvisGeomMap, 0).x), 0.3));
}

// confvisSnapToRim searching within `reach` radians.
vec3 confvisSnapToRimWithin(vec3 g, vec3 wOwn, float reach) {
  vec3 u = normalize(g), own = normalize(wOwn);
  vec3 away = u * dot(u, own) - own;  // tangent at u, pointing away from own
  float awayLength = length(away);
  float step = max(1.0 / float(textureSize(confvisCoverageMap, 0).x), reach / 32.0);
  bool search = confvisDisplayShows(u) && awayLength > 1e-6;
  vec3 tangent = away / max(awayLength, 1e-6);
  float shown = 0.0, hidden = -1.0;
  for (float angle = step; search && hidden < 0.0 && angle <= reach + 0.5 * step; angle += step) {
    bool shows = confvisDisplayShows(cos(angle) * u + sin(angle) * tangent);
    shown = shows ? angle : shown;
    hidden = shows ? hidden : angle;
  }
  for (int k = 0; k < (hidden > 0.0 ? 10 : 0); ++k) {
    float middle = 0.5 * (shown + hidden);
    bool shows = confvisDisplayShows(cos(middle) * u + sin(middle) * tangent);
    shown = shows ? middle : shown;
    hidden = shows ? hidden : middle;
  }
  return hidden > 0.0 ? length(g) * (cos(shown) * u + sin(shown) * tangent) : g;
}

// The ray map's virtual direction at physical direction p (unit): T_ray, as Embree's rays see it.
vec3 confvisRayDirection(vec3 p) { return normalize(textureLod(confvisCoverageMap, p, 0.0).xyz); }

// One Gauss-Newton step on the ray map from physical direction p toward the physical direction
// that shows virtual direction v (both unit): the tangent step at p, by central differences an
// eighth of a ray-map texel wide (the bilinear map's own slope there, not a secant over its
// texels: next to a leaf T_ray is flat to first order). Zero where they are degenerate.
vec3 confvisRayNewtonStep(vec3 v, vec3 p, out float stretch) {
  float h = 0.25 / float(textureSize(confvisCoverageMap, 0).x);
  vec3 t1 = normalize(cross(p, abs(p.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
  vec3 t2 = cross(p, t1);
  vec3 a = (confvisRayDirection(normalize(p + h * t1)) - confvisRayDirection(normalize(p - h * t1))) /
           (2.0 * h);
  vec3 b = (confvisRayDirection(normalize(p + h * t2)) - confvisRayDirection(normalize(p - h * t2))) /
           (2.0 * h);
  vec3 f = v - confvisRayDirection(p);
  float aa = dot(a, a), ab = dot(a, b), bb = dot(b, b), af = dot(a, f), bf = dot(b, f);
  float det = aa * bb - ab * ab;
  stretch = sqrt(sqrt(max(det, 0.0)));  // the geometric mean of T_ray's two stretches at p
  if (!(det > 1e-8 * aa * bb)) return vec3(0.0);
  return ((bb * af - ab * bf) * t1 + (aa * bf - ab * af) * t2) / det;
}

// The geom map's bilinear footprint at v lies inside the source field (all four texels valid).
bool confvisGeomFootprintValid(vec3 v) {
  vec4 alpha = textureGather(confvisGeomMap, v, 3);
  return min(min(alpha.x, alpha.y), min(alpha.z, alpha.w)) >= 0.5;
}

// Up to `steps` Gauss-Newton steps on the ray map from physical direction p toward the one that
// shows virtual direction v (both unit), the first of them `first` (confvisRayNewtonStep at p),
// each at most four ray texels long and kept only where the display shows it and the ray map's
// residual shrinks.
vec3 confvisDescendOnRayMap(vec3 v, vec3 p, vec3 first, int steps) {
  float texel = 2.0 / float(textureSize(confvisCoverageMap, 0).x);
  float stretch;
  float residual = distance(confvisRayDirection(p), v);
  for (int k = 0; k < steps; ++k) {
    vec3 s = k == 0 ? first : confvisRayNewtonStep(v, p, stretch);
    s *= min(1.0, 4.0 * texel / max(length(s), 1e-20));  // at most four texels a step
    // Halved while it leaves the display (the ray map's extension past the rim is extrapolated)
    // or does not shrink the residual.
    bool taken = false;
    for (int halving = 0; halving < 6 && !taken; ++halving, s *= 0.5) {
      vec3 q = normalize(p + s);
      float r = distance(confvisRayDirection(q), v);
      taken = r < residual && confvisDisplayShows(q);
      p = taken ? q : p;
      residual = taken ? r : residual;
    }
  }
  return p;
}

// The cut's ends (issue 23, point 5). Where the source's cut ends (a leaf of the cut: cave5's
// ceiling-corner directions), T_geom grows like a square root (T_ray like a square), and every
// lookup of the geom map, the four-texel one included, puts a point on or right next to the leaf
// up to a few texels short of the rim where the ray map (Embree's rays) shows it. g: the geom
// lookup's physical direction for virtual direction v (both unit). Where the first Gauss-Newton
// step on the ray map moves g by more than half a ray texel and the geom footprint lies inside
// the source field (not next to the source field's rim, where the ray map's extension past the
// display is no inverse of anything: md230x6's corners under a hemisphere), up to ten steps move
// g to where the ray map shows v, each kept only where the display shows it and the ray map's
// residual shrinks. Elsewhere the maps agree within the interpolation's error and g is returned.
vec3 confvisRefineOnRayMap(vec3 v, vec3 g) {
  float texel = 2.0 / float(textureSize(confvisCoverageMap, 0).x);
  float stretch;
  vec3 first = confvisRayNewtonStep(v, g, stretch);
  bool refine = length(first) > 0.5 * texel && confvisGeomFootprintValid(v) &&
                confvisDisplayShows(g);
  vec3 p = confvisDescendOnRayMap(v, g, first, refine ? 10 : 0);
  // On the leaf itself T_ray is flat (its stretch vanishes like the distance to the leaf's image,
  // a point of the rim), and the bilinear ray map's preimage of the leaf stays up to a texel
  // below the rim, while Embree's pixels up to the rim see directions next to the leaf: where the
  // refined point's stretch is below a quarter, it goes on, in the direction it came, to a rim
  // within two ray texels.
  if (refine) confvisRayNewtonStep(v, p, stretch);
  for (int once = 0; once < (refine && stretch < 0.25 ? 1 : 0); ++once)
    p = normalize(confvisSnapToRimWithin(p, g, 2.0 * texel));
  return p;
}

// `warped`, the four-texel lookup's warp of `relative` (both relative to c), moved by
// confvisRefineOnRayMap where `refine` (the snap to the rim switched on).
vec4 confvisRefineWarpOnRayMap(vec3 relative, vec4 warped, bool refine) {
  float distance = length(relative);
  for (int once = 0; once < (refine && distance > 1e-9 ? 1 : 0); ++once)
    warped.xyz = distance * confvisRefineOnRayMap(relative / distance, normalize(warped.xyz));
  return warped;
}

#endif  // CONFVIS_WARP_RIM_GLSL
