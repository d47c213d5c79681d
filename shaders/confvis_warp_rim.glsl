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
// kCoverageBinding). Every stage that calls confvisSnapToRim needs it (the backend: the
// conformal pre-pass and the geometry shader, warp.geom).
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
vec3 confvisSnapToRim(vec3 g, vec3 wOwn) {
  vec3 u = normalize(g), own = normalize(wOwn);
  vec3 away = u * dot(u, own) - own;  // tangent at u, pointing away from own
  float awayLength = length(away);
  float reach = min(16.0 * 2.0 / float(textureSize(confvisGeomMap, 0).x), 0.3);
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

#endif  // CONFVIS_WARP_RIM_GLSL
