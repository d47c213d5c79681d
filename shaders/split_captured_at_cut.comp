#version 450
#extension GL_GOOGLE_include_directive : require
// The once-a-frame capture's torn pieces split at the cut (indirect dispatch over the list
// find_captured_torn_pieces.comp fills): each deferred split's nine records (confvis_captured_
// split.glsl) get what warp.geom's splitAtCut emits in each wall's draw, the same crossing
// (confvis_cut_crossing.glsl): the lone corner's piece and the others' quad, each up to the cut.
#include "confvis_frame.glsl"
#include "confvis_warp.glsl"
#include "confvis_warp_rim.glsl"
#include "confvis_cut_crossing.glsl"
#include "confvis_captured_split.glsl"

layout(local_size_x = 8) in;  // kSplitGroup

void main() {
  uint piece = gl_GlobalInvocationID.x;
  if (piece >= tornCount) return;
  uint first = 3u * tornFirstTriangle[piece];
  // The corners: 0 lone (relative, attributes), 1 the three warps, 3 and 5 the others.
  Corner c[3];
  for (int k = 0; k < 3; ++k)
    c[k] = Corner(vec3(0.0), vec4(0.0, 0.0, 0.0, 1.0), vec3(0.0), vec3(0.0), vec2(0.0));
  for (uint j = 0u; j < 9u; ++j) {
    uint v = first + j;
    int k = deferredVertex(v);
    vec4 p = records[3u * v], q = records[3u * v + 1u], r = records[3u * v + 2u];
    int corner = k == 0 ? 0 : k == 3 ? 1 : k == 5 ? 2 : -1;
    for (int i = 0; i < 3; ++i) {
      bool mine = corner == i;
      c[i].relative = mine ? p.xyz : c[i].relative;
      c[i].world = mine ? q.xyz : c[i].world;
      c[i].normal = mine ? vec3(q.w, r.xy) : c[i].normal;
      c[i].uv = mine ? r.zw : c[i].uv;
    }
    c[0].warped.xyz = k == 1 ? p.xyz : c[0].warped.xyz;
    c[1].warped.xyz = k == 1 ? q.xyz : c[1].warped.xyz;
    c[2].warped.xyz = k == 1 ? vec3(q.w, r.xy) : c[2].warped.xyz;
  }
  bool snap = split.snapToRim != 0u;
  Corner drawn[7];
  drawn[0] = c[0];
  drawn[3] = c[1];
  drawn[5] = c[2];
  crossing(c[0], c[1], snap, drawn[1], drawn[4]);
  crossing(c[0], c[2], snap, drawn[2], drawn[6]);
  for (uint j = 0u; j < 9u; ++j) {
    uint v = first + j;
    Corner s = drawn[clamp(deferredVertex(v), 0, 6)];
    records[3u * v] = vec4(frame.warpCentre.xyz + s.warped.xyz, 1.0);
    records[3u * v + 1u] = vec4(s.world, s.normal.x);
    records[3u * v + 2u] = vec4(s.normal.yz, s.uv);
  }
}
