#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal pre-pass, once per frame: every distinct edge of the scene (mesh_edges.cpp) gets its
// warped midpoint and its tessellation level once. The triangles on both sides read the same
// result (classify_triangles.comp, then warp.tesc), so shared edges get the same subdivision
// and leave no cracks; the midpoint's warp is the costly part and is no longer done per triangle
// and per view. This pass finishes the edges the chord tests find straight (most of a finely
// meshed scene's) and queues the others for classify_edges_bent.comp, which measures the smooth
// ones and queues the rest for the four-texel lookup next to the cut (classify_edges_at_cut.comp).
// Lavapipe runs a branch for a whole SIMD group as soon as one lane takes it: measuring the
// 10k smooth edges of a 1M-triangle sphere here cost 30 ms of a 55 ms pass, packed together in
// the queue 3 ms. A coarse scene, whose edges mostly bend, pays ~1 ms for the queue (20k
// triangles).
#include "confvis_prepass_edges.glsl"

layout(local_size_x = 64) in;

void main() {
  uint e = gl_GlobalInvocationID.x;
  if (e >= prepass.count) return;
  EdgeEnds ends = loadEdgeEnds(e);
  vec4 midpoint;
  bool plain = confvisWarpRelativeBilinear(0.5 * (ends.ra + ends.rb), midpoint);
  bool straight = plain && edgeSurelyStraight(ends, normalize(midpoint.xyz));
  if (straight) writeStraightEdgeLevel(e, ends, midpoint);
  else enqueue(kQueueEdges, e);
}
