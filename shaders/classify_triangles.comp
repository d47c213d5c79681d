#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal pre-pass, once per frame and mesh, first pass over every triangle: the cheap test,
// from its edges' flags (confvis_prepass_edges.glsl) and, where they do not tell, chords.
// Triangles entirely outside the source field are dropped; those the warp leaves straight enough to draw flat between their
// warped corners (every edge at one segment) and too small after the warp for
// confvisDropTriangle to drop (no two corners further apart than minGap: the common case) are
// written to the flat list, drawn by the cheap pipeline; the other straight ones go to the
// mesh's straight list (classify_straight_triangles.comp runs the full drop test on them), the
// rest to its bent list (classify_bent_triangles.comp); both dispatched indirectly, their group
// counts kept here.
#include "confvis_prepass_common.glsl"

layout(local_size_x = 64) in;

void classify(uint t) {
  uint base = prepass.firstIndex + 3u * t;
  uint i[3] = uint[3](sceneIndex(base), sceneIndex(base + 1u), sceneIndex(base + 2u));
  uint flags = edgeFlagsOf(triangleEdge(base)) & edgeFlagsOf(triangleEdge(base + 1u)) &
               edgeFlagsOf(triangleEdge(base + 2u));
  bool unseen = (flags & kEdgeUnseen) != 0u;  // every corner outside the source field
  bool straight = !unseen && (flags & kEdgeStraight) != 0u;
  bool drawnFlat = straight && (flags & kEdgeSmall) != 0u;
  // Straight but too large after the warp for the flags: kept flat where its edges pass
  // surelyKept's chord rules (kEdgeTame) and its shape is kept (most of a coarse scene's
  // triangles, and 70 % of a 1M-triangle sphere's under cave5; the chord rules here, per
  // triangle, cost 4 ms of its 20 ms pass on lavapipe), the rest to the exact test. A loop
  // entered only where a SIMD lane needs it, as lavapipe runs both sides of an if.
  for (uint once = 0u; once < (straight && !drawnFlat && (flags & kEdgeTame) != 0u ? 1u : 0u);
       ++once) {
    uint corner[3];
    vec3 r[3];
    vec4 w[3];
    loadTriangle(base, corner, r, w);
    drawnFlat = !confvisFlipsOrTears(r[0], r[1], r[2], w[0].xyz, w[1].xyz, w[2].xyz);
  }
  uint none[3] = uint[3](0u, 0u, 0u);  // degenerate: no fragments
  writeFlat(t, drawnFlat ? i : none);
  // The flat list's count is the mesh's triangles less the bent list's and these (UnseenCounts):
  // counting the flat ones instead took a workgroup counter and two barriers, which lavapipe
  // runs as coroutine switches (~15 % of this pass at 1M triangles).
  if (unseen) atomicAdd(unseenCounts[prepass.mesh], 1u);
  else if (straight && !drawnFlat) appendStraight(t);
  else if (!drawnFlat) appendBent(t);
}

void main() {
  uint t = gl_GlobalInvocationID.x;
  if (t < prepass.count) classify(t);
}
