#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal pre-pass, indirect dispatch over the straight list that classify_triangles.comp
// fills (every edge in one segment, but corners further apart after the warp than its cheap test
// covers): triangles confvisDropTriangle keeps are written to the flat list, the others go to the
// bent list (classify_bent_triangles.comp puts them on the dropping list). A pass of its own:
// lavapipe runs the bent pass's every test for every triangle on its list, and a finely meshed
// scene has many triangles of a few pixels (a seventh of 1M at 480-pixel walls).
#include "confvis_warp.glsl"
#include "confvis_prepass_common.glsl"

layout(local_size_x = 64) in;

void main() {
  uint slot = gl_GlobalInvocationID.x;
  if (slot >= straightDispatch[prepass.mesh].count) return;
  uint t = straightTriangles[prepass.firstIndex / 3u + slot];
  uint i[3];
  vec3 r[3];
  vec4 w[3];
  loadTriangle(prepass.firstIndex + 3u * t, i, r, w);
  if (confvisDropTriangle(r[0], r[1], r[2], w[0], w[1], w[2], prepass.minGap)) {
    appendBent(t);
  } else {
    writeFlat(t, i);
  }
}
