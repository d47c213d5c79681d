// Conformal pre-pass: edge e's warped midpoint and tessellation level (classify_edges.comp and,
// for the edges whose midpoint needs the four-texel lookup, classify_edges_across_cut.comp).
// The level's sign tells whether the edge may lose pieces to confvisDropTriangle (negative: it
// spans the cut, or part of it lies outside the source field).
#ifndef CONFVIS_PREPASS_EDGES_GLSL
#define CONFVIS_PREPASS_EDGES_GLSL

#include "confvis_warp.glsl"
#include "confvis_prepass_common.glsl"

// The midpoint of edge e relative to c.
vec3 edgeMidpointRelative(uint e) {
  return 0.5 * (vertexRelative(edges[e].x) + vertexRelative(edges[e].y));
}

void writeEdgeLevel(uint e, vec4 midpoint) {
  uvec2 v = edges[e];
  bool acrossCut;
  float segments = confvisMeasureEdgeWithMidpoint(
      vertexRelative(v.x), vertexRelative(v.y), warped[v.x].xyz, warped[v.y].xyz, midpoint,
      prepass.maxErrorAngle, prepass.maxSegmentAngle, acrossCut);
  bool mayDrop = acrossCut || min(midpoint.w, min(warped[v.x].w, warped[v.y].w)) < 1.0;
  edgeLevels[e] = vec4(midpoint.xyz, mayDrop ? -segments : segments);
}

#endif
