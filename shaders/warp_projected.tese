#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal mode, patches that lose no pieces: tessellated vertices projected with the off-axis
// matrix of the wall for this eye, straight to the fragment shader (as warp.geom does).
#include "confvis_warp_tese.glsl"
#include "confvis_warp_capture.glsl"

layout(location = 0 CONFVIS_XFB(16)) out vec3 outWorld;
layout(location = 1 CONFVIS_XFB(28)) out vec3 outNormal;
layout(location = 2 CONFVIS_XFB(40)) out vec2 outUv;

void main() {
  TessellatedVertex v = tessellatedVertex();
  outWorld = v.world;
  outNormal = v.normal;
  outUv = v.uv;
  gl_Position = currentView().viewProj * vec4(frame.warpCentre.xyz + v.warped.xyz, 1.0);
}
