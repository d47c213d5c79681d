#version 450
#extension GL_GOOGLE_include_directive : require
// Shading shared with the Embree backend: base colour (factor x texture) x two-sided Lambert with
// a headlight at the eye (in conformal mode the eye's virtual position).
#include "confvis_render_common.glsl"

layout(set = 2, binding = 0) uniform sampler2D baseColorTexture;  // 1x1 white when none

layout(location = 0) in vec3 inWorld;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;

layout(location = 0) out vec4 outColor;

void main() {
  // Meshes without normals shade with the face normal of the virtual triangle.
  vec3 normal = push.hasNormals != 0u ? inNormal : cross(dFdx(inWorld), dFdy(inWorld));
  vec3 toLight = currentView().eyeVirtual.xyz - inWorld;
  float lambert = abs(dot(normalize(normal), normalize(toLight)));
  vec4 base = push.baseColorFactor * texture(baseColorTexture, inUv);
  outColor = vec4(base.rgb * lambert, 1.0);
}
