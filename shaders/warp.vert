#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal mode, triangles that need subdividing: the corners come warped from the pre-pass
// (warp_vertices.comp); the tessellation stages warp only the new vertices.
#include "confvis_render_common.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec4 inWarped;

layout(location = 0) out vec3 outRelative;  // virtual point in the physical frame, relative to c
layout(location = 1) out vec4 outWarped;    // warped point relative to c, w = validity
layout(location = 2) out vec3 outWorld;
layout(location = 3) out vec3 outNormal;
layout(location = 4) out vec2 outUv;

void main() {
  outRelative = (frame.worldToPhysical * vec4(inPosition, 1.0)).xyz - frame.warpCentre.xyz;
  outWarped = inWarped;
  outWorld = inPosition;
  outNormal = inNormal;
  outUv = inUv;
}
