#version 450
#extension GL_GOOGLE_include_directive : require
// Plain mode: the ordinary off-axis view of each wall.
#include "confvis_render_common.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;

layout(location = 0) out vec3 outWorld;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec2 outUv;

void main() {
  outWorld = inPosition;
  outNormal = inNormal;
  outUv = inUv;
  gl_Position = currentView().viewProj * (frame.worldToPhysical * vec4(inPosition, 1.0));
}
