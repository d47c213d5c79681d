// The bent triangles' shared part (classify_bent_triangles.comp, split_triangles_at_cut.comp):
// reading one, the lists it may go to (pieces, tessellated, dropping) and the choice among them
// for a triangle not split along the cut.
#ifndef CONFVIS_PREPASS_BENT_GLSL
#define CONFVIS_PREPASS_BENT_GLSL

#include "confvis_warp.glsl"
#include "confvis_prepass_common.glsl"

void appendPiece(uint at, uint i0, uint i1, uint i2) {
  pieceIndices[at] = i0; pieceIndices[at + 1u] = i1; pieceIndices[at + 2u] = i2;
}

// Appends to the tessellated or the dropping list.
void append(uint list, uint i0, uint i1, uint i2, vec4 levels[3]) {
  uint slot = atomicAdd(commands[kLists * prepass.mesh + list].indexCount, 3u);
  // The dropping list fills the mesh's range from its end, back to front.
  uint at = list == kListTessellated ? prepass.firstIndex + slot
                                     : prepass.firstIndex + 3u * prepass.count - 3u - slot;
  complexIndices[at] = i0; complexIndices[at + 1u] = i1; complexIndices[at + 2u] = i2;
  for (uint k = 0u; k < 3u; ++k) patchLevels[at + k] = levels[k];
}

// Draws a triangle whose edges need two segments at most (edge k, opposite corner k, when
// split[k]) in flat pieces (the pieces list, warp_simple.vert) between its corners and the split
// edges' midpoints, instead of tessellating it: the midpoints' warps are the pre-pass's
// (GpuScene numbers them after the scene's vertices), exactly what
// tessellation at level 2 places there, without its warped centre and its cost (lavapipe
// tessellates on one thread; most bent triangles of a finely meshed scene under a baked map bend
// by two segments).
void appendSplit(uint i[3], bool split[3], uint edge[3]) {
  uint m[3];  // index of the midpoint of the edge opposite corner k
  uint pieces = 1u;
  for (uint k = 0u; k < 3u; ++k) {
    m[k] = prepass.midpointBase + edge[k] - uint(prepass.vertexOffset);
    pieces += split[k] ? 1u : 0u;
  }
  uint at = kPieceCapacity * prepass.firstIndex +
            atomicAdd(commands[kLists * prepass.mesh + kListPieces].indexCount, 3u * pieces);
  if (pieces == 2u) {  // one split edge: its opposite corner fans to its midpoint
    uint k = split[0] ? 0u : split[1] ? 1u : 2u;
    uint a = (k + 1u) % 3u, b = (k + 2u) % 3u;  // edge k runs from corner a to corner b
    appendPiece(at, i[k], i[a], m[k]);
    appendPiece(at + 3u, i[k], m[k], i[b]);
    return;
  }
  if (pieces == 4u) {
    appendPiece(at, i[0], m[2], m[1]);
    appendPiece(at + 3u, i[1], m[0], m[2]);
    appendPiece(at + 6u, i[2], m[1], m[0]);
    appendPiece(at + 9u, m[0], m[1], m[2]);
    return;
  }
  // Two split edges, meeting at corner u (opposite the unsplit one): u's corner between their
  // midpoints cut off, the quad beyond it in two.
  uint u = !split[0] ? 0u : !split[1] ? 1u : 2u;
  uint a = (u + 1u) % 3u, b = (u + 2u) % 3u;  // m[b] lies on u-a, m[a] on b-u
  appendPiece(at, i[u], m[b], m[a]);
  appendPiece(at + 3u, i[a], i[b], m[a]);
  appendPiece(at + 6u, i[a], m[a], m[b]);
}

// Bent triangle t of the current mesh: its corners, virtual points, warps and edges; its edge
// levels (rawLevels: w < 0 where the edge may lose pieces); which edges need more than one segment
// (split) and the most segments of any (inner); whether confvisDropTriangle drops it as it is at
// the strictest gap, and whether pieces of it may be dropped: across the cut or entirely outside
// the source field (an edge whose samples all lie inside, validity 0.5 or more, the rim's blend,
// loses none, however close to the rim).
void loadBentTriangle(uint t, out uint i[3], out vec3 r[3], out vec4 w[3], out uint edge[3],
                      out vec4 rawLevels[3], out bool split[3], out float inner, out bool drops,
                      out bool mayDrop) {
  uint base = prepass.firstIndex + 3u * t;
  loadTriangle(base, i, r, w);
  drops = dropsTriangle(r, w, prepass.minGap);
  mayDrop = drops;
  inner = 1.0;
  for (uint k = 0u; k < 3u; ++k) {
    edge[k] = triangleEdge(base + k);
    rawLevels[k] = edgeLevels[edge[k]];
    mayDrop = mayDrop || (edgeFlagsOf(edge[k]) & (kEdgeAcrossCut | kEdgeOutside)) != 0u;
    float segments = abs(rawLevels[k].w);
    split[k] = segments > 1.0;
    inner = max(inner, segments);
  }
}

// Whether split_triangles_at_cut.comp may split the triangle along the cut (it checks the
// segments of the uncut edges itself): the split on, every corner inside the source field, and
// the cut across one or two of its edges.
bool splitMayApply(vec4 w[3], uint edge[3]) {
  uint cuts = 0u;
  for (uint k = 0u; k < 3u; ++k) cuts += (edgeFlagsOf(edge[k]) & kEdgeAcrossCut) != 0u ? 1u : 0u;
  return prepass.splitAlongCut != 0u && min(w[0].w, min(w[1].w, w[2].w)) >= 1.0 &&
         (cuts == 1u || cuts == 2u);
}

// A bent triangle not split along the cut: to the pieces list where its edges need two segments
// at most and no piece may be dropped, else tessellated, through the geometry shader where pieces
// may be dropped. A patch of one segment an edge tessellates into itself alone: warp.geom's test
// on it, with every view's gap (the corners' warps are the pre-pass's in every way of drawing),
// decided here where the views agree; kept ones are drawn flat, as a piece (lavapipe's geometry
// stage costs some 7 us a patch and wall, most of a 1M-triangle frame's cost at the cut). The
// test in a loop entered once or not at all, not an if: lavapipe runs both sides of an if for all
// SIMD lanes but leaves a loop that no lane runs.
void sortBentTriangle(uint i[3], vec3 r[3], vec4 w[3], uint edge[3], vec4 rawLevels[3],
                      bool split[3], float inner, bool drops, bool mayDrop) {
  bool decided = false;
  for (uint once = 0u; once < (mayDrop && inner <= 1.0 ? 1u : 0u); ++once)
    decided = drops == dropsTriangle(r, w, prepass.maxGap);
  if (decided) {
    if (!drops) appendSplit(i, split, edge);
  } else if (!mayDrop && inner <= 2.0) {
    appendSplit(i, split, edge);
  } else {
    append(mayDrop ? kListDropping : kListTessellated, i[0], i[1], i[2], rawLevels);
  }
}

#endif  // CONFVIS_PREPASS_BENT_GLSL
