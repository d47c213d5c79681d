#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal pre-pass, once per frame and mesh: sorts the mesh's triangles into those the warp
// leaves straight enough to draw flat between their warped corners (the common case: drawn by
// the cheap pipeline) and those that need tessellation or lie on the cut (drawn by the
// tessellation pipeline, which subdivides, culls and drops exactly as if it drew everything).
// Triangles entirely outside the source field are dropped here. Edge levels come from
// classify_edges.comp; tessellated triangles copy theirs next to their indices for warp.tesc.
#include "confvis_warp.glsl"
#include "confvis_prepass_common.glsl"

layout(local_size_x = 64) in;

void append(uint list, uint i0, uint i1, uint i2, vec4 levels[3]) {
  uint slot = atomicAdd(commands[2 * prepass.mesh + list].indexCount, 3u);
  uint at = prepass.firstIndex + slot;
  if (list == 0u) {
    simpleIndices[at] = i0; simpleIndices[at + 1u] = i1; simpleIndices[at + 2u] = i2;
  } else {
    complexIndices[at] = i0; complexIndices[at + 1u] = i1; complexIndices[at + 2u] = i2;
    for (uint k = 0u; k < 3u; ++k) patchLevels[at + k] = levels[k];
  }
}

void main() {
  uint t = gl_GlobalInvocationID.x;
  if (t >= prepass.count) return;
  uint base = prepass.firstIndex + 3u * t;
  uint i[3] = uint[3](indices[base], indices[base + 1u], indices[base + 2u]);
  vec3 r[3];
  vec4 w[3];
  for (int k = 0; k < 3; ++k) {
    uint v = uint(prepass.vertexOffset) + i[k];
    r[k] = vertexRelative(v);
    w[k] = warped[v];
  }
  if (max(w[0].w, max(w[1].w, w[2].w)) < 0.5) return;  // nothing of it is shown
  vec4 levels[3];
  bool simple = !confvisDropTriangle(r[0], r[1], r[2], w[0], w[1], w[2], prepass.minGap);
  for (uint k = 0u; k < 3u; ++k) {
    levels[k] = edgeLevels[triangleEdges[base + k]];
    simple = simple && levels[k].w <= 1.0;
  }
  append(simple ? 0u : 1u, i[0], i[1], i[2], levels);
}
