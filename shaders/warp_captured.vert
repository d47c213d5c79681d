#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal mode, the tessellated lists captured once a frame (confvis_warp_capture.glsl): each
// wall and eye projects the warped physical points with its own off-axis matrix.
#include "confvis_render_common.glsl"

layout(location = 0) in vec4 inPhysical;  // c + T(x - c), w = 1
layout(location = 1) in vec3 inWorld;
layout(location = 2) in vec3 inNormal;
layout(location = 3) in vec2 inUv;

layout(location = 0) out vec3 outWorld;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec2 outUv;

void main() {
  outWorld = inWorld;
  outNormal = inNormal;
  outUv = inUv;
  gl_Position = currentView().viewProj * inPhysical;
}
