#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal pre-pass, once per frame: every distinct edge of the scene (mesh_edges.cpp) gets its
// warped midpoint and its tessellation level once. The triangles on both sides read the same
// result (classify_triangles.comp, then warp.tesc), so shared edges get the same subdivision
// and leave no cracks; the midpoint's warp is the costly part and is no longer done per triangle
// and per view.
#include "confvis_warp.glsl"
#include "confvis_prepass_common.glsl"

layout(local_size_x = 64) in;

void main() {
  uint e = gl_GlobalInvocationID.x;
  if (e >= prepass.count) return;
  uvec2 v = edges[e];
  vec3 midpoint;
  float segments = confvisEdgeSegments(vertexRelative(v.x), vertexRelative(v.y), warped[v.x].xyz,
                                       warped[v.y].xyz, prepass.maxErrorAngle,
                                       prepass.maxSegmentAngle, midpoint);
  edgeLevels[e] = vec4(midpoint, segments);
}
