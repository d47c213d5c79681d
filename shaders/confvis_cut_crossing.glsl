// The split of a piece the source's cut tears (issue 23): where the cut crosses an edge and each
// side's limit of the warp there, out to the display's rim. Shared by warp.geom (each wall's
// draw) and split_captured_at_cut.comp (the once-a-frame capture's torn pieces, split in compute
// so that the geometry shader's SIMD groups no longer all pay for it). Include after
// confvis_warp.glsl and confvis_warp_rim.glsl.
#ifndef CONFVIS_CUT_CROSSING_GLSL
#define CONFVIS_CUT_CROSSING_GLSL

#include "confvis_rim_limit.glsl"

// A point of the drawn triangle: virtual point relative to c, warp, attributes.
struct Corner {
  vec3 relative;
  vec4 warped;
  vec3 world;
  vec3 normal;
  vec2 uv;
};

// Bisection steps for the crossing of an edge with the cut: 2^-6 of the piece's edge (its
// pieces are a texel of the geom map or two pixels, whichever is longer: a few hundredths of a
// pixel). Each step is a full lookup; the torn pieces' split was half of the once-a-frame
// capture's GPU time on lavapipe (10 steps: 6.3 ms a 20k-triangle cave5 frame, 6: 5.4-5.9 ms).
const int kCutBisections = 6;

// Where the cut crosses edge p-q (p on one side, q on the other): bisects the edge, keeping the
// half whose warp turns the more (the jump), and returns the crossing's point on each side, each
// its side's limit of the warp there (confvisWarpRelativeToward, hinted by that side's warp),
// moved out to the display's rim where `snapToRim`.
void crossing(Corner p, Corner q, bool snapToRim, out Corner onP, out Corner onQ) {
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
  // extrapolated limits stop short of it by a band (the square-root growth next to the cut), and
  // next to a leaf they stay by their own corners (confvisRimLimit). A loop entered once or not
  // at all (lavapipe runs both sides of an if for every lane).
  for (int once = 0; once < (snapToRim ? 1 : 0); ++once) {
    vec3 direction = normalize(x.relative);  // next to a leaf, where the ray map shows x
    onP.warped.xyz = confvisRimLimit(direction, onP.warped.xyz, p.warped.xyz);
    onQ.warped.xyz = confvisRimLimit(direction, onQ.warped.xyz, q.warped.xyz);
  }
}

// The corner of a torn piece that lies alone on its side of the cut: the one opposite the warp's
// shortest edge (w: the corners' warps).
int loneCorner(vec3 w0, vec3 w1, vec3 w2) {
  float edgeAngle[3] = float[3](confvisAngle(w1, w2), confvisAngle(w2, w0), confvisAngle(w0, w1));
  return edgeAngle[0] <= edgeAngle[1] && edgeAngle[0] <= edgeAngle[2] ? 0
       : edgeAngle[1] <= edgeAngle[2]                                 ? 1
                                                                      : 2;
}

#endif  // CONFVIS_CUT_CROSSING_GLSL
