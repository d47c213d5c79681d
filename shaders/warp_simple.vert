#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal mode, triangles the pre-pass found straight enough and the pieces of those it split:
// drawn flat between the corners it warped (classify_triangles.comp), edge midpoints and points
// on the source's cut (classify_bent_triangles.comp; GpuScene numbers them after the scene's
// vertices, with their warps in the same buffer).
#include "confvis_render_common.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec4 inWarped;  // from warp_vertices.comp, relative to c

layout(location = 0) out vec3 outWorld;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec2 outUv;

void main() {
  outWorld = inPosition;
  outNormal = inNormal;
  outUv = inUv;
  gl_Position = currentView().viewProj * vec4(frame.warpCentre.xyz + inWarped.xyz, 1.0);
}
