#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal pre-pass, once per frame: every distinct edge of the scene (mesh_edges.cpp) gets its
// warped midpoint and its tessellation level once. The triangles on both sides read the same
// result (classify_triangles.comp, then warp.tesc), so shared edges get the same subdivision
// and leave no cracks; the midpoint's warp is the costly part and is no longer done per triangle
// and per view. This pass finishes the edges whose midpoint the bilinear blend warps and whose
// halves surely span no jump: the straight ones by chord tests alone (most of a finely meshed
// scene's), the bent ones by the measurement itself; the others (next to the cut) are queued for
// classify_edges_bent.comp. (Before, every edge too long for the straight test was queued: all
// of a 20k-triangle scene's, 2.6 ms of its 9.5 ms pre-pass on lavapipe, which ran the
// four-texel lookup for each.)
#include "confvis_prepass_edges.glsl"

layout(local_size_x = 64) in;

void main() {
  uint e = gl_GlobalInvocationID.x;
  if (e >= prepass.count) return;
  EdgeEnds ends = loadEdgeEnds(e);
  vec4 midpoint;
  bool plain = confvisWarpRelativeBilinear(0.5 * (ends.ra + ends.rb), midpoint);
  vec3 um = normalize(midpoint.xyz);
  bool straight = plain && edgeSurelyStraight(ends, um);
  if (straight) writeStraightEdgeLevel(e, ends, midpoint);
  // Loops run once or not at all: lavapipe runs both sides of an if (and of &&) for all SIMD
  // lanes but leaves a loop that no lane runs, and the tests and atans below are wasted on the
  // straight edges, most of a finely meshed scene's (evaluated for every edge, they cost 20 ms of
  // a 1M-triangle frame).
  bool bentSmoothly = false;
  for (uint once = 0u; once < (plain && !straight ? 1u : 0u); ++once)
    bentSmoothly = edgeSurelyWithoutJump(ends, um);
  for (uint once = 0u; once < (bentSmoothly ? 1u : 0u); ++once)
    writeSmoothEdgeLevel(e, ends, midpoint);
  if (!straight && !bentSmoothly) enqueue(kQueueEdges, e);
}
