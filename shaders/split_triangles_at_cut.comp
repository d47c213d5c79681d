#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal pre-pass, last pass (indirect dispatch over the cut list that
// classify_bent_triangles.comp fills): splits the triangles the source's cut crosses exactly
// along it (through two edges) or at its tip (through one), drawn flat in the pieces list up to
// the cut on each side; those it cannot split are sorted as the bent pass sorts the rest
// (sortBentTriangle). A pass of its own: on lavapipe the split's code, even where no SIMD lane
// ran it, made every workgroup of the bent pass ~30 us slower (1.3 ms of a 20k-triangle
// pre-pass), and few triangles need it.
#include "confvis_prepass_bent.glsl"

layout(local_size_x = 64) in;

// A triangle that the cut crosses through two of its edges (corner u on one side, the others on
// the other) and whose third edge is drawn in at most kMaxUncutSegments segments, split exactly
// along the cut: the corner's piece and the other side's quad (fanned through the third edge's
// points, as its neighbour tessellates it) between its corners and four cut vertices, each side's
// limit of the warp at the two crossings, drawn flat in the pieces list. Instead of tessellating
// it finely and dropping the pieces across the cut in the geometry shader (a band of two pixels or a texel
// unshown along the cut, and most of the geometry shader's work). False where it does not apply.
bool splitFound(uint i[3], vec4 w[3], vec4 rawLevels[3], uint edge[3], uint u);

// The most segments of the uncut edge of a triangle split along the cut (its pieces: two more).
const uint kMaxUncutSegments = 8u;

// A triangle that the cut crosses through one edge only (k: the edge opposite corner k), where
// the cut ends inside it or leaves through corner k: the jump across its other edges is below
// what the edge test sees (a few pixels, the cut's tip). Split at the crossing X into two fans,
// one a side, from X (that side's limit of the warp there) over the uncut edge on that side
// (their points as the neighbours' tessellation places them), drawn flat; unless a piece is one
// that confvisDropTriangle would drop (a real jump after all). Instead of the geometry shader's
// drop of the pieces across it: most of the dropping list at 1M triangles under a baked map.
bool splitAtCutTip(uint i[3], vec3 r[3], vec4 w[3], vec4 rawLevels[3], uint edge[3], uint k);

bool splitAlongCut(uint i[3], vec3 r[3], vec4 w[3], vec4 rawLevels[3], uint edge[3]) {
  bool cut[3];
  uint cuts = 0u;
  for (uint k = 0u; k < 3u; ++k) {
    cut[k] = (edgeFlagsOf(edge[k]) & kEdgeAcrossCut) != 0u;
    cuts += cut[k] ? 1u : 0u;
  }
  // The split is on and every corner inside the source field (splitMayApply queued only such).
  uint u = !cut[0] ? 0u : !cut[1] ? 1u : 2u;
  bool applies = cuts == 2u && rawLevels[u].w > 0.0 && rawLevels[u].w <= float(kMaxUncutSegments);
  uint k = cut[0] ? 0u : cut[1] ? 1u : 2u;  // the cut edge where there is one
  bool tip = cuts == 1u && rawLevels[(k + 1u) % 3u].w > 0.0 &&
             rawLevels[(k + 1u) % 3u].w <= float(kMaxUncutSegments) &&
             rawLevels[(k + 2u) % 3u].w > 0.0 &&
             rawLevels[(k + 2u) % 3u].w <= float(kMaxUncutSegments);
  // Loops run once or not at all rather than ifs: lavapipe runs both sides of an if for all
  // SIMD lanes, but leaves a loop as soon as no lane runs it, and few triangles here need the
  // lookups below.
  bool split = false;
  for (uint once = 0u; once < (applies ? 1u : 0u); ++once)
    split = splitFound(i, w, rawLevels, edge, u);
  for (uint once = 0u; once < (tip ? 1u : 0u); ++once)
    split = splitAtCutTip(i, r, w, rawLevels, edge, k);
  return split;
}

// Reserves `indices` slots of the mesh's part of the pieces list, if they fit (a split triangle
// may take more than its kPieceCapacity share); returns the first, or ~0u.
uint reservePieces(uint indices) {
  uint capacity = kPieceCapacity * 3u * prepass.count;
  uint taken = commands[kLists * prepass.mesh + kListPieces].indexCount;
  for (;;) {
    if (taken + indices > capacity) return ~0u;
    uint seen = atomicCompSwap(commands[kLists * prepass.mesh + kListPieces].indexCount, taken,
                               taken + indices);
    if (seen == taken) return kPieceCapacity * prepass.firstIndex + taken;
    taken = seen;
  }
}

// Writes the cut vertex `slot`: the point k / n along edge a-b (the triangle's corners a and b,
// vertices va and vb), warped as the tessellation evaluation shader warps the points it places
// there (the neighbour across the edge tessellates it into n segments).
vec4 writeEdgeVertex(uint slot, uint va, uint vb, float s) {
  CutVertex c = vertexBetween(va, vb, s);
  c.warped = confvisWarpRelative((1.0 - s) * vertexRelative(va) + s * vertexRelative(vb));
  storeCutVertex(slot, c);
  return c.warped;
}

// Point j of the triangle's edge `e` from corner p to corner q (local indices ip, iq) drawn in n
// segments, as a vertex number (the mesh's, as in its indices): the corners, the pre-pass's
// midpoint in the middle, the others cut vertices from `slot` on (slot + j - 1 for point j).
uint edgePointIndex(uint e, uint n, uint j, uint ip, uint iq, uint slot) {
  uint offset = uint(prepass.vertexOffset);
  return j == 0u ? ip
       : j == n ? iq
       : 2u * j == n ? prepass.midpointBase + e - offset
                     : prepass.cutVertexBase + slot + j - 1u - offset;
}

// Writes the points between the corners of that edge (those edgePointIndex numbers as cut
// vertices), warped as the neighbour's tessellation places them (writeEdgeVertex), and tells
// whether the fan from X (virtual point rx, warp wx) over them keeps every piece
// (confvisDropTriangle). Points carried one at a time, no arrays: lavapipe keeps arrays indexed
// in a loop in memory, lane by lane, which made the whole pass 2-3 ms slower at 20k triangles.
bool writeFanPoints(uint e, uint n, uint ip, uint iq, vec3 rp, vec3 rq, vec4 wp, vec4 wq,
                    uint slot, vec3 rx, vec4 wx) {
  uint offset = uint(prepass.vertexOffset);
  vec3 previousRel = rp;
  vec4 previousWarp = wp;
  bool kept = true;
  for (uint j = 1u; j <= n; ++j) {
    float s = float(j) / float(n);
    vec3 rel = j == n ? rq : mix(rp, rq, s);
    vec4 warp = j == n ? wq : vec4(edgeLevels[e].xyz, 1.0);
    for (uint once = 0u; once < (j < n && 2u * j != n ? 1u : 0u); ++once)
      warp = writeEdgeVertex(slot + j - 1u, offset + ip, offset + iq, s);
    kept = kept && !dropsTriangle(vec3[3](rx, previousRel, rel),
                                  vec4[3](wx, previousWarp, warp), prepass.minGap);
    previousRel = rel;
    previousWarp = warp;
  }
  return kept;
}

// The fan's pieces from cut vertex x (a vertex number) over that edge's points, from `at` on.
void appendFan(uint at, uint x, uint e, uint n, uint ip, uint iq, uint slot) {
  for (uint j = 0u; j < n; ++j)
    appendPiece(at + 3u * j, x, edgePointIndex(e, n, j, ip, iq, slot),
                edgePointIndex(e, n, j + 1u, ip, iq, slot));
}

bool splitFound(uint i[3], vec4 w[3], vec4 rawLevels[3], uint edge[3], uint u) {
  // X where the cut crosses u-a (edge[b], opposite b), Y where it crosses b-u (edge[a]): the
  // edges' cut vertices (classify_edges_at_cut.comp).
  uint a = (u + 1u) % 3u, b = (u + 2u) % 3u;
  uint x = edgeCutVertex[edge[b]].x, y = edgeCutVertex[edge[a]].x;
  if (x >= kCutVertexUnsure || y >= kCutVertexUnsure) return false;  // unsure, or none
  // The uncut edge (opposite u, from corner a to b) in n segments: its points in between are
  // the pre-pass's midpoint (n = 2) or cut vertices of their own, the other side's quad a fan
  // from X through them.
  uint n = uint(rawLevels[u].w);
  uint between = n > 2u ? n - 1u : 0u;
  uint slot = 0u;
  for (uint once = 0u; once < (between > 0u ? 1u : 0u); ++once) slot = reserveCutVertices(between);
  if (slot == ~0u) return false;
  uint pieces = n + 2u;
  uint at = reservePieces(3u * pieces);
  if (at == ~0u) return false;
  uint offset = uint(prepass.vertexOffset);
  uint vu = offset + i[u], va = offset + i[a], vb = offset + i[b];
  // The middle point's slot stays unwritten: the fan uses the pre-pass's midpoint there.
  for (uint k = 1u; k <= between; ++k)
    for (uint once = 0u; once < (2u * k != n ? 1u : 0u); ++once)
      writeEdgeVertex(slot + k - 1u, va, vb, float(k) / float(n));
  // Each edge's first cut vertex continues the side of its first vertex.
  uint cutBase = prepass.cutVertexBase - offset;  // the draw adds the offset back
  bool uFirstOnX = sceneEdge(edge[b]).x == vu, uFirstOnY = sceneEdge(edge[a]).x == vu;
  uint xu = cutBase + x + (uFirstOnX ? 0u : 1u), xa = cutBase + x + (uFirstOnX ? 1u : 0u);
  uint yu = cutBase + y + (uFirstOnY ? 0u : 1u), yb = cutBase + y + (uFirstOnY ? 1u : 0u);
  appendPiece(at, i[u], xu, yu);
  appendFan(at + 3u, xa, edge[u], n, i[a], i[b], slot);  // the midpoint keeps the pre-pass's warp
  appendPiece(at + 3u * (n + 1u), xa, i[b], yb);
  atomicAdd(queueDispatch[kQueueCutVertices].groupsX, 1u);
  return true;
}

bool splitAtCutTip(uint i[3], vec3 r[3], vec4 w[3], vec4 rawLevels[3], uint edge[3], uint k) {
  uint a = (k + 1u) % 3u, b = (k + 2u) % 3u;  // the cut edge runs from corner a to corner b
  // Unsure sides are common here (the jump is small); the drop test below guards the pieces.
  uvec2 cutVertex = edgeCutVertex[edge[k]];
  if (cutVertex.x == ~0u) return false;
  cutVertex.x &= ~kCutVertexUnsure;
  uint offset = uint(prepass.vertexOffset);
  bool aFirst = sceneEdge(edge[k]).x == offset + i[a];
  float t = uintBitsToFloat(cutVertex.y);  // from sceneEdge(edge[k]).x
  vec3 rx = aFirst ? mix(r[a], r[b], t) : mix(r[b], r[a], t);
  uint xa = cutVertex.x + (aFirst ? 0u : 1u), xb = cutVertex.x + (aFirst ? 1u : 0u);
  // Side a: the fan from X over k -> a (edge[b]); side b: over b -> k (edge[a]).
  uint na = uint(rawLevels[b].w), nb = uint(rawLevels[a].w);
  uint betweenA = na > 2u ? na - 1u : 0u, betweenB = nb > 2u ? nb - 1u : 0u;
  uint slot = 0u;
  for (uint once = 0u; once < (betweenA + betweenB > 0u ? 1u : 0u); ++once)
    slot = reserveCutVertices(betweenA + betweenB);
  if (slot == ~0u) return false;
  // A piece confvisDropTriangle would drop spans a real jump: the geometry shader's case.
  bool kept = writeFanPoints(edge[b], na, i[k], i[a], r[k], r[a], w[k], w[a], slot, rx,
                             cutWarps[xa]);
  kept = writeFanPoints(edge[a], nb, i[b], i[k], r[b], r[k], w[b], w[k], slot + betweenA, rx,
                        cutWarps[xb]) && kept;
  if (!kept) return false;
  uint at = reservePieces(3u * (na + nb));
  if (at == ~0u) return false;
  uint cutBase = prepass.cutVertexBase - offset;  // the draw adds the offset back
  appendFan(at, cutBase + xa, edge[b], na, i[k], i[a], slot);
  appendFan(at + 3u * na, cutBase + xb, edge[a], nb, i[b], i[k], slot + betweenA);
  atomicAdd(queueDispatch[kQueueCutVertices].groupsX, 1u);
  return true;
}

void main() {
  uint slot = gl_GlobalInvocationID.x;
  if (slot >= cutDispatch[prepass.mesh].count) return;
  uint t = cutTriangles[prepass.firstIndex / 3u + slot];
  uint i[3], edge[3];
  vec3 r[3];
  vec4 w[3], rawLevels[3];
  bool split[3], drops, mayDrop;
  float inner;
  loadBentTriangle(t, i, r, w, edge, rawLevels, split, inner, drops, mayDrop);
  if (!splitAlongCut(i, r, w, rawLevels, edge))
    sortBentTriangle(i, r, w, edge, rawLevels, split, inner, drops, mayDrop);
}
