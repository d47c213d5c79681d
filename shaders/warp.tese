#version 450
#extension GL_GOOGLE_include_directive : require
// Conformal mode, patches that may lose pieces: tessellated vertices for warp.geom.
#include "confvis_warp_tese.glsl"

layout(location = 0) out vec3 outRelative;
layout(location = 1) out vec4 outWarped;
layout(location = 2) out vec3 outWorld;
layout(location = 3) out vec3 outNormal;
layout(location = 4) out vec2 outUv;

void main() {
  TessellatedVertex v = tessellatedVertex();
  outRelative = v.relative;
  outWarped = v.warped;
  outWorld = v.world;
  outNormal = v.normal;
  outUv = v.uv;
}
