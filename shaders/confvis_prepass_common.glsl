// Resources of the conformal pre-pass compute shaders (backends/vulkan/src/conformal_prepass.cpp
// creates the matching layout). Set 0 is the frame set of confvis_render_common.glsl, set 1 the
// warp map (confvis_warp.glsl), set 2 the scene's buffers and the pre-pass outputs.
#ifndef CONFVIS_PREPASS_COMMON_GLSL
#define CONFVIS_PREPASS_COMMON_GLSL

#include "confvis_frame.glsl"

struct DrawCommand {  // VkDrawIndexedIndirectCommand
  uint indexCount;
  uint instanceCount;
  uint firstIndex;
  int vertexOffset;
  uint firstInstance;
};

// Vertices as uploaded (position, normal, uv: 8 floats each).
layout(set = 2, binding = 0, std430) readonly buffer Vertices { float vertices[]; };
layout(set = 2, binding = 1, std430) readonly buffer Indices { uint indices[]; };
layout(set = 2, binding = 2, std430) buffer Warped { vec4 warped[]; };
layout(set = 2, binding = 3, std430) writeonly buffer SimpleIndices { uint simpleIndices[]; };
layout(set = 2, binding = 4, std430) writeonly buffer ComplexIndices { uint complexIndices[]; };
// Two commands per mesh: [2 m] simple, [2 m + 1] tessellated.
layout(set = 2, binding = 5, std430) buffer Commands { DrawCommand commands[]; };

layout(push_constant) uniform Prepass {
  uint count;         // vertices (warp) or the mesh's triangles (classify)
  uint mesh;
  uint firstIndex;
  int vertexOffset;
  float maxErrorAngle;
  float maxSegmentAngle;
  float minGap;
} prepass;

// Virtual point of vertex v in the physical frame, relative to the map's reference point.
vec3 vertexRelative(uint v) {
  vec3 p = vec3(vertices[8u * v], vertices[8u * v + 1u], vertices[8u * v + 2u]);
  return (frame.worldToPhysical * vec4(p, 1.0)).xyz - frame.warpCentre.xyz;
}

#endif
