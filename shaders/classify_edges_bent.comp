#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal pre-pass, indirect dispatch over the edges classify_edges.comp queued (those that may
// bend, stretch or span the cut): their midpoints warped by the full lookup (four texels across
// the cut, confvisWarpRelative) and their levels measured.
#include "confvis_prepass_edges.glsl"

layout(local_size_x = 64) in;

void main() {
  uint slot = gl_GlobalInvocationID.x;
  if (slot >= queueDispatch[kQueueEdges].count) return;
  uint e = queuedEdges[slot];
  EdgeEnds ends = loadEdgeEnds(e);
  writeEdgeLevel(e, ends, confvisWarpRelative(0.5 * (ends.ra + ends.rb)));
}
