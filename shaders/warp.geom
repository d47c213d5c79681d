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
#include "confvis_rim_limit.glsl"
#include "confvis_warp_capture.glsl"

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

// A point of the drawn triangle: virtual point relative to c, warp, attributes.
struct Corner {
  vec3 relative;
  vec4 warped;
  vec3 world;
  vec3 normal;
  vec2 uv;
};

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

// Bisection steps for the crossing of an edge with the cut: 2^-6 of the piece's edge (its
// pieces are a texel of the geom map or two pixels, whichever is longer: a few hundredths of a
// pixel). Each step is a full lookup; the torn pieces' split was half of the once-a-frame
// capture's GPU time on lavapipe (10 steps: 6.3 ms a 20k-triangle cave5 frame, 6: 5.4-5.9 ms).
const int kCutBisections = 6;

// Where the cut crosses edge p-q (p on one side, q on the other): bisects the edge, keeping the
// half whose warp turns the more (the jump), and returns the crossing's point on each side, each
// its side's limit of the warp there (confvisWarpRelativeToward, hinted by that side's warp).
void crossing(Corner p, Corner q, out Corner onP, out Corner onQ) {
  float s0 = 0.0, s1 = 1.0;
  vec3 w0 = p.warped.xyz, w1 = q.warped.xyz;
  for (int step = 0; step < kCutBisections; ++step) {
    float m = 0.5 * (s0 + s1);
    vec3 wm = confvisWarpRelative(mix(p.relative, q.relative, m)).xyz;
    if (confvisAngle(w0, wm) >= confvisAngle(wm, w1)) {
      s1 = m;
      w1 = wm;
    } else {
      s0 = m;
      w0 = wm;
    }
  }
  float s = 0.5 * (s0 + s1);
  Corner x = Corner(mix(p.relative, q.relative, s), vec4(0.0), mix(p.world, q.world, s),
                    normalize(mix(p.normal, q.normal, s)), mix(p.uv, q.uv, s));
  onP = x;
  onQ = x;
  confvisWarpRelativeTowardEach(x.relative, w0, w1, onP.warped, onQ.warped);
  // Each side's limit out to the display's rim, as the pre-pass moves its cut vertices: the
  // extrapolated limits stop short of it by a band (the square-root growth next to the cut).
  // A loop entered once or not at all (lavapipe runs both sides of an if for every lane).
  for (int once = 0; once < (snapsToRim() ? 1 : 0); ++once) {
    vec3 direction = normalize(x.relative);  // next to a leaf, where the ray map shows x
    onP.warped.xyz = confvisRimLimit(direction, onP.warped.xyz, p.warped.xyz);
    onQ.warped.xyz = confvisRimLimit(direction, onQ.warped.xyz, q.warped.xyz);
  }
}

// A piece the cut tears: corner `lone` (opposite the warp's shortest edge) on one side, the
// others on the other. Drawn as the lone corner's triangle and the others' quad, each up to the
// cut (its side's limit of the warp at the crossings), instead of dropped: the dropped pieces
// were most of the black cracks along cave5's top rim (issue 23). The parts are drawn even where
// they still look torn by confvisDropTriangle's rules (the cut's tip inside the piece, where both
// sides meet again, or a strongly stretched side next to the cut): leaving those out kept more
// of the rim's cracks (BackendCrossCheckRim: 6.7 / 5.4 / 7.4 / 1.2 % off Embree against
// 6.2 / 5.0 / 5.9 / 1.2 % drawn).
void splitAtCut() {
  float edgeAngle[3];
  for (int k = 0; k < 3; ++k)
    edgeAngle[k] = confvisAngle(inWarped[(k + 1) % 3].xyz, inWarped[(k + 2) % 3].xyz);
  int lone = edgeAngle[0] <= edgeAngle[1] && edgeAngle[0] <= edgeAngle[2] ? 0
           : edgeAngle[1] <= edgeAngle[2]                                 ? 1
                                                                          : 2;
  Corner l = inputCorner(lone), a = inputCorner((lone + 1) % 3), b = inputCorner((lone + 2) % 3);
  Corner xl, xa, yl, yb;
  crossing(l, a, xl, xa);
  crossing(l, b, yl, yb);
  emit(l);
  emit(xl);
  emit(yl);
  EndPrimitive();
  emit(a);  // the quad a, b, yb, xa as a strip
  emit(xa);
  emit(b);
  emit(yb);
  EndPrimitive();
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
