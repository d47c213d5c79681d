#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal mode: project tessellated triangles with the off-axis matrix of the wall for this
// eye; drop those entirely outside the source field, and draw those that straddle the source's
// cut up to it on each side (splitAtCut) instead of dropping them, their ends moved out to the
// display's rim through the coverage map (confvis_warp_rim.glsl), as the pre-pass moves its cut
// vertices.
#include "confvis_render_common.glsl"
#include "confvis_warp.glsl"
#include "confvis_warp_rim.glsl"
#include "confvis_warp_capture.glsl"
#include "confvis_cut_crossing.glsl"

layout(triangles) in;
layout(triangle_strip, max_vertices = 7) out;

layout(location = 0) in vec3 inRelative[];
layout(location = 1) in vec4 inWarped[];
layout(location = 2) in vec3 inWorld[];
layout(location = 3) in vec3 inNormal[];
layout(location = 4) in vec2 inUv[];

layout(location = 0 CONFVIS_XFB(16)) out vec3 outWorld;
layout(location = 1 CONFVIS_XFB(28)) out vec3 outNormal;
layout(location = 2 CONFVIS_XFB(40)) out vec2 outUv;

Corner inputCorner(int k) {
  return Corner(inRelative[k], inWarped[k], inWorld[k], inNormal[k], inUv[k]);
}

void emit(Corner c) {
  outWorld = c.world;
  outNormal = c.normal;
  outUv = c.uv;
  gl_Position = currentView().viewProj * vec4(frame.warpCentre.xyz + c.warped.xyz, 1.0);
  EmitVertex();
}

#ifdef CONFVIS_CAPTURE
// A record written as it stands (the capture's view projects by the identity).
void emitDeferred(vec4 position, vec3 world, vec3 normal, vec2 uv) {
  outWorld = world;
  outNormal = normal;
  outUv = uv;
  gl_Position = position;
  EmitVertex();
}
#endif

// A piece the cut tears: corner `lone` (opposite the warp's shortest edge) on one side, the
// others on the other. Drawn as the lone corner's triangle and the others' quad, each up to the
// cut (its side's limit of the warp at the crossings), instead of dropped: the dropped pieces
// were most of the black cracks along cave5's top rim (issue 23). The parts are drawn even where
// they still look torn by confvisDropTriangle's rules (the cut's tip inside the piece, where both
// sides meet again, or a strongly stretched side next to the cut): leaving those out kept more
// of the rim's cracks (BackendCrossCheckRim: 6.7 / 5.4 / 7.4 / 1.2 % off Embree against
// 6.2 / 5.0 / 5.9 / 1.2 % drawn).
void splitAtCut() {
  int lone = loneCorner(inWarped[0].xyz, inWarped[1].xyz, inWarped[2].xyz);
  Corner l = inputCorner(lone), a = inputCorner((lone + 1) % 3), b = inputCorner((lone + 2) % 3);
#ifdef CONFVIS_CAPTURE
  // The capture leaves the split to split_captured_at_cut.comp: lavapipe runs the split for all
  // eight lanes of a SIMD group, and a quarter of the Dropping list's pieces are torn, so nearly
  // every group paid the ~14 lookups and two rim searches (most of the capture's GPU time). The
  // piece's corners go into the split's seven vertices (the same strips), each record marked by
  // w = -1 - its vertex's number; the compute pass overwrites them with the split's vertices.
  emitDeferred(vec4(l.relative, -1.0), l.world, l.normal, l.uv);
  emitDeferred(vec4(l.warped.xyz, -2.0), a.warped.xyz, b.warped.xyz, vec2(0.0));
  emitDeferred(vec4(0.0, 0.0, 0.0, -3.0), vec3(0.0), vec3(0.0), vec2(0.0));
  EndPrimitive();
  emitDeferred(vec4(a.relative, -4.0), a.world, a.normal, a.uv);
  emitDeferred(vec4(0.0, 0.0, 0.0, -5.0), vec3(0.0), vec3(0.0), vec2(0.0));
  emitDeferred(vec4(b.relative, -6.0), b.world, b.normal, b.uv);
  emitDeferred(vec4(0.0, 0.0, 0.0, -7.0), vec3(0.0), vec3(0.0), vec2(0.0));
  EndPrimitive();
#else
  Corner xl, xa, yl, yb;
  crossing(l, a, snapsToRim(), xl, xa);
  crossing(l, b, snapsToRim(), yl, yb);
  emit(l);
  emit(xl);
  emit(yl);
  EndPrimitive();
  emit(a);  // the quad a, b, yb, xa as a strip
  emit(xa);
  emit(b);
  emit(yb);
  EndPrimitive();
#endif
}

void main() {
  float minGap = currentView().params.z;
  if (confvisDropTriangle(inRelative[0], inRelative[1], inRelative[2], inWarped[0], inWarped[1],
                          inWarped[2], minGap)) {
    if (max(inWarped[0].w, max(inWarped[1].w, inWarped[2].w)) >= 0.5 && drawsTornPieces())
      splitAtCut();
    return;
  }
  for (int i = 0; i < 3; ++i) emit(inputCorner(i));
  EndPrimitive();
}
