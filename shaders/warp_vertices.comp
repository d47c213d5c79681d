#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal pre-pass, once per frame: every scene vertex warped once, for all walls and eyes.
#include "confvis_warp.glsl"
#include "confvis_prepass_common.glsl"

layout(local_size_x = 64) in;

void main() {
  uint v = gl_GlobalInvocationID.x;
  if (v >= prepass.count) return;
  warped[v] = confvisWarpRelative(vertexRelative(v));
}
