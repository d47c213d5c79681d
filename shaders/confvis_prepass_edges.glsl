// Conformal pre-pass: edge e's warped midpoint and tessellation level (classify_edges.comp for
// the straight edges, classify_edges_bent.comp for the smoothly bent ones,
// classify_edges_at_cut.comp for the others).
// The level's sign tells whether the edge may lose pieces to confvisDropTriangle (negative: it
// spans the cut, or part of it lies outside the source field).
#ifndef CONFVIS_PREPASS_EDGES_GLSL
#define CONFVIS_PREPASS_EDGES_GLSL

#include "confvis_warp.glsl"
#include "confvis_prepass_common.glsl"

// What the edge passes read of an edge, once: its vertices, their virtual points relative to c,
// their unit directions and their warps (and unit warp directions). Loading and normalizing them
// once per test cost lavapipe, which gathers every load lane by lane, much of that pass (1.5M
// edges at 1M triangles).
struct EdgeEnds {
  uvec2 v;              // vertex numbers, sceneEdge(e)
  vec3 ra, rb, ua, ub;  // virtual points relative to c, unit
  vec4 wa, wb;          // warps
  vec3 va, vb;          // unit warp directions
};

EdgeEnds loadEdgeEnds(uint e) {
  EdgeEnds ends;
  ends.v = sceneEdge(e);
  ends.ra = vertexRelative(ends.v.x);
  ends.rb = vertexRelative(ends.v.y);
  ends.ua = normalize(ends.ra);
  ends.ub = normalize(ends.rb);
  ends.wa = vertexWarp(ends.v.x);
  ends.wb = vertexWarp(ends.v.y);
  ends.va = normalize(ends.wa.xyz);
  ends.vb = normalize(ends.wb.xyz);
  return ends;
}

// The edge's warped halves surely do not span a jump (confvisHalvesSpanJump would find none): its
// rules on chords instead of angles. A chord c = 2 sin(angle / 2) is below its angle and, up to
// c = 0.4 (23 degrees), above it by less than 0.7 %: with a 1 % margin every rule holds for the
// angles too. An edge it does not accept may still be smooth (classify_edges_bent.comp decides).
// um: the warped midpoint's unit direction.
bool edgeSurelyWithoutJump(EdgeEnds ends, vec3 um) {
  float halfA = length(ends.va - um), halfB = length(um - ends.vb);
  float longer = max(halfA, halfB), shorter = min(halfA, halfB);
  float floor8 = 8.0 * prepass.maxErrorAngle;
  return longer <= 0.4 && 1.01 * longer <= max(3.0 * shorter, floor8) &&
         1.01 * (halfA + halfB) <= max(3.0 * length(ends.va - ends.vb), floor8);
}

// Edge e is drawn in one segment and spans no cut, as writeEdgeLevel would find: it is short,
// its warped halves do not span a jump (edgeSurelyWithoutJump, the rules of the bent edges' pass:
// a fixed multiple of the error bound instead made every edge of a 1M-triangle sphere longer
// than four pixels at 1920-pixel walls go through that pass, 68 of a 140 ms pre-pass on
// lavapipe) and its warped midpoint lies within the error bound of the chord. Conservative
// (chords below angles, with a margin): an edge it does not accept may still be straight.
// um: the warped midpoint's unit direction.
bool edgeSurelyStraight(EdgeEnds ends, vec3 um) {
  return chordBelow(length(ends.ua - ends.ub), prepass.maxSegmentAngle) &&
         edgeSurelyWithoutJump(ends, um) &&
         chordBelow(directionChord(um, ends.wa.xyz + ends.wb.xyz), prepass.maxErrorAngle);
}

// Where the source's cut crosses the edge: the parameter t from its first vertex to its second,
// by bisection on which end's warp the bilinear lookup lands nearer. The blend flips sides
// halfway between the texel centres on either side, where the four-texel lookup flips too.
// 14 steps: 1/16384 of an edge (a few thousandths of a pixel at 480-pixel walls).
float cutCrossing(EdgeEnds ends) {
  float lo = 0.0, hi = 1.0;
  for (int step = 0; step < 14; ++step) {
    float m = 0.5 * (lo + hi);
    vec3 relative = mix(ends.ra, ends.rb, m);
    vec3 g = textureLod(confvisGeomMap, relative, 0.0).xyz * length(relative);
    bool nearFirst = distance(g, ends.wa.xyz) <= distance(g, ends.wb.xyz);
    lo = nearFirst ? m : lo;
    hi = nearFirst ? hi : m;
  }
  return 0.5 * (lo + hi);
}

// Writes cut vertex `slot`: the point at t along the edge with the limit of the warp on the side
// of the end whose warp is wOwn (the other end's: wOther), moved out to the rim
// (prepass.snapCutToRim, confvisSnapToRim in confvis_warp_rim.glsl). False where that limit is
// not clearly on own's side or lies outside the source field.
bool writeCutVertex(uint slot, EdgeEnds ends, float t, vec3 wOwn, vec3 wOther) {
  CutVertex c = vertexBetween(ends.v.x, ends.v.y, t);
  c.warped = confvisWarpRelativeToward(mix(ends.ra, ends.rb, t), wOwn);
  bool ownSide =
      c.warped.w >= 0.5 && distance(c.warped.xyz, wOwn) < distance(c.warped.xyz, wOther);
  for (uint once = 0u; once < (prepass.snapCutToRim != 0u ? 1u : 0u); ++once)
    c.warped.xyz = confvisSnapToRim(c.warped.xyz, wOwn);
  storeCutVertex(slot, c);
  return ownSide;
}

// Edge e's two cut vertices (EdgeCutVertices).
void writeEdgeCutVertices(uint e, EdgeEnds ends) {
  uint slot = reserveCutVertices(2u);
  bool ok = slot != ~0u;
  float t = 0.5;
  for (uint once = 0u; once < (ok ? 1u : 0u); ++once) {
    t = cutCrossing(ends);
    ok = writeCutVertex(slot, ends, t, ends.wa.xyz, ends.wb.xyz);
    ok = writeCutVertex(slot + 1u, ends, t, ends.wb.xyz, ends.wa.xyz) && ok;
  }
  // Slots written but not clearly on their sides keep the top bit (kCutVertexUnsure).
  edgeCutVertex[e] = uvec2(slot == ~0u ? ~0u : ok ? slot : slot | kCutVertexUnsure,
                           floatBitsToUint(t));
}

// Edge e's level and flags (EdgeFlags), `segments` its level (negative where it may lose pieces).
void writeEdge(uint e, EdgeEnds ends, vec4 midpoint, float segments, bool acrossCut) {
  edgeLevels[e] = vec4(midpoint.xyz, segments);
  float warpedChord = length(ends.va - ends.vb);
  bool small = chordBelow(warpedChord, prepass.minGap);
  bool tame = warpedChord <= 0.4 && 1.01 * warpedChord <= 16.0 * length(ends.ua - ends.ub);
  edgeFlags[e] = (abs(segments) == 1.0 ? kEdgeStraight : 0u) | (small ? kEdgeSmall : 0u) |
                 (tame ? kEdgeTame : 0u) |
                 (max(ends.wa.w, ends.wb.w) < 0.5 ? kEdgeUnseen : 0u) |
                 (acrossCut ? kEdgeAcrossCut : 0u) |
                 (min(keptValidity(midpoint.w), min(ends.wa.w, ends.wb.w)) < 0.5 ? kEdgeOutside : 0u);
}

// Part of the edge lies outside the source field (its corners' or midpoint's validity below 1).
bool edgeLeavesField(EdgeEnds ends, vec4 midpoint) {
  return min(keptValidity(midpoint.w), min(ends.wa.w, ends.wb.w)) < 1.0;
}

// writeEdgeLevel for an edge edgeSurelyStraight accepts: one segment.
void writeStraightEdgeLevel(uint e, EdgeEnds ends, vec4 midpoint) {
  writeEdge(e, ends, midpoint, edgeLeavesField(ends, midpoint) ? -1.0 : 1.0, false);
}

// confvisSmoothEdgeSegments with the bound of the wall that shows the warped midpoint wm
// (errorAngleToward), looked up only where the strictest bound asks for more than one segment
// (the local bound is never stricter): its loop over the walls cost 3 ms of a 20k-triangle
// frame's pre-pass on lavapipe when run for every edge.
float smoothEdgeSegments(EdgeEnds ends, vec3 wm) {
  float segments = confvisSmoothEdgeSegments(ends.ra, ends.rb, ends.wa.xyz, ends.wb.xyz, wm,
                                             prepass.maxErrorAngle, prepass.maxSegmentAngle);
  for (uint once = 0u; once < (segments > 1.0 ? 1u : 0u); ++once)
    segments = confvisSmoothEdgeSegments(ends.ra, ends.rb, ends.wa.xyz, ends.wb.xyz, wm,
                                         errorAngleToward(wm), prepass.maxSegmentAngle);
  return segments;
}

// writeEdgeLevel for an edge edgeSurelyWithoutJump accepts, with its midpoint's bilinear warp
// (confvisWarpRelativeBilinear true: the full lookup gives the same).
void writeSmoothEdgeLevel(uint e, EdgeEnds ends, vec4 midpoint) {
  float segments = smoothEdgeSegments(ends, midpoint.xyz);
  writeEdge(e, ends, midpoint, edgeLeavesField(ends, midpoint) ? -segments : segments, false);
}

void writeEdgeLevel(uint e, EdgeEnds ends, vec4 midpoint) {
  bool acrossCut;
  // The cut and its segments by the strictest bound, a smooth bend by the local one.
  float segments = confvisMeasureEdgeWithMidpoint(ends.ra, ends.rb, ends.wa.xyz, ends.wb.xyz,
                                                  midpoint, prepass.maxErrorAngle,
                                                  prepass.maxSegmentAngle, acrossCut);
  if (!acrossCut) segments = smoothEdgeSegments(ends, midpoint.xyz);
  bool mayDrop = acrossCut || edgeLeavesField(ends, midpoint);
  writeEdge(e, ends, midpoint, mayDrop ? -segments : segments, acrossCut);
  // A loop entered once or not at all (lavapipe runs both sides of an if for all SIMD lanes).
  for (uint once = 0u; once < (acrossCut && prepass.splitAlongCut != 0u ? 1u : 0u); ++once)
    writeEdgeCutVertices(e, ends);
}

#endif
