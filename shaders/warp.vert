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
#include "confvis_render_common.glsl"

layout(set = 0, binding = 3, std430) readonly buffer TessellatedIndices { uint tessellatedIndices[]; };
layout(set = 0, binding = 4, std430) readonly buffer SceneVertices { float sceneVertices[]; };
layout(set = 0, binding = 5, std430) readonly buffer Warped { vec4 warped[]; };

layout(location = 0) out vec3 outRelative;  // virtual point in the physical frame, relative to c
layout(location = 1) out vec4 outWarped;    // warped point relative to c, w = validity
layout(location = 2) out vec3 outWorld;
layout(location = 3) out vec3 outNormal;
layout(location = 4) out vec2 outUv;
layout(location = 5) flat out uint outSlot;

void main() {
  uint v = uint(int(tessellatedIndices[gl_VertexIndex]) + push.vertexOffset);
  uint at = 8u * v;  // position, normal, uv
  vec3 position = vec3(sceneVertices[at], sceneVertices[at + 1u], sceneVertices[at + 2u]);
  outRelative = (frame.worldToPhysical * vec4(position, 1.0)).xyz - frame.warpCentre.xyz;
  outWarped = warped[v];
  outWorld = position;
  outNormal = vec3(sceneVertices[at + 3u], sceneVertices[at + 4u], sceneVertices[at + 5u]);
  outUv = vec2(sceneVertices[at + 6u], sceneVertices[at + 7u]);
  outSlot = uint(gl_VertexIndex) / 3u;
}
