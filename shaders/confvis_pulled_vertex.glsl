// The conformal pipelines' vertex shaders read their vertices themselves (set 0, bindings 3-8;
// backends/vulkan/src/frame_renderer.cpp writes them): vertex numbers below push.midpointBase
// are the scene's vertices with the pre-pass's warps, number midpointBase + e is the midpoint of
// the scene's edge e with the warp the pre-pass measured for it (classify_edges.comp). The
// pre-pass splits triangles that bend by two segments at most into flat pieces between corners
// and edge midpoints (classify_bent_triangles.comp); the tessellation stages use the same midpoint
// warps, so both ways of drawing an edge meet bit for bit.
#ifndef CONFVIS_PULLED_VERTEX_GLSL
#define CONFVIS_PULLED_VERTEX_GLSL

#include "confvis_render_common.glsl"

layout(set = 0, binding = 3, std430) readonly buffer TessellatedIndices { uint tessellatedIndices[]; };
// Vertices as uploaded (position, normal, uv: 8 floats each).
layout(set = 0, binding = 4, std430) readonly buffer SceneVertices { float sceneVertices[]; };
layout(set = 0, binding = 5, std430) readonly buffer Warped { vec4 warped[]; };
layout(set = 0, binding = 6, std430) readonly buffer Edges { uvec2 edges[]; };
layout(set = 0, binding = 7, std430) readonly buffer EdgeLevels { vec4 edgeLevels[]; };
// The pre-pass's vertices on the source's cut (confvis_prepass_common.glsl): vertex number
// kCutVertexBit + s is slot s.
struct CutVertex {
  vec4 position;
  vec4 normal;
  vec4 uv;
  vec4 warped;
};
layout(set = 0, binding = 8, std430) readonly buffer CutVertices { CutVertex cutVertices[]; };
const uint kCutVertexBit = 0x80000000u;

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

PulledVertex pulledVertex(uint v) {
  if (v >= kCutVertexBit) {
    CutVertex c = cutVertices[v - kCutVertexBit];
    return PulledVertex(c.position.xyz, c.normal.xyz, c.uv.xy, c.warped);
  }
  if (v < push.midpointBase) return sceneVertex(v);
  uint e = v - push.midpointBase;
  PulledVertex a = sceneVertex(edges[e].x), b = sceneVertex(edges[e].y);
  PulledVertex m;
  m.position = 0.5 * (a.position + b.position);
  m.normal = 0.5 * (a.normal + b.normal);
  m.uv = 0.5 * (a.uv + b.uv);
  // Split triangles lie inside the source field (classify_bent_triangles.comp).
  m.warped = vec4(edgeLevels[e].xyz, 1.0);
  return m;
}

#endif
