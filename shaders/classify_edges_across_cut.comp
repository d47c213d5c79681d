#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal pre-pass, indirect dispatch over the edges classify_edges.comp queued: their
// midpoints warped by the four-texel lookup across the cut (confvisWarpRelative).
#include "confvis_prepass_edges.glsl"

layout(local_size_x = 64) in;

void main() {
  uint slot = gl_GlobalInvocationID.x;
  if (slot >= acrossCutDispatch[kAcrossCutEdges].count) return;
  uint e = acrossCutEdges[slot];
  writeEdgeLevel(e, confvisWarpRelative(edgeMidpointRelative(e)));
}
