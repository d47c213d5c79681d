#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal mode: subdivide each triangle by how much the warp bends its edges.
#include "confvis_render_common.glsl"
#include "confvis_warp.glsl"

layout(vertices = 3) out;

layout(location = 0) in vec3 inRelative[];
layout(location = 1) in vec4 inWarped[];
layout(location = 2) in vec3 inWorld[];
layout(location = 3) in vec3 inNormal[];
layout(location = 4) in vec2 inUv[];

layout(location = 0) out vec3 outRelative[];
layout(location = 1) out vec4 outWarped[];
layout(location = 2) out vec3 outWorld[];
layout(location = 3) out vec3 outNormal[];
layout(location = 4) out vec2 outUv[];

float segments(int i, int j) {
  vec4 params = wallView().params;
  if (params.w == 0.0) return 1.0;
  return confvisEdgeSegments(inRelative[i], inRelative[j], inWarped[i].xyz, inWarped[j].xyz,
                             params.x, params.y);
}

void main() {
  outRelative[gl_InvocationID] = inRelative[gl_InvocationID];
  outWarped[gl_InvocationID] = inWarped[gl_InvocationID];
  outWorld[gl_InvocationID] = inWorld[gl_InvocationID];
  outNormal[gl_InvocationID] = inNormal[gl_InvocationID];
  outUv[gl_InvocationID] = inUv[gl_InvocationID];
  if (gl_InvocationID == 0) {
    if (max(inWarped[0].w, max(inWarped[1].w, inWarped[2].w)) < 0.5) {
      // Entirely outside the source field: nothing of it is shown.
      gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = 0.0;
      gl_TessLevelInner[0] = 0.0;
      return;
    }
    // Outer level k belongs to the edge opposite corner k.
    float e0 = segments(1, 2), e1 = segments(2, 0), e2 = segments(0, 1);
    gl_TessLevelOuter[0] = e0;
    gl_TessLevelOuter[1] = e1;
    gl_TessLevelOuter[2] = e2;
    gl_TessLevelInner[0] = max(e0, max(e1, e2));
  }
}
