#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal pre-pass, once per frame and mesh, first pass over every triangle: the cheap test.
// Triangles entirely outside the source field are dropped; those the warp leaves straight
// enough to draw flat between their warped corners (every edge at one segment by
// classify_edges.comp, no drop rule firing for the whole triangle: the common case) go to the
// flat list, drawn by the cheap pipeline; the others go to the mesh's bent list, whose
// indirect dispatch (group count kept here) classify_bent_triangles.comp runs.
#include "confvis_warp.glsl"
#include "confvis_prepass_common.glsl"

layout(local_size_x = 64) in;

void main() {
  uint t = gl_GlobalInvocationID.x;
  if (t >= prepass.count) return;
  uint base = prepass.firstIndex + 3u * t;
  uint i[3];
  vec3 r[3];
  vec4 w[3];
  loadTriangle(base, i, r, w);
  if (max(w[0].w, max(w[1].w, w[2].w)) < 0.5) return;  // nothing of it is shown
  bool drops = confvisDropTriangle(r[0], r[1], r[2], w[0], w[1], w[2], prepass.minGap);
  bool bent = false;
  for (uint k = 0u; k < 3u; ++k) bent = bent || abs(edgeLevels[triangleEdges[base + k]].w) > 1.0;
  if (!drops && !bent) {  // the dropping pipeline would draw it unchanged
    uint at = prepass.firstIndex +
              atomicAdd(commands[kLists * prepass.mesh + kListFlat].indexCount, 3u);
    simpleIndices[at] = i[0]; simpleIndices[at + 1u] = i[1]; simpleIndices[at + 2u] = i[2];
    return;
  }
  uint slot = atomicAdd(bentDispatch[prepass.mesh].count, 1u);
  bentTriangles[prepass.firstIndex / 3u + slot] = t | (drops ? kBentDrops : 0u);
  // The first of each workgroup's worth of slots grows the dispatch to cover it.
  if (slot % kBentGroup == 0u) atomicMax(bentDispatch[prepass.mesh].groupsX, slot / kBentGroup + 1u);
}
