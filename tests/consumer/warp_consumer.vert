#version 450
// An application's own vertex shader using the installed warp include: compiled by the consumer
// test with glslangValidator -I${confvis_SHADER_DIR}, as README.md says.
#extension GL_GOOGLE_include_directive : require
#include "confvis_warp.glsl"

layout(location = 0) in vec3 position;  // virtual scene point, physical frame
layout(push_constant) uniform Frame {
  mat4 viewProjection;
  vec4 reference;  // the map's reference point c (xyz)
} frame;

void main() {
  vec4 warped = confvisWarpRelative(position - frame.reference.xyz);  // w: inside the source field
  gl_Position = frame.viewProjection * vec4(frame.reference.xyz + warped.xyz, 1.0);
}
