#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal pre-pass, once per frame: every distinct edge of the scene (mesh_edges.cpp) gets its
// warped midpoint and its tessellation level once. The triangles on both sides read the same
// result (classify_triangles.comp, then warp.tesc), so shared edges get the same subdivision
// and leave no cracks; the midpoint's warp is the costly part and is no longer done per triangle
// and per view. This pass finishes the straight edges (most of a finely meshed scene's) by cheap
// tests; the others, and those whose midpoint the bilinear blend cannot warp (next to the cut),
// are queued for classify_edges_bent.comp.
#include "confvis_prepass_edges.glsl"

layout(local_size_x = 64) in;

void main() {
  uint e = gl_GlobalInvocationID.x;
  if (e >= prepass.count) return;
  vec4 midpoint;
  bool plain = confvisWarpRelativeBilinear(edgeMidpointRelative(e), midpoint);
  if (plain && edgeSurelyStraight(e, midpoint)) writeStraightEdgeLevel(e, midpoint);
  else enqueue(kQueueEdges, e);
}
