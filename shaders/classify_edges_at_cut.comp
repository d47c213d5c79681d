#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal pre-pass, indirect dispatch over the edges classify_edges_bent.comp queued (those that
// may span the cut or leave the bilinear blend): their midpoints warped by the full lookup (four
// texels across the cut, confvisWarpRelative) and their levels measured, cut vertices included.
// A pass of their own: in the bent edges' pass they lay scattered among the smooth ones, and
// lavapipe ran the lookup for every SIMD group holding one (12 ms of a 20k-triangle pre-pass).
#include "confvis_prepass_edges.glsl"

layout(local_size_x = 64) in;

void main() {
  uint slot = gl_GlobalInvocationID.x;
  if (slot >= queueDispatch[kQueueEdgesAtCut].count) return;
  uint e = queuedEdges[uint(queuedEdges.length()) / 2u + slot];
  EdgeEnds ends = loadEdgeEnds(e);
  writeEdgeLevel(e, ends, confvisWarpRelative(0.5 * (ends.ra + ends.rb)));
}
