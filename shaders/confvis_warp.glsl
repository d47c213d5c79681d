// confvis conformal warp for Vulkan renderers (design note §5, forward path).
//
// A virtual scene point x, expressed in the physical frame (after the application's navigation
// transform), is drawn at the physical point
//     W^-1(x) = c + |x - c| * T_geom(dir(x - c)),
// where c is the map's reference point and T_geom is the baked `geom` cube map of a
// confvis::RetargetMap: indexed by the virtual direction, storing the physical direction in RGB and
// the source-field validity in A. Distances to c are kept, so depth stays correct for every eye;
// project the warped point with the wall's ordinary off-axis (generalized perspective) matrix.
//
// Descriptor layout (one binding):
//   layout(set = CONFVIS_WARP_SET, binding = CONFVIS_WARP_BINDING) uniform samplerCube
//   - image: VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT, 6 array layers, VK_FORMAT_R32G32B32A32_SFLOAT
//     (float32: half floats quantise directions to ~0.03 degrees), one mip level, layer i =
//     toVulkanLayout(map.geom).faces[i] (confvis/base/cube_map.hpp converts the in-face
//     orientation; confvis/backends/vulkan/warp_interface.hpp packs the upload data);
//   - sampler: VK_FILTER_LINEAR (min and mag; the format must support linear filtering),
//     VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, unnormalizedCoordinates = VK_FALSE.
// Including it: `#extension GL_GOOGLE_include_directive : require` then
// `#include "confvis_warp.glsl"`, compiled with `glslangValidator -I<dir>`,
// where <dir> is ${confvis_SHADER_DIR} of the installed package (share/confvis/shaders).
// Define CONFVIS_WARP_SET and CONFVIS_WARP_BINDING before including this file to move the binding
// (defaults: set 1, binding 0). The map is needed in every stage that calls these functions.
//
// Triangles must be subdivided before the per-vertex warp (edges bend): use
// confvisEdgeSegments() for the tessellation levels, and drop triangles with
// confvisDropTriangle() after tessellation (those straddling the source's cut, whose corners land
// far apart or whose shape tears, and those entirely outside the source field) instead of
// smearing them across a wall.
#ifndef CONFVIS_WARP_GLSL
#define CONFVIS_WARP_GLSL

#ifndef CONFVIS_WARP_SET
#define CONFVIS_WARP_SET 1
#endif
#ifndef CONFVIS_WARP_BINDING
#define CONFVIS_WARP_BINDING 0
#endif

layout(set = CONFVIS_WARP_SET, binding = CONFVIS_WARP_BINDING) uniform samplerCube confvisGeomMap;

// Angle between two non-zero vectors in radians (atan keeps tiny angles accurate).
float confvisAngle(vec3 a, vec3 b) { return atan(length(cross(a, b)), dot(a, b)); }

// Face coordinates (sc, tc), major axis ma and the directions in which s and t grow of a
// non-zero direction, exactly as the Vulkan spec's cube-map face selection table.
void confvisCubeFaceCoordinates(vec3 v, out float sc, out float tc, out float ma, out vec3 sAxis,
                                out vec3 tAxis) {
  vec3 a = abs(v);
  if (a.x >= a.y && a.x >= a.z) {
    ma = a.x; sc = v.x > 0.0 ? -v.z : v.z; tc = -v.y;
    sAxis = vec3(0.0, 0.0, v.x > 0.0 ? -1.0 : 1.0); tAxis = vec3(0.0, -1.0, 0.0);
  } else if (a.y >= a.z) {
    ma = a.y; sc = v.x; tc = v.y > 0.0 ? v.z : -v.z;
    sAxis = vec3(1.0, 0.0, 0.0); tAxis = vec3(0.0, 0.0, v.y > 0.0 ? 1.0 : -1.0);
  } else {
    ma = a.z; sc = v.z > 0.0 ? v.x : -v.x; tc = -v.y;
    sAxis = vec3(v.z > 0.0 ? 1.0 : -1.0, 0.0, 0.0); tAxis = vec3(0.0, -1.0, 0.0);
  }
}

// Where v falls within the 2x2 texel block of the geom map's bilinear footprint: the weights of
// texels (i, j) are (i ? f.x : 1 - f.x) (j ? f.y : 1 - f.y).
vec2 confvisGeomFootprintFraction(vec3 v) {
  float sc, tc, ma;
  vec3 sAxis, tAxis;
  confvisCubeFaceCoordinates(v, sc, tc, ma, sAxis, tAxis);
  float n = float(textureSize(confvisGeomMap, 0).x);
  return fract((0.5 * vec2(sc, tc) / ma + 0.5) * n - 0.5);
}

// Cube-map lookup of T_geom for a non-zero virtual direction: xyz = unit physical direction,
// w = validity (alpha, 1 inside the source field). Bilinear, except across the source's cut: the
// map jumps there, and blending texels from both sides would land between them (in the middle of
// a wall). Where the hardware's bilinear blend comes out shorter than unit directions about
// eight neighbour spacings apart would give, the four texels are fetched; those that a side of
// the block spanning a jump separates from the nearest one (a side more than three times the
// shortest and eight spacings long: not a magnification, which keeps the block square) are
// replaced by extrapolations of the nearest texel's side, so a point next to the cut keeps its
// own side, up to the cut. (A fixed eight-spacing rule read the unbounded magnification next to
// a monitor wall's corners as jumps and tore the triangles there: 5 % of md230x6 black.)
vec4 confvisSampleGeomAcrossCut(vec3 v);

// confvisSampleGeomAcrossCut continuing the side of the block's texel nearest to `hint` (a
// physical direction; zero: the texel nearest v, as confvisSampleGeomAcrossCut): at a point on
// the cut, each side's limit, the hint being a point of that side.
vec4 confvisSampleGeomAcrossCutToward(vec3 v, vec3 hint);

// The hardware's bilinear blend alone, normalised, in `g`; false where the blend comes out too
// short (the footprint may straddle the cut), where confvisSampleGeom fetches the four texels.
// "Too short" is weighed by the footprint's weights w: unit vectors blend to a length of
// 1 - sum_{k<l} w_k w_l |u_k - u_l|^2 / 2, so a jump J to texels of total weight W shortens it by
// W (1 - W) J^2 / 2 and moves the blend W J off its side. A flat bound (the shortest blend of two
// texels 16 / n apart at equal weights) let jumps of 16-40 / n through wherever the far side
// weighs little, and those are the jumps next to the cut's ends, where both sides meet again:
// a vertex there landed up to 8 / n off its side (up to 39 px at 960-px walls, 128 texels),
// the black notches at cave5's top wall corners (issue 23). The bound 8 (1 - sum w^2) / n^2
// (the spread the weights allow, times a smooth map's own texel spacing squared at a stretch of
// two) sends those to the four texels; 0.57 % of all directions take that path on cave5's
// 128-texel map, from 0.53 %.
// Devices that run both sides of a branch for every SIMD lane (lavapipe) pay the costly path
// for every lookup in confvisSampleGeom; a caller that can queue the few false ones for a
// pass of their own (the conformal pre-pass does) saves that.
bool confvisSampleGeomBilinear(vec3 v, out vec4 g) {
  vec4 blended = textureLod(confvisGeomMap, v, 0.0);
  float n = float(textureSize(confvisGeomMap, 0).x);
  vec2 f = confvisGeomFootprintFraction(v);
  // sum of the bilinear weights squared: a product of the two axes' (1 - f)^2 + f^2.
  vec2 axisSquares = (1.0 - f) * (1.0 - f) + f * f;
  float spread = 1.0 - axisSquares.x * axisSquares.y;
  float shortest = 1.0 - 8.0 * spread / (n * n);
  float len = length(blended.xyz);
  g = vec4(blended.xyz / len, blended.w);
  return len >= shortest;
}

vec4 confvisSampleGeom(vec3 v) {
  vec4 g;
  if (confvisSampleGeomBilinear(v, g)) return g;
  return confvisSampleGeomAcrossCut(v);
}

// The four texels of the bilinear footprint at v, as texels k = 2 j + i of the block (i along s,
// j along t; xyz direction, w validity). textureGather order: (i0, j1), (i1, j1), (i1, j0), (i0, j0).
void confvisGatherGeom(vec3 v, out vec4 corner[4]) {
  vec4 gx = textureGather(confvisGeomMap, v, 0);
  vec4 gy = textureGather(confvisGeomMap, v, 1);
  vec4 gz = textureGather(confvisGeomMap, v, 2);
  vec4 gw = textureGather(confvisGeomMap, v, 3);
  corner[0] = vec4(gx.w, gy.w, gz.w, gw.w);
  corner[1] = vec4(gx.z, gy.z, gz.z, gw.z);
  corner[2] = vec4(gx.x, gy.x, gz.x, gw.x);
  corner[3] = vec4(gx.y, gy.y, gz.y, gw.y);
}

vec4 confvisSampleGeomAcrossCut(vec3 v) { return confvisSampleGeomAcrossCutToward(v, vec3(0.0)); }

// What confvisSampleGeomAcrossCutToward reads of the map around v: the bilinear footprint's
// fraction f, its four texels, and the blocks one texel over along s and t, each way (index 0:
// towards +, 1: towards -). Gathered once for every corner and hint: lavapipe runs the corners'
// ifs for every SIMD lane, so each corner gathering its own blocks doubled a lookup's gathers,
// and the torn pieces' two limits at one crossing (warp.geom) gathered the same block twice.
struct ConfvisGeomBlock {
  vec2 f;
  float n;
  vec4 corner[4];
  vec4 overS[2][4], overT[2][4];
};

ConfvisGeomBlock confvisGatherGeomBlock(vec3 v) {
  float sc, tc, ma;
  vec3 sAxis, tAxis;
  confvisCubeFaceCoordinates(v, sc, tc, ma, sAxis, tAxis);
  ConfvisGeomBlock block;
  block.n = float(textureSize(confvisGeomMap, 0).x);
  block.f = fract((0.5 * vec2(sc, tc) / ma + 0.5) * block.n - 0.5);
  confvisGatherGeom(v, block.corner);
  float texelStep = 2.0 * ma / block.n;  // one texel in sc or tc
  confvisGatherGeom(v + texelStep * sAxis, block.overS[0]);
  confvisGatherGeom(v - texelStep * sAxis, block.overS[1]);
  confvisGatherGeom(v + texelStep * tAxis, block.overT[0]);
  confvisGatherGeom(v - texelStep * tAxis, block.overT[1]);
  return block;
}

// confvisSampleGeomAcrossCutToward from the block gathered at its point.
vec4 confvisResolveGeomBlock(ConfvisGeomBlock block, vec3 hint) {
  vec2 f = block.f;
  float n = block.n;
  vec4 corner[4] = block.corner;
  float weight[4] = float[4]((1.0 - f.x) * (1.0 - f.y), f.x * (1.0 - f.y), (1.0 - f.x) * f.y, f.x * f.y);
  vec3 unit[4];
  for (int k = 0; k < 4; ++k) unit[k] = normalize(corner[k].xyz);
  bool hinted = dot(hint, hint) > 0.0;
  vec3 towards = hinted ? normalize(hint) : vec3(0.0);
  int nearest = 0;
  for (int k = 1; k < 4; ++k)
    if (hinted ? distance(unit[k], towards) < distance(unit[nearest], towards)
               : weight[k] > weight[nearest])
      nearest = k;
  // The sides of the block that span the cut: longer than three times its shortest side (a
  // conformal map keeps the block nearly square, even where it magnifies strongly next to a
  // display corner) and than eight neighbour spacings (2/n radians each where the map does not
  // stretch). The nearest texel's side: the texels joined to it by the other sides.
  float side[4] = float[4](distance(unit[0], unit[1]), distance(unit[1], unit[3]),
                           distance(unit[3], unit[2]), distance(unit[2], unit[0]));
  float longSide = max(3.0 * min(min(side[0], side[1]), min(side[2], side[3])), min(16.0 / n, 1.5));
  bool member[4], known[4];
  vec3 value[4];
  for (int k = 0; k < 4; ++k) member[k] = k == nearest;
  // Around the block 0-1-3-2: twice suffices to reach every corner joined to the nearest one.
  const int ring[4] = int[4](0, 1, 3, 2);
  for (int pass = 0; pass < 2; ++pass)
    for (int e = 0; e < 4; ++e) {
      int p = ring[e], q = ring[(e + 1) % 4];
      if (side[e] <= longSide && (member[p] || member[q])) member[p] = member[q] = true;
    }
  for (int k = 0; k < 4; ++k) {
    known[k] = member[k];
    value[k] = corner[k].xyz;
  }
  vec3 anchor = unit[nearest];
  // A texel across the cut is replaced by the nearest side's map continued linearly: the
  // parallelogram of the other three texels, else the line from its neighbour in the block's
  // row (column) through the texel beyond that neighbour, fetched one texel over (averaged where
  // both exist). So points between the last texel centre and the cut continue their side up to
  // the cut instead of clamping to that texel. (Mirrors conformal/src/cut_aware_lookup.cpp.)
  for (int k = 0; k < 4; ++k) {
    if (member[k]) continue;
    int i = k % 2, j = k / 2;
    int inRow = 2 * j + (1 - i), inColumn = 2 * (1 - j) + i, diagonal = 3 - k;
    if (member[inRow] && member[inColumn] && member[diagonal]) {
      value[k] = corner[inRow].xyz + corner[inColumn].xyz - corner[diagonal].xyz;
      known[k] = true;
      continue;
    }
    vec3 sum = vec3(0.0);
    float lines = 0.0;
    if (member[inRow]) {
      // The block one texel over along s, away from k: its texel in the neighbour's row lies
      // beyond the neighbour.
      vec3 beyond = block.overS[i][2 * j + (i == 1 ? 0 : 1)].xyz;
      if (distance(normalize(beyond), unit[inRow]) <= longSide) {
        sum += 2.0 * corner[inRow].xyz - beyond;
        lines += 1.0;
      }
    }
    if (member[inColumn]) {
      vec3 beyond = block.overT[j][2 * (j == 1 ? 0 : 1) + i].xyz;
      if (distance(normalize(beyond), unit[inColumn]) <= longSide) {
        sum += 2.0 * corner[inColumn].xyz - beyond;
        lines += 1.0;
      }
    }
    if (lines > 0.0) {
      value[k] = sum / lines;
      known[k] = true;
    }
  }
  for (int k = 0; k < 4; ++k) {
    int i = k % 2, j = k / 2;
    int inRow = 2 * j + (1 - i), inColumn = 2 * (1 - j) + i, diagonal = 3 - k;
    if (!known[k] && known[inRow] && known[inColumn] && known[diagonal]) {
      value[k] = value[inRow] + value[inColumn] - value[diagonal];
      known[k] = true;
    }
  }
  vec3 direction = vec3(0.0);
  float validity = 0.0, total = 0.0;
  for (int k = 0; k < 4; ++k) {
    if (known[k]) direction += weight[k] * value[k];
    if (member[k]) {
      validity += weight[k] * corner[k].w;
      total += weight[k];
    }
  }
  if (dot(direction, direction) == 0.0) direction = anchor;
  return vec4(normalize(direction), total > 0.0 ? validity / total : corner[nearest].w);
}

vec4 confvisSampleGeomAcrossCutToward(vec3 v, vec3 hint) {
  return confvisResolveGeomBlock(confvisGatherGeomBlock(v), hint);
}

// Warps a point given relative to c: xyz = warped point relative to c, w = validity.
vec4 confvisWarpRelative(vec3 relative) {
  float r = length(relative);
  if (r < 1e-9) return vec4(relative, 1.0);  // c itself stays put
  vec4 g = confvisSampleGeom(relative / r);
  return vec4(r * g.xyz, g.w);
}

// confvisWarpRelative on the side of `hint` (confvisSampleGeomAcrossCutToward): next to the cut
// only, where the four texels span it.
vec4 confvisWarpRelativeToward(vec3 relative, vec3 hint) {
  float r = length(relative);
  vec4 g = confvisSampleGeomAcrossCutToward(relative / max(r, 1e-30), hint);
  return vec4(r * g.xyz, g.w);
}

// confvisWarpRelativeToward of one point toward two hints (each side's limit at a point on the
// cut), the map read once.
void confvisWarpRelativeTowardEach(vec3 relative, vec3 hintA, vec3 hintB, out vec4 towardA,
                                   out vec4 towardB) {
  float r = length(relative);
  ConfvisGeomBlock block = confvisGatherGeomBlock(relative / max(r, 1e-30));
  vec4 a = confvisResolveGeomBlock(block, hintA), b = confvisResolveGeomBlock(block, hintB);
  towardA = vec4(r * a.xyz, a.w);
  towardB = vec4(r * b.xyz, b.w);
}

// confvisWarpRelative through confvisSampleGeomBilinear: false where that needs the four texels
// (`warped` then holds the plain blend's warp; confvisWarpRelative gives the right one).
bool confvisWarpRelativeBilinear(vec3 relative, out vec4 warped) {
  float r = length(relative);
  vec4 g;
  bool plain = confvisSampleGeomBilinear(relative / max(r, 1e-30), g);
  warped = r < 1e-9 ? vec4(relative, 1.0) : vec4(r * g.xyz, g.w);
  return plain || r < 1e-9;
}

// Angle between neighbouring texels of the geom map around direction v (non-zero): 2 / n on the
// face, times the squared cosine of v to the face's axis (down to a third at its corners).
float confvisTexelAngle(vec3 v) {
  vec3 a = abs(v);
  float ma = max(a.x, max(a.y, a.z)) / length(v);  // cosine to the face's axis
  return 2.0 / float(textureSize(confvisGeomMap, 0).x) * ma * ma;
}

// Segments for the edge a-b (virtual points relative to c; wa, wb their warps from
// confvisWarpRelative) so that the drawn polyline stays within maxErrorAngle (radians, seen
// from c) of the bent edge: the warped midpoint's deviation from the chord shrinks with the square
// of the segment count. maxSegmentAngle caps the angular length of a segment so that a long edge
// whose bend happens to vanish at its midpoint is still subdivided. An edge across the source's
// cut is cut into segments of four times maxErrorAngle (two pixels at the default half-pixel
// error) or one texel of the geom map, whichever is longer: the triangles dropped along the cut
// leave a band of that width in the source unshown, while everything up to it is drawn up to the
// cut (confvisSampleGeomAcrossCut extrapolates each side there). Finer segments mostly cost: these
// patches (inner level = longest edge's, so the square of it in triangles) were most of the frame
// on lavapipe under a baked cave5 map (128 texels a face, 480-pixel walls: two-pixel segments
// 4.3 x plain, half-texel ones 2.2 x). When the lookup still clamped each side to its last texel
// centre (another half texel unshown), texel-sized segments left too large gaps at 64 texels a
// face (the md230x6 golden: 2.4 % bad pixels), and its side rule tore md230x6's corners; with the
// extrapolated lookup they draw 0.98 % of the pixels off Embree at 1.8 x (half-texel segments
// with the clamping lookup: 1.06 % at 2.0-2.2 x).
// It is told from a smooth bend by its halves: where T_geom jumps, one warped half spans the jump and is
// more than three times as long as the other (and longer than eight times maxErrorAngle), while
// a smooth map stretches both halves of a short edge alike. Symmetric in (a, b), so the two triangles sharing an edge
// agree and leave no cracks. In [1, 64]. warpedMidpoint receives the warp of the edge's midpoint
// (relative to c), e.g. for culling the patch.
float confvisEdgeSegments(vec3 a, vec3 b, vec3 wa, vec3 wb, float maxErrorAngle,
                          float maxSegmentAngle, out vec3 warpedMidpoint);

// The cut test above on the warped halves (angles) of an edge split at its midpoint, and the
// warped chord (the angle between the warped ends): one half spans a jump, or both do, the
// midpoint out across the cut and the ends back on one side (an edge that the cut crosses
// twice, where it runs along the mesh's lines: the halves then come out alike, and their
// deviation from the chord asked for up to 64 segments, tessellated and mostly dropped by the
// geometry shader at the cut). A smooth map bends a short edge into a gentle arc, whose halves
// add up to barely more than its chord, never three times it.
bool confvisHalvesSpanJump(float halfA, float halfB, float chord, float maxErrorAngle) {
  return max(halfA, halfB) > max(3.0 * min(halfA, halfB), 8.0 * maxErrorAngle) ||
         halfA + halfB > max(3.0 * chord, 8.0 * maxErrorAngle);
}

// confvisMeasureEdgeWithMidpoint's segments for an edge that does not span the cut (wm: its
// midpoint's warp).
float confvisSmoothEdgeSegments(vec3 a, vec3 b, vec3 wa, vec3 wb, vec3 wm, float maxErrorAngle,
                                float maxSegmentAngle);

// confvisEdgeSegments with more of what it measured: warpedMidpoint.w is the midpoint's validity,
// acrossCut whether the edge was taken to span the cut (the two-pixel segments).
float confvisMeasureEdgeWithMidpoint(vec3 a, vec3 b, vec3 wa, vec3 wb, vec4 warpedMidpoint,
                                     float maxErrorAngle, float maxSegmentAngle,
                                     out bool acrossCut);

float confvisMeasureEdge(vec3 a, vec3 b, vec3 wa, vec3 wb, float maxErrorAngle,
                         float maxSegmentAngle, out vec4 warpedMidpoint, out bool acrossCut) {
  warpedMidpoint = confvisWarpRelative(0.5 * (a + b));
  return confvisMeasureEdgeWithMidpoint(a, b, wa, wb, warpedMidpoint, maxErrorAngle,
                                        maxSegmentAngle, acrossCut);
}

// confvisMeasureEdge with the midpoint's warp given (confvisWarpRelative(0.5 * (a + b))).
float confvisMeasureEdgeWithMidpoint(vec3 a, vec3 b, vec3 wa, vec3 wb, vec4 warpedMidpoint,
                                     float maxErrorAngle, float maxSegmentAngle,
                                     out bool acrossCut) {
  vec3 wm = warpedMidpoint.xyz;
  float edge = confvisAngle(a, b);
  float halfA = confvisAngle(wa, wm), halfB = confvisAngle(wm, wb);
  acrossCut = confvisHalvesSpanJump(halfA, halfB, confvisAngle(wa, wb), maxErrorAngle);
  if (acrossCut)
    return clamp(ceil(edge / max(4.0 * maxErrorAngle, confvisTexelAngle(a + b))), 1.0, 64.0);
  return confvisSmoothEdgeSegments(a, b, wa, wb, wm, maxErrorAngle, maxSegmentAngle);
}

float confvisSmoothEdgeSegments(vec3 a, vec3 b, vec3 wa, vec3 wb, vec3 wm, float maxErrorAngle,
                                float maxSegmentAngle) {
  float deviation = confvisAngle(wm, 0.5 * (wa + wb));
  float segments = max(sqrt(deviation / maxErrorAngle), confvisAngle(a, b) / maxSegmentAngle);
  return clamp(ceil(segments), 1.0, 64.0);
}

float confvisEdgeSegments(vec3 a, vec3 b, vec3 wa, vec3 wb, float maxErrorAngle,
                          float maxSegmentAngle, out vec3 warpedMidpoint) {
  vec4 midpoint;
  bool acrossCut;
  float segments = confvisMeasureEdge(a, b, wa, wb, maxErrorAngle, maxSegmentAngle, midpoint,
                                      acrossCut);
  warpedMidpoint = midpoint.xyz;
  return segments;
}

// Twice the area of a triangle over its longest edge squared: its shape, 0 for a sliver.
float confvisRoundness(vec3 a, vec3 b, vec3 c) {
  float longest = max(dot(b - a, b - a), max(dot(c - b, c - b), dot(a - c, a - c)));
  return longest > 0.0 ? length(cross(b - a, c - a)) / longest : 0.0;
}

// True for a (small, tessellated) triangle that must not be drawn: one entirely outside the
// source field (validity below 0.5 at every corner; pieces partly outside the rim are kept, the
// map is continuous there and dropping them leaves gaps along the rim), or one that straddles the
// source's cut (T_geom jumps there). Only triangles whose warped angular size exceeds minGap
// (radians; a few pixels, so that the small jumps near the cut's ends, where both sides meet
// again, are kept) can straddle it; they do when the warp stretches them more than 16 times (the
// jump; a conformal map's own stretch across a tessellated triangle stays far below) or tears
// their shape: flips them, or turns them into a sliver 16 times flatter (a conformal map keeps
// the shape of a small triangle). A milder 4x stretch rule dropped legitimately stretched
// triangles near the corners of strongly curved displays and left gaps.
// The warp flips the triangle a-b-c (orientation seen from c, the reference point) or tears it
// into a sliver 16 times flatter: confvisDropTriangle's shape rules, shared with the pre-pass's
// chord test (confvis_prepass_common.glsl, surelyKept).
bool confvisFlipsOrTears(vec3 a, vec3 b, vec3 c, vec3 wa, vec3 wb, vec3 wc) {
  bool flipped =
      dot(cross(b - a, c - a), a + b + c) * dot(cross(wb - wa, wc - wa), wa + wb + wc) < 0.0;
  return flipped || 16.0 * confvisRoundness(wa, wb, wc) < confvisRoundness(a, b, c);
}

bool confvisDropTriangle(vec3 a, vec3 b, vec3 c, vec4 wa, vec4 wb, vec4 wc, float minGap) {
  if (max(wa.w, max(wb.w, wc.w)) < 0.5) return true;
  float virtualSize = max(confvisAngle(a, b), max(confvisAngle(b, c), confvisAngle(c, a)));
  float warpedSize =
      max(confvisAngle(wa.xyz, wb.xyz), max(confvisAngle(wb.xyz, wc.xyz), confvisAngle(wc.xyz, wa.xyz)));
  if (warpedSize <= minGap) return false;
  if (warpedSize > 16.0 * virtualSize) return true;
  return confvisFlipsOrTears(a, b, c, wa.xyz, wb.xyz, wc.xyz);
}

#endif  // CONFVIS_WARP_GLSL
