#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal mode: place the tessellated vertices on the virtual triangle and warp them.
#include "confvis_render_common.glsl"
#include "confvis_warp.glsl"

layout(triangles, equal_spacing, ccw) in;

layout(location = 0) in vec3 inRelative[];
layout(location = 1) in vec4 inWarped[];
layout(location = 2) in vec3 inWorld[];
layout(location = 3) in vec3 inNormal[];
layout(location = 4) in vec2 inUv[];

layout(location = 0) out vec3 outRelative;
layout(location = 1) out vec4 outWarped;
layout(location = 2) out vec3 outWorld;
layout(location = 3) out vec3 outNormal;
layout(location = 4) out vec2 outUv;

void main() {
  vec3 b = gl_TessCoord;
  outWorld = b.x * inWorld[0] + b.y * inWorld[1] + b.z * inWorld[2];
  outNormal = b.x * inNormal[0] + b.y * inNormal[1] + b.z * inNormal[2];
  outUv = b.x * inUv[0] + b.y * inUv[1] + b.z * inUv[2];
  precise vec3 relative = b.x * inRelative[0] + b.y * inRelative[1] + b.z * inRelative[2];
  outRelative = relative;
  // Corners keep the vertex stage's warp (bitwise equal in every patch that shares them).
  if (b.x == 1.0) outWarped = inWarped[0];
  else if (b.y == 1.0) outWarped = inWarped[1];
  else if (b.z == 1.0) outWarped = inWarped[2];
  else outWarped = confvisWarpRelative(relative);
}
