#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal pre-pass (indirect dispatch over the bent list that classify_triangles.comp and
// classify_straight_triangles.comp fill): sorts the triangles that are not flat as they are into
// those drawn in flat pieces between their corners and edge midpoints, those that need
// tessellation only (tessellation pipeline without a geometry shader) and those that may lose
// pieces to confvisDropTriangle: on or next to the cut or partly outside the source field
// (tessellation and the geometry shader that drops pieces, exactly as if it drew everything;
// lavapipe runs it in its single-threaded draw stage, so only these pay for it). Those the cut
// crosses go to the cut list, for split_triangles_at_cut.comp. A pass of its own because lavapipe
// evaluates both sides of a branch for all SIMD lanes: in one pass every triangle of the scene
// paid for the tests below. Tessellated triangles copy their edge levels next to their indices
// for warp.tesc.
#include "confvis_prepass_bent.glsl"

layout(local_size_x = 64) in;

void main() {
  uint slot = gl_GlobalInvocationID.x;
  if (slot >= bentDispatch[prepass.mesh].count) return;
  uint t = bentTriangles[prepass.firstIndex / 3u + slot];
  uint i[3], edge[3];
  vec3 r[3];
  vec4 w[3], rawLevels[3];
  bool split[3], drops, mayDrop;
  float inner;
  loadBentTriangle(t, i, r, w, edge, rawLevels, split, inner, drops, mayDrop);
  // (A patch the warp stretched 4 times or flattened, in itself or its midpoint triangles, went
  // to the geometry shader too until measured: the same images or better without, at 20k and 300k
  // triangles on cave5, cave3 and md230x6, and up to 40 % fewer patches through the geometry
  // shader; the edges' jump test and the flags of edges across the cut find the pieces to drop.)
  if (mayDrop && splitMayApply(w, edge)) {
    appendAtCut(t);
  } else {
    sortBentTriangle(i, r, w, edge, rawLevels, split, inner, drops, mayDrop);
  }
}
