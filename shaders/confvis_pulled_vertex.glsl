// The tessellation pipelines' vertex shader (warp.vert) reads its vertices itself (set 0,
// bindings 3-5; backends/vulkan/src/frame_renderer.cpp writes them): the scene's vertices with the
// pre-pass's warps (warp_vertices.comp).
#ifndef CONFVIS_PULLED_VERTEX_GLSL
#define CONFVIS_PULLED_VERTEX_GLSL

#include "confvis_render_common.glsl"

layout(set = 0, binding = 3, std430) readonly buffer TessellatedIndices { uint tessellatedIndices[]; };
// Vertices as uploaded (position, normal, uv: 8 floats each).
layout(set = 0, binding = 4, std430) readonly buffer SceneVertices { float sceneVertices[]; };
layout(set = 0, binding = 5, std430) readonly buffer Warped { vec4 warped[]; };

struct PulledVertex {
  vec3 position;  // world (virtual)
  vec3 normal;
  vec2 uv;
  vec4 warped;    // relative to c, w = validity
};

PulledVertex sceneVertex(uint v) {
  uint at = 8u * v;
  PulledVertex p;
  p.position = vec3(sceneVertices[at], sceneVertices[at + 1u], sceneVertices[at + 2u]);
  p.normal = vec3(sceneVertices[at + 3u], sceneVertices[at + 4u], sceneVertices[at + 5u]);
  p.uv = vec2(sceneVertices[at + 6u], sceneVertices[at + 7u]);
  p.warped = warped[v];
  return p;
}

#endif
