// Resources of the conformal pre-pass compute shaders (backends/vulkan/src/conformal_prepass.cpp
// creates the matching layout). Set 0 is the frame set of confvis_render_common.glsl, set 1 the
// warp map (confvis_warp.glsl), set 2 the scene's buffers and the pre-pass outputs.
#ifndef CONFVIS_PREPASS_COMMON_GLSL
#define CONFVIS_PREPASS_COMMON_GLSL

#include "confvis_frame.glsl"
#include "confvis_warp.glsl"

struct DrawCommand {  // VkDrawIndexedIndirectCommand
  uint indexCount;
  uint instanceCount;
  uint firstIndex;
  int vertexOffset;
  uint firstInstance;
};

// Vertices as uploaded (position, normal, uv: 8 floats each).
layout(set = 2, binding = 0, std430) readonly buffer Vertices { float vertices[]; };
// Binding 1: CutDispatches below (the indices are read through indexTexels).
// Per scene vertex: its warp relative to c, w = validity. The first part of the warps the draws
// read (backends/vulkan/src/gpu_scene.hpp): the edge midpoints' (EdgeLevels) and the cut
// vertices' (CutWarps) follow it.
layout(set = 2, binding = 2, std430) buffer Warped { vec4 warped[]; };
layout(set = 2, binding = 3, std430) writeonly buffer SimpleIndices { uint simpleIndices[]; };
layout(set = 2, binding = 4, std430) writeonly buffer ComplexIndices { uint complexIndices[]; };
// Four commands per mesh: [4 m] flat (the mesh's whole range, see writeFlat), [4 m + 1] tessellated, [4 m + 2] tessellated with the
// geometry shader that drops pieces, [4 m + 3] flat pieces of split triangles (kListFlat...
// below). Both tessellated lists share
// ComplexIndices and PatchLevels: the first fills the mesh's range from its start, the second
// from its end (its command's firstIndex is left at the range's start; the host knows the count).
layout(set = 2, binding = 5, std430) buffer Commands { DrawCommand commands[]; };
// Binding 6: CutTriangles below; binding 7: unused (the edges and the triangles' edges are read
// through edgeTexels and triangleEdgeTexels).
// Per edge: xyz = warped midpoint relative to c, w = tessellation segments, negative where pieces
// of the edge's triangles may be dropped (classify_edges.comp). The midpoints' part of Warped, so
// the flat pieces draw the midpoints by index with fixed-function fetch (warp_simple.vert).
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
// its mesh; a mesh's part starts at its first index / 3.
layout(set = 2, binding = 12, std430) buffer BentTriangles { uint bentTriangles[]; };
const uint kBentGroup = 64u;  // local_size_x of classify_bent_triangles.comp

// The few vertices and edges the cheap first passes cannot finish, queued by warp_vertices.comp
// (lookups the bilinear blend alone cannot do: confvisSampleGeomBilinear false, next to the cut)
// and classify_edges.comp (the edges that may bend, stretch or span the cut) for passes of their
// own (warp_vertices_across_cut.comp, classify_edges_bent.comp, dispatched
// indirectly): lavapipe runs both sides of a branch for all SIMD lanes, so in one pass every
// vertex and edge paid for the four-texel lookup and the full edge measurement (0.13 s of a 0.5 s
// frame at 1M triangles). [0]: vertices, [1]: edges; BentDispatch's layout, reset to 0, 1, 1, 0
// from the host.
layout(set = 2, binding = 13, std430) buffer QueueDispatches { BentDispatch queueDispatch[4]; };
layout(set = 2, binding = 14, std430) buffer QueuedVertices { uint queuedVertices[]; };
layout(set = 2, binding = 15, std430) buffer QueuedEdges { uint queuedEdges[]; };
const uint kQueueVertices = 0u, kQueueEdges = 1u;
// [3]: the bent edges that classify_edges_bent.comp cannot find smooth, for the four-texel lookup
// next to the cut (classify_edges_at_cut.comp), in the second half of QueuedEdges.
const uint kQueueEdgesAtCut = 3u;
// [2].count: the cut vertices' slots taken so far (CutVertices below), [2].groupsX: the triangles
// split along the cut (for the frame's statistics).
const uint kQueueCutVertices = 2u;

// The ray map (kCoverageBinding of the warp set, confvis_warp_rim.glsl), for its alpha: where
// the display shows a physical direction, as the backward path (Embree) sees it. Its rim is the
// image of the cut.
#include "confvis_warp_rim.glsl"

// Per mesh: its triangles entirely outside the source field, reset from the host. The flat
// list's triangles that are not degenerate (writeFlat), for the frame's statistics, are the
// mesh's triangles less these and its bent list's.
layout(set = 2, binding = 16, std430) buffer UnseenCounts { uint unseenCounts[]; };
// Per edge, what classify_triangles.comp needs of it (confvis_prepass_edges.glsl writes it):
// kEdgeStraight where it is drawn in one segment, kEdgeSmall where its warped corners lie
// within minGap of each other (a triangle of three straight and small edges is drawn flat:
// confvisDropTriangle keeps it), kEdgeUnseen where both corners lie outside the source field (a
// triangle of three such edges shows nothing).
layout(set = 2, binding = 17, std430) buffer EdgeFlags { uint edgeFlags[]; };
// kEdgeAcrossCut where the edge spans the source's cut (confvisHalvesSpanJump on its halves).
// kEdgeOutside where a corner or the midpoint lies outside the source field (validity below
// 0.5): only then can the geometry shader drop pieces of its triangles for being outside.
// kEdgeTame where the warped edge's chord is at most 0.4 and 16 times the virtual one's (with
// surelyKept's 1 % margin): a triangle of three such edges passes surelyKept's chord rules, and
// only its shape is left to test (classify_triangles.comp).
const uint kEdgeStraight = 1u, kEdgeSmall = 2u, kEdgeUnseen = 4u, kEdgeAcrossCut = 8u,
           kEdgeOutside = 16u, kEdgeTame = 32u;

// Per mesh, as the bent list: the straight triangles too large after the warp for
// classify_triangles.comp to tell whether confvisDropTriangle keeps them, for
// classify_straight_triangles.comp.
layout(set = 2, binding = 18, std430) buffer StraightDispatches { BentDispatch straightDispatch[]; };
layout(set = 2, binding = 19, std430) buffer StraightTriangles { uint straightTriangles[]; };

// Per mesh, as the bent list: the bent triangles the source's cut crosses that may be split
// along it, queued by classify_bent_triangles.comp for split_triangles_at_cut.comp.
layout(set = 2, binding = 1, std430) buffer CutDispatches { BentDispatch cutDispatch[]; };
layout(set = 2, binding = 6, std430) buffer CutTriangles { uint cutTriangles[]; };

// Queues vertex or edge `item` on `queue`, growing its dispatch to cover it.
void enqueue(uint queue, uint item) {
  uint slot = atomicAdd(queueDispatch[queue].count, 1u);
  uint atCut = queue == kQueueEdgesAtCut ? uint(queuedEdges.length()) / 2u : 0u;  // its half
  if (queue == kQueueVertices) queuedVertices[slot] = item;
  else queuedEdges[atCut + slot] = item;
  if (slot % kBentGroup == 0u) atomicMax(queueDispatch[queue].groupsX, slot / kBentGroup + 1u);
}

// Chord between the directions of two non-zero vectors: 2 sin(angle / 2), a lower bound of the
// angle and monotone in it, with no atan. A cheap and conservative pre-test of angle <= limit is
// chordBelow(chord, limit): NaN (zero vectors) counts as not below.
float directionChord(vec3 a, vec3 b) { return length(normalize(a) - normalize(b)); }
bool chordBelow(float chord, float limit) {
  return chord <= 0.99 * 2.0 * sin(0.5 * limit);  // 1 % margin for the two functions' rounding
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
  uint midpointBase;  // edge e's midpoint is vertex midpointBase + e (GpuScene::midpointBase)
  float maxGap;       // minGap of the view that tolerates the widest gap (minGap: the strictest)
  uint splitAlongCut; // VulkanOptions::splitAlongCut (classify_bent_triangles.comp)
  uint cutVertexBase; // cut vertex slot s is vertex cutVertexBase + s (GpuScene::cutVertexBase)
  uint errorWallCount; // ErrorWalls entries in use
  uint snapCutToRim;  // VulkanOptions::snapCutToRim (classify_edges_at_cut.comp)
  uint dropOutside;   // VulkanOptions::dropOutsideSourceField (keptValidity)
} prepass;

// The validity the pre-pass keeps for a warp (of a vertex or an edge's midpoint): 1, so that
// nothing is dropped or sent to the geometry shader for lying outside the source field, unless
// prepass.dropOutside. The map's extension beyond the field (the analytic maps' closed form, a
// baked map's extrapolated rings) places such points beyond the rim seen from c, where no wall
// pixel is lit from c; but from an eye off c the part of them inside the room shows on the walls,
// next to the rim, where Embree's rays, bent through the ray map's extension, draw it too. Dropped,
// they left a saw-toothed band of a 0.6 m ceiling unshown along the top of the CAVE's side walls
// with the head 20 cm off c (issue 23).
float keptValidity(float validity) { return prepass.dropOutside != 0u ? validity : 1.0; }
vec4 keptWarp(vec4 warp) { return vec4(warp.xyz, keptValidity(warp.w)); }

// Writes triangle t (vertex indices i) of the current mesh into its flat list, whose slots are
// the mesh's own index range: classify_triangles.comp fills every slot, with a degenerate
// triangle (no fragments) where the triangle is drawn otherwise or not at all. No compaction:
// appending 1M triangles through one atomic counter cost more than the degenerate ones, and the
// scene's own order keeps the vertex cache warm.
void writeFlat(uint t, uint i[3]) {
  uint at = prepass.firstIndex + 3u * t;
  simpleIndices[at] = i[0]; simpleIndices[at + 1u] = i[1]; simpleIndices[at + 2u] = i[2];
}

// Appends triangle t of the current mesh to its bent list, growing the list's dispatch (the first
// of each workgroup's worth of slots).
void appendBent(uint t) {
  uint slot = atomicAdd(bentDispatch[prepass.mesh].count, 1u);
  bentTriangles[prepass.firstIndex / 3u + slot] = t;
  if (slot % kBentGroup == 0u) atomicMax(bentDispatch[prepass.mesh].groupsX, slot / kBentGroup + 1u);
}

// The same for the straight list.
void appendStraight(uint t) {
  uint slot = atomicAdd(straightDispatch[prepass.mesh].count, 1u);
  straightTriangles[prepass.firstIndex / 3u + slot] = t;
  if (slot % kBentGroup == 0u) atomicMax(straightDispatch[prepass.mesh].groupsX, slot / kBentGroup + 1u);
}

// The same for the cut list (classify_bent_triangles.comp).
void appendAtCut(uint t) {
  uint slot = atomicAdd(cutDispatch[prepass.mesh].count, 1u);
  cutTriangles[prepass.firstIndex / 3u + slot] = t;
  if (slot % kBentGroup == 0u) atomicMax(cutDispatch[prepass.mesh].groupsX, slot / kBentGroup + 1u);
}

// Per vertex: its virtual point in the physical frame relative to the map's reference point
// (xyz), written once by warp_vertices.comp; the later passes read it instead of transforming the
// vertex again (each edge and triangle reads two or three).
layout(set = 2, binding = 20, std430) buffer Relative { vec4 relative[]; };

// The same data as some of the storage buffers above, as uniform texel buffers (PrepassTexels
// of backends/vulkan/src/pipelines.hpp), for the reads of the passes over every vertex, edge and
// triangle: lavapipe gathers a texel fetch for all SIMD lanes at once but loads from a storage
// buffer lane by lane (an edge's two warps cost 6 ms of a 1M-triangle edge pass as storage
// loads, 1 ms as texel fetches). Written through the storage buffers, read through these after
// the pass that wrote them.
layout(set = 2, binding = 25) uniform samplerBuffer vertexTexels;    // Vertices, 2 texels each
layout(set = 2, binding = 26) uniform samplerBuffer relativeTexels;  // Relative
layout(set = 2, binding = 27) uniform samplerBuffer warpedTexels;    // Warped, scene vertices
// The scene's distinct edges (vertex pairs) and, laid out like the indices, each triangle's edge
// opposite each corner (mesh_edges.cpp).
layout(set = 2, binding = 28) uniform usamplerBuffer edgeTexels;
layout(set = 2, binding = 29) uniform usamplerBuffer indexTexels;    // the scene's indices
layout(set = 2, binding = 30) uniform usamplerBuffer triangleEdgeTexels;
layout(set = 2, binding = 31) uniform usamplerBuffer edgeFlagTexels;  // EdgeFlags

vec4 vertexWarp(uint v) { return texelFetch(warpedTexels, int(v)); }
uvec2 sceneEdge(uint e) { return texelFetch(edgeTexels, int(e)).xy; }
uint sceneIndex(uint at) { return texelFetch(indexTexels, int(at)).x; }
uint triangleEdge(uint at) { return texelFetch(triangleEdgeTexels, int(at)).x; }
uint edgeFlagsOf(uint e) { return texelFetch(edgeFlagTexels, int(e)).x; }

// The vertices split_triangles_at_cut.comp makes where the source's cut crosses an edge, one
// per side: the point on the cut with that side's limit of the warp, for the pieces list. Slot s
// is vertex prepass.cutVertexBase + s: its attributes (8 floats, as uploaded) in the cut part of
// the scene's vertex buffer, its warp in the cut part of the warps (storeCutVertex).
struct CutVertex {
  vec3 position;  // world (virtual)
  vec3 normal;
  vec2 uv;
  vec4 warped;    // relative to c, w = validity
};
layout(set = 2, binding = 21, std430) writeonly buffer CutAttributes { float cutAttributes[]; };
layout(set = 2, binding = 22, std430) buffer CutWarps { vec4 cutWarps[]; };

uint cutVertexCapacity() { return uint(cutAttributes.length()) / 8u; }

// Takes `count` cut vertex slots; the first, or ~0u where they do not fit (those beyond the
// buffer fall back to the geometry shader's drop).
uint reserveCutVertices(uint count) {
  uint slot = atomicAdd(queueDispatch[kQueueCutVertices].count, count);
  return slot + count <= cutVertexCapacity() ? slot : ~0u;
}

// Per edge with kEdgeAcrossCut (and the split along the cut on): x, the first of the two cut
// vertices where the cut crosses it, each side's limit of the warp there (the first continues
// the side of sceneEdge(e).x, the second that of sceneEdge(e).y), or ~0u where they could not be
// made; y, the crossing's parameter from sceneEdge(e).x to sceneEdge(e).y (float bits). The first slot has
// kCutVertexUnsure set where a side's limit did not land clearly on its side (next to the cut's
// ends, where the jump is small) or outside the source field.
// Made once per edge by classify_edges_at_cut.comp, where the few edges across the cut are packed
// together, and shared by the two triangles on the edge: the bisection and the four-texel
// lookups in the bent triangles' pass, run by whole SIMD groups for one triangle each, cost
// 5 ms of a 20k-triangle scene's 9.5 ms pre-pass on lavapipe.
layout(set = 2, binding = 23, std430) buffer EdgeCutVertices { uvec2 edgeCutVertex[]; };
const uint kCutVertexUnsure = 0x80000000u;

void storeCutVertex(uint slot, CutVertex c) {
  uint at = 8u * slot;
  cutAttributes[at] = c.position.x; cutAttributes[at + 1u] = c.position.y;
  cutAttributes[at + 2u] = c.position.z;
  cutAttributes[at + 3u] = c.normal.x; cutAttributes[at + 4u] = c.normal.y;
  cutAttributes[at + 5u] = c.normal.z;
  cutAttributes[at + 6u] = c.uv.x; cutAttributes[at + 7u] = c.uv.y;
  cutWarps[slot] = c.warped;
}

// confvisDropTriangle surely keeps the triangle (virtual points r relative to c, warps w): some
// corner inside the source field and, unless its warped sides are all within `gap`, warped sides
// no more than 16 times the virtual ones and neither flipped nor torn (confvisFlipsOrTears, as
// confvisDropTriangle tests it). Chords instead of angles, so no atan: a chord is below its
// angle and, up to 0.4 (23 degrees), above it by less than 0.7 %; with a 1 % margin the rules
// hold for the angles. A triangle it does not accept may still be kept.
bool surelyKept(vec3 r[3], vec4 w[3], float gap) {
  float warpedChord =
      max(directionChord(w[0].xyz, w[1].xyz),
          max(directionChord(w[1].xyz, w[2].xyz), directionChord(w[2].xyz, w[0].xyz)));
  float virtualChord = max(directionChord(r[0], r[1]),
                           max(directionChord(r[1], r[2]), directionChord(r[2], r[0])));
  bool shapeKept = !confvisFlipsOrTears(r[0], r[1], r[2], w[0].xyz, w[1].xyz, w[2].xyz);
  bool seen = max(w[0].w, max(w[1].w, w[2].w)) >= 0.5;
  return seen && (chordBelow(warpedChord, gap) ||
                  (warpedChord <= 0.4 && 1.01 * warpedChord <= 16.0 * virtualChord && shapeKept));
}

// confvisDropTriangle, its atans spent only where surelyKept cannot tell (a loop run once or not
// at all: lavapipe runs both sides of an if for all SIMD lanes, but leaves a loop no lane runs).
bool dropsTriangle(vec3 r[3], vec4 w[3], float gap) {
  bool drops = false;
  for (uint once = 0u; once < (surelyKept(r, w, gap) ? 0u : 1u); ++once)
    drops = confvisDropTriangle(r[0], r[1], r[2], w[0], w[1], w[2], gap);
  return drops;
}

// The scene's position, normal and uv at s from vertex va to vb (the warp left to the caller).
CutVertex vertexBetween(uint va, uint vb, float s) {
  CutVertex c;
  c.position = mix(vec3(vertices[8u * va], vertices[8u * va + 1u], vertices[8u * va + 2u]),
                   vec3(vertices[8u * vb], vertices[8u * vb + 1u], vertices[8u * vb + 2u]), s);
  c.normal = mix(vec3(vertices[8u * va + 3u], vertices[8u * va + 4u], vertices[8u * va + 5u]),
                 vec3(vertices[8u * vb + 3u], vertices[8u * vb + 4u], vertices[8u * vb + 5u]), s);
  c.uv = mix(vec2(vertices[8u * va + 6u], vertices[8u * va + 7u]),
             vec2(vertices[8u * vb + 6u], vertices[8u * vb + 7u]), s);
  return c;
}

// The frame's walls with the bend error each tolerates (backends/vulkan/src/frame_plan.cpp,
// errorWall): lit rectangle relative to c, and lowerLeft.w = errorPixels x pixel pitch / plane
// distance; prepass.errorWallCount of them (a uniform buffer: lavapipe loads an element once for
// all SIMD lanes where the index is uniform).
struct ErrorWall {
  vec4 lowerLeft;
  vec4 right;   // unit; w: width, metres
  vec4 up;      // unit; w: height, metres
  vec4 normal;  // unit, towards c; w: the plane's distance from c
};
layout(set = 2, binding = 24, std140) uniform ErrorWalls { ErrorWall errorWalls[64]; };

// The bend error bound (radians seen from c) in physical direction d from c: errorPixels of the
// pixels of the wall that shows d (the nearest wall whose lit rectangle the ray meets), which
// subtend pitch cos^2 / D there; prepass.maxErrorAngle (the smallest pixel anywhere) where no
// wall shows d. Up to three times the strictest bound at a CAVE wall's centre: fewer bent edges
// split where the drawn error stays within the option's pixels.
float errorAngleToward(vec3 d) {
  d = normalize(d);
  float nearest = 1e30, bound = prepass.maxErrorAngle;
  for (uint k = 0u; k < prepass.errorWallCount; ++k) {
    ErrorWall wall = errorWalls[k];
    float cosine = -dot(d, wall.normal.xyz);
    float along = cosine > 1e-6 ? wall.normal.w / cosine : 1e30;
    vec3 onWall = along * d - wall.lowerLeft.xyz;
    float s = dot(onWall, wall.right.xyz), t = dot(onWall, wall.up.xyz);
    bool shows = along < nearest && s >= 0.0 && s <= wall.right.w && t >= 0.0 && t <= wall.up.w;
    nearest = shows ? along : nearest;
    bound = shows ? max(prepass.maxErrorAngle, wall.lowerLeft.w * cosine * cosine) : bound;
  }
  return bound;
}

// Virtual point of vertex v in the physical frame, relative to the map's reference point, from
// the scene's vertices (warp_vertices.comp; the others read vertexRelative).
vec3 transformVertex(uint v) {
  vec3 p = texelFetch(vertexTexels, int(2u * v)).xyz;
  return (frame.worldToPhysical * vec4(p, 1.0)).xyz - frame.warpCentre.xyz;
}

// The same, as warp_vertices.comp stored it.
vec3 vertexRelative(uint v) { return texelFetch(relativeTexels, int(v)).xyz; }

// The triangle whose indices start at `base`: its vertex indices, virtual points relative to c
// and warps (warp_vertices.comp).
void loadTriangle(uint base, out uint i[3], out vec3 r[3], out vec4 w[3]) {
  for (uint k = 0u; k < 3u; ++k) {
    i[k] = sceneIndex(base + k);
    uint v = uint(prepass.vertexOffset) + i[k];
    r[k] = vertexRelative(v);
    w[k] = vertexWarp(v);
  }
}

#endif
