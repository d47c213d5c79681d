// The frame's uniforms, shared by the confvis Vulkan backend's graphics and compute shaders.
// worldToPhysical undoes the virtual camera: a world (virtual) point x goes to
// c + R^T (x - position) in the physical frame. warpCentre.xyz is the map's reference point.
#ifndef CONFVIS_FRAME_GLSL
#define CONFVIS_FRAME_GLSL

layout(set = 0, binding = 0) uniform Frame {
  mat4 worldToPhysical;
  vec4 warpCentre;
} frame;

#endif
