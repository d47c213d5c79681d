#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal mode, triangles that need subdividing: the corners come warped from the pre-pass
// (warp_vertices.comp); the tessellation stages warp only the new vertices.
//
// Drawn without an index buffer: vertex i of the draw is corner i % 3 of slot i / 3 of the
// pre-pass's tessellated lists, whose indices, vertices and warps this shader reads itself. The
// slot tells warp.tesc where the patch's edge levels are. gl_PrimitiveID cannot: Mesa's lavapipe
// 22.3 restarts it within large indexed draws (cracks between patches that read their
// neighbours' levels, and stray triangles through the geometry shader), which had the lists
// drawn 16 patches a draw, thousands of draws a frame.
#include "confvis_pulled_vertex.glsl"

layout(location = 0) out vec3 outRelative;  // virtual point in the physical frame, relative to c
layout(location = 1) out vec4 outWarped;    // warped point relative to c, w = validity
layout(location = 2) out vec3 outWorld;
layout(location = 3) out vec3 outNormal;
layout(location = 4) out vec2 outUv;
layout(location = 5) flat out uint outSlot;

void main() {
  PulledVertex v = sceneVertex(uint(int(tessellatedIndices[gl_VertexIndex]) + push.vertexOffset));
  outRelative = (frame.worldToPhysical * vec4(v.position, 1.0)).xyz - frame.warpCentre.xyz;
  outWarped = v.warped;
  outWorld = v.position;
  outNormal = v.normal;
  outUv = v.uv;
  outSlot = uint(gl_VertexIndex) / 3u;
}
