#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal mode: drop tessellated triangles that straddle the source's cut or leave the source
// field, project the rest with the off-axis matrix of the wall for this eye.
#include "confvis_render_common.glsl"
#include "confvis_warp.glsl"

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

layout(location = 0) in vec3 inRelative[];
layout(location = 1) in vec4 inWarped[];
layout(location = 2) in vec3 inWorld[];
layout(location = 3) in vec3 inNormal[];
layout(location = 4) in vec2 inUv[];

layout(location = 0) out vec3 outWorld;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec2 outUv;

void main() {
  View view = currentView();
  if (confvisDropTriangle(inRelative[0], inRelative[1], inRelative[2], inWarped[0], inWarped[1],
                          inWarped[2], view.params.z))
    return;
  for (int i = 0; i < 3; ++i) {
    outWorld = inWorld[i];
    outNormal = inNormal[i];
    outUv = inUv[i];
    gl_Position = view.viewProj * vec4(frame.warpCentre.xyz + inWarped[i].xyz, 1.0);
    EmitVertex();
  }
  EndPrimitive();
}
