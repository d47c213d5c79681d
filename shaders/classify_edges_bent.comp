#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal pre-pass, indirect dispatch over the edges classify_edges.comp queued (those its chord
// tests do not find straight): the smoothly bent ones measured from the midpoint's bilinear warp
// (most of them); the others (which may span the cut) queued for classify_edges_at_cut.comp.
#include "confvis_prepass_edges.glsl"

layout(local_size_x = 64) in;

void main() {
  uint slot = gl_GlobalInvocationID.x;
  if (slot >= queueDispatch[kQueueEdges].count) return;
  uint e = queuedEdges[slot];
  EdgeEnds ends = loadEdgeEnds(e);
  vec4 midpoint;
  bool bentSmoothly = confvisWarpRelativeBilinear(0.5 * (ends.ra + ends.rb), midpoint);
  // A loop entered once or not at all (lavapipe runs both sides of an if for all SIMD lanes).
  for (uint once = 0u; once < (bentSmoothly ? 1u : 0u); ++once)
    bentSmoothly = edgeSurelyWithoutJump(ends, normalize(midpoint.xyz));
  for (uint once = 0u; once < (bentSmoothly ? 1u : 0u); ++once)
    writeSmoothEdgeLevel(e, ends, midpoint);
  if (!bentSmoothly) enqueue(kQueueEdgesAtCut, e);
}
