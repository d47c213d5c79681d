#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal mode, the flat pieces of the triangles the pre-pass split at their edge midpoints
// (classify_triangles.comp): drawn flat between the warps it measured (warp_vertices.comp,
// classify_edges.comp), from the vertices this shader reads itself. (The unsplit flat triangles
// keep warp_simple.vert: fixed-function vertex fetch is faster on lavapipe, 1M triangles.)
#include "confvis_pulled_vertex.glsl"

layout(location = 0) out vec3 outWorld;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec2 outUv;

void main() {
  PulledVertex v = pulledVertex(uint(gl_VertexIndex));
  outWorld = v.position;
  outNormal = v.normal;
  outUv = v.uv;
  gl_Position = currentView().viewProj * vec4(frame.warpCentre.xyz + v.warped.xyz, 1.0);
}
