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
  vec4 w = confvisWarpRelative(r);
  float distance = length(r);
  for (uint once = 0u; once < (prepass.snapCutToRim != 0u && distance > 1e-9 ? 1u : 0u); ++once)
    w.xyz = distance * confvisRefineOnRayMap(r / distance, normalize(w.xyz));
  warped[v] = keptWarp(w);
}
