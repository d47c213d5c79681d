#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal pre-pass, indirect dispatch over the vertices warp_vertices.comp queued: warped by
// the four-texel lookup across the cut (confvisWarpRelative), then, next to the cut's ends, moved to
// where the ray map shows them (confvisRefineOnRayMap, confvis_warp_rim.glsl).
#include "confvis_warp.glsl"
#include "confvis_prepass_common.glsl"

layout(local_size_x = 64) in;

void main() {
  uint slot = gl_GlobalInvocationID.x;
  if (slot >= queueDispatch[kQueueVertices].count) return;
  uint v = queuedVertices[slot];
  vec3 r = vertexRelative(v);
  warped[v] = keptWarp(
      confvisRefineWarpOnRayMap(r, confvisWarpRelative(r), prepass.snapCutToRim != 0u));
}
