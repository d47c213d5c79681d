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
// Four commands per mesh: [4 m] flat, [4 m + 1] tessellated, [4 m + 2] tessellated with the
// geometry shader that drops pieces, [4 m + 3] flat pieces of split triangles (kListFlat...
// below). Both tessellated lists share
// ComplexIndices and PatchLevels: the first fills the mesh's range from its start, the second
// from its end (its command's firstIndex is left at the range's start; the host knows the count).
layout(set = 2, binding = 5, std430) buffer Commands { DrawCommand commands[]; };
// The scene's distinct edges (vertex pairs) and, laid out like the indices, each triangle's edge
// opposite each corner (mesh_edges.cpp).
layout(set = 2, binding = 6, std430) readonly buffer Edges { uvec2 edges[]; };
layout(set = 2, binding = 7, std430) readonly buffer TriangleEdges { uint triangleEdges[]; };
// Per edge: xyz = warped midpoint relative to c, w = tessellation segments, negative where pieces
// of the edge's triangles may be dropped (classify_edges.comp).
layout(set = 2, binding = 8, std430) buffer EdgeLevels { vec4 edgeLevels[]; };
// Per slot of the tessellated lists, laid out like their indices: the edge levels opposite each
// corner (w: segments, negative where the edge may lose pieces), for warp.tesc
// (confvis_render_common.glsl: set 0, binding 2).
layout(set = 2, binding = 9, std430) writeonly buffer PatchLevels { vec4 patchLevels[]; };

// The pieces list: kPieceCapacity index slots per index of the scene, since a triangle split at
// its edge midpoints makes up to four (classify_bent_triangles.comp); a mesh's part starts at
// kPieceCapacity times its first index.
layout(set = 2, binding = 10, std430) writeonly buffer PieceIndices { uint pieceIndices[]; };
const uint kPieceCapacity = 4u;

// Per mesh: the indirect dispatch of classify_bent_triangles.comp (VkDispatchIndirectCommand,
// groupsX grown by classify_triangles.comp; reset to 0, 1, 1 from the host) and the length of
// the mesh's part of the bent list.
struct BentDispatch {
  uint groupsX;
  uint groupsY;
  uint groupsZ;
  uint count;
};
layout(set = 2, binding = 11, std430) buffer BentDispatches { BentDispatch bentDispatch[]; };
// The bent list: per triangle that classify_triangles.comp could not draw flat, its number in
// its mesh, kBentDrops set where confvisDropTriangle drops it whole; a mesh's part starts at its
// first index / 3.
layout(set = 2, binding = 12, std430) buffer BentTriangles { uint bentTriangles[]; };
const uint kBentDrops = 0x80000000u;
const uint kBentGroup = 64u;  // local_size_x of classify_bent_triangles.comp

// The lookups the bilinear blend alone cannot do (confvisSampleGeomBilinear false: next to the
// cut), queued by warp_vertices.comp and classify_edges.comp for a pass of their own
// (warp_vertices_across_cut.comp, classify_edges_across_cut.comp, dispatched indirectly): lavapipe
// runs both sides of a branch for all SIMD lanes, so a single pass paid the four-texel lookup for
// every vertex and edge (0.13 s of a 0.5 s frame at 1M triangles). [0]: vertices, [1]: edges;
// BentDispatch's layout, reset to 0, 1, 1, 0 from the host.
layout(set = 2, binding = 13, std430) buffer AcrossCutDispatches { BentDispatch acrossCutDispatch[2]; };
layout(set = 2, binding = 14, std430) buffer AcrossCutVertices { uint acrossCutVertices[]; };
layout(set = 2, binding = 15, std430) buffer AcrossCutEdges { uint acrossCutEdges[]; };
const uint kAcrossCutVertices = 0u, kAcrossCutEdges = 1u;

// Queues vertex or edge `item` on across-cut list `list`, growing its dispatch to cover it.
void queueAcrossCut(uint list, uint item) {
  uint slot = atomicAdd(acrossCutDispatch[list].count, 1u);
  if (list == kAcrossCutVertices) acrossCutVertices[slot] = item;
  else acrossCutEdges[slot] = item;
  if (slot % kBentGroup == 0u) atomicMax(acrossCutDispatch[list].groupsX, slot / kBentGroup + 1u);
}

const uint kListFlat = 0u, kListTessellated = 1u, kListDropping = 2u, kListPieces = 3u;
const uint kLists = 4u;

layout(push_constant) uniform Prepass {
  uint count;         // vertices (warp), edges or the mesh's triangles (classify)
  uint mesh;
  uint firstIndex;
  int vertexOffset;
  float maxErrorAngle;
  float maxSegmentAngle;
  float minGap;
  uint midpointBase;  // the scene's vertex count: edge e's midpoint is vertex midpointBase + e
} prepass;

// Virtual point of vertex v in the physical frame, relative to the map's reference point.
vec3 vertexRelative(uint v) {
  vec3 p = vec3(vertices[8u * v], vertices[8u * v + 1u], vertices[8u * v + 2u]);
  return (frame.worldToPhysical * vec4(p, 1.0)).xyz - frame.warpCentre.xyz;
}

// The triangle whose indices start at `base`: its vertex indices, virtual points relative to c
// and warps (warp_vertices.comp).
void loadTriangle(uint base, out uint i[3], out vec3 r[3], out vec4 w[3]) {
  for (uint k = 0u; k < 3u; ++k) {
    i[k] = indices[base + k];
    uint v = uint(prepass.vertexOffset) + i[k];
    r[k] = vertexRelative(v);
    w[k] = warped[v];
  }
}

#endif
