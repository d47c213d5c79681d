#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal pre-pass, once per frame: every scene vertex warped once, for all walls and eyes.
// Those the bilinear blend cannot warp (next to the cut) are queued for
// warp_vertices_across_cut.comp.
#include "confvis_warp.glsl"
#include "confvis_prepass_common.glsl"

layout(local_size_x = 64) in;

void main() {
  uint v = gl_GlobalInvocationID.x;
  if (v >= prepass.count) return;
  vec3 r = transformVertex(v);
  relative[v] = vec4(r, 0.0);
  vec4 w;
  bool plain = confvisWarpRelativeBilinear(r, w);
  warped[v] = keptWarp(w);
  if (!plain) enqueue(kQueueVertices, v);
}
