// Conformal mode, tessellation evaluation: place the tessellated vertices on the virtual triangle
// and warp them. Shared by warp.tese (for warp.geom, which drops pieces across the cut and
// projects the rest) and warp_projected.tese (projects them itself: the patches the pre-pass
// found to lose no pieces need no geometry shader).
#ifndef CONFVIS_WARP_TESE_GLSL
#define CONFVIS_WARP_TESE_GLSL

#include "confvis_render_common.glsl"
#include "confvis_warp.glsl"
#include "confvis_warp_rim.glsl"

layout(triangles, equal_spacing, ccw) in;

layout(location = 0) in vec3 inRelative[];
layout(location = 1) in vec4 inWarped[];
layout(location = 2) in vec3 inWorld[];
layout(location = 3) in vec3 inNormal[];
layout(location = 4) in vec2 inUv[];
layout(location = 5) patch in vec4 inEdgeMidpoints[3];  // warp.tesc

struct TessellatedVertex {
  vec3 relative;  // virtual point relative to c
  vec4 warped;    // its warp relative to c, w = validity
  vec3 world;
  vec3 normal;
  vec2 uv;
};

// confvisWarpRelative, and where the bilinear blend cannot warp it (next to the cut) moved to where
// the ray map shows it (confvisRefineOnRayMap), as warp_vertices_across_cut.comp does the corners:
// the curves a patch draws between refined corners next to a cut's leaf (the left and right
// walls' corners under cave5's missing ceiling) would otherwise bend back to the unrefined lookup.
// Not with the snap to the rim off (snapsToRim, confvis_render_common.glsl).
vec4 confvisWarpRelativeRefined(vec3 relative) {
  vec4 w;
  if (confvisWarpRelativeBilinear(relative, w)) return w;
  return confvisRefineWarpOnRayMap(relative, confvisWarpRelative(relative), snapsToRim());
}

TessellatedVertex tessellatedVertex() {
  vec3 b = gl_TessCoord;
  TessellatedVertex v;
  v.world = b.x * inWorld[0] + b.y * inWorld[1] + b.z * inWorld[2];
  v.normal = b.x * inNormal[0] + b.y * inNormal[1] + b.z * inNormal[2];
  v.uv = b.x * inUv[0] + b.y * inUv[1] + b.z * inUv[2];
  precise vec3 relative = b.x * inRelative[0] + b.y * inRelative[1] + b.z * inRelative[2];
  v.relative = relative;
  // Corners keep the vertex stage's warp and edge midpoints the pre-pass's (bitwise equal in
  // every patch that shares them, and in the flat pieces of split triangles).
  if (b.x == 1.0) v.warped = inWarped[0];
  else if (b.y == 1.0) v.warped = inWarped[1];
  else if (b.z == 1.0) v.warped = inWarped[2];
  else if (b.x == 0.0 && b.y == 0.5 && inEdgeMidpoints[0].w > 0.0) v.warped = inEdgeMidpoints[0];
  else if (b.y == 0.0 && b.z == 0.5 && inEdgeMidpoints[1].w > 0.0) v.warped = inEdgeMidpoints[1];
  else if (b.z == 0.0 && b.x == 0.5 && inEdgeMidpoints[2].w > 0.0) v.warped = inEdgeMidpoints[2];
  else v.warped = confvisWarpRelativeRefined(relative);
  return v;
}

#endif
