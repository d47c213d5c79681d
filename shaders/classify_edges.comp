#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal pre-pass, once per frame: every distinct edge of the scene (mesh_edges.cpp) gets its
// warped midpoint and its tessellation level once. The triangles on both sides read the same
// result (classify_triangles.comp, then warp.tesc), so shared edges get the same subdivision
// and leave no cracks; the midpoint's warp is the costly part and is no longer done per triangle
// and per view. The level's sign tells whether the edge may lose pieces to confvisDropTriangle
// (negative: it spans the cut, or part of it lies outside the source field).
#include "confvis_warp.glsl"
#include "confvis_prepass_common.glsl"

layout(local_size_x = 64) in;

void main() {
  uint e = gl_GlobalInvocationID.x;
  if (e >= prepass.count) return;
  uvec2 v = edges[e];
  vec4 midpoint;
  bool acrossCut;
  float segments = confvisMeasureEdge(vertexRelative(v.x), vertexRelative(v.y), warped[v.x].xyz,
                                      warped[v.y].xyz, prepass.maxErrorAngle,
                                      prepass.maxSegmentAngle, midpoint, acrossCut);
  bool mayDrop = acrossCut || min(midpoint.w, min(warped[v.x].w, warped[v.y].w)) < 1.0;
  edgeLevels[e] = vec4(midpoint.xyz, mayDrop ? -segments : segments);
}
