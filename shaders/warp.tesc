#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal mode: subdivide each triangle by how much the warp bends its edges (measured by the
// pre-pass).
#include "confvis_render_common.glsl"
#include "confvis_warp.glsl"

layout(vertices = 3) out;

layout(location = 0) in vec3 inRelative[];
layout(location = 1) in vec4 inWarped[];
layout(location = 2) in vec3 inWorld[];
layout(location = 3) in vec3 inNormal[];
layout(location = 4) in vec2 inUv[];
layout(location = 5) flat in uint inSlot[];  // the patch's slot in the pre-pass's lists

layout(location = 0) out vec3 outRelative[];
layout(location = 1) out vec4 outWarped[];
layout(location = 2) out vec3 outWorld[];
layout(location = 3) out vec3 outNormal[];
layout(location = 4) out vec2 outUv[];
// Per edge (opposite corner k): its warped midpoint as the pre-pass measured it, w = 1 where the
// edge lies inside the source field (the midpoint's validity is then 1), else 0.
layout(location = 5) patch out vec4 outEdgeMidpoints[3];

// Segments of the edge opposite corner k, as the pre-pass measured them once per edge
// (classify_edges.comp), and its warped midpoint.
float segments(int k, out vec3 warpedMidpoint) {
  vec4 level = patchLevels[3u * inSlot[0] + uint(k)];  // w < 0: the edge may lose pieces
  warpedMidpoint = level.xyz;
  outEdgeMidpoints[k] = vec4(level.xyz, level.w > 0.0 ? 1.0 : 0.0);
  return wallView().params.w == 0.0 ? 1.0 : abs(level.w);
}

// Bits of the clip planes (x, y both sides, near) that a point relative to c lies outside of,
// with a margin of a tenth of the view for the bulge of bent edges between the sampled points.
uint outside(vec3 relative) {
  vec4 p = currentView().viewProj * vec4(frame.warpCentre.xyz + relative, 1.0);
  float w = 1.1 * p.w;
  return (p.x < -w ? 1u : 0u) | (p.x > w ? 2u : 0u) | (p.y < -w ? 4u : 0u) | (p.y > w ? 8u : 0u) |
         (p.z < 0.0 ? 16u : 0u);
}

void cull() {
  gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = 0.0;
  gl_TessLevelInner[0] = 0.0;
}

void main() {
  outRelative[gl_InvocationID] = inRelative[gl_InvocationID];
  outWarped[gl_InvocationID] = inWarped[gl_InvocationID];
  outWorld[gl_InvocationID] = inWorld[gl_InvocationID];
  outNormal[gl_InvocationID] = inNormal[gl_InvocationID];
  outUv[gl_InvocationID] = inUv[gl_InvocationID];
  if (gl_InvocationID != 0) return;
  if (max(inWarped[0].w, max(inWarped[1].w, inWarped[2].w)) < 0.5) {
    cull();  // entirely outside the source field: nothing of it is shown
    return;
  }
  // Outer level k belongs to the edge opposite corner k.
  vec3 m0, m1, m2;
  float e0 = segments(0, m0), e1 = segments(1, m1), e2 = segments(2, m2);
  // Patches whose warped corners and edge midpoints all lie beyond one side of this view are
  // not drawn, unless an edge bends so much that the samples say little about the curve between
  // them. An edge across the cut (or partly outside the source field; w = 0) does not count: its
  // midpoint lands on one side, its corners on either, and the pieces drawn between them
  // (warp.geom drops those straddling the cut) stay with their own side's samples. Such patches
  // were drawn for every wall, most of the geometry shader's work under a baked cave5 map.
  float bendLimit = 16.0 * wallView().params.x;
  bool strongBend = false;
  vec3 m[3] = vec3[3](m0, m1, m2);
  for (int k = 0; k < 3; ++k) {
    vec3 chordMid = 0.5 * (inWarped[(k + 1) % 3].xyz + inWarped[(k + 2) % 3].xyz);
    strongBend = strongBend ||
                 (outEdgeMidpoints[k].w > 0.0 && confvisAngle(m[k], chordMid) > bendLimit);
  }
  // The once-a-frame capture (params.w above 4, confvis_warp_capture.glsl) draws for every wall:
  // no view culls it.
  bool capturing = wallView().params.w > 4.5;
  if (!capturing && !strongBend && (outside(inWarped[0].xyz) & outside(inWarped[1].xyz) &
                      outside(inWarped[2].xyz) & outside(m0) & outside(m1) & outside(m2)) != 0u) {
    cull();
    return;
  }
  gl_TessLevelOuter[0] = e0;
  gl_TessLevelOuter[1] = e1;
  gl_TessLevelOuter[2] = e2;
  gl_TessLevelInner[0] = max(e0, max(e1, e2));
}
