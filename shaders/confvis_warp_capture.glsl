// Once-a-frame capture of the tessellated lists (backends/vulkan/src/warp_capture.*): warp.geom
// and warp_projected.tese are compiled a second time with CONFVIS_CAPTURE defined, their outputs
// then written by transform feedback into one buffer that every wall and eye draws
// (warp_captured.vert). The capture pass projects with an identity viewProj, so gl_Position holds
// the warped physical point c + T(x - c) and each wall's draw applies its own projection
// (clipping per wall stays the hardware's). Record: gl_Position, world, normal, uv: 48 bytes.
#ifndef CONFVIS_WARP_CAPTURE_GLSL
#define CONFVIS_WARP_CAPTURE_GLSL

#ifdef CONFVIS_CAPTURE
#define CONFVIS_XFB(offset) , xfb_buffer = 0, xfb_offset = offset
layout(xfb_buffer = 0, xfb_stride = 48) out;
out gl_PerVertex {
  layout(xfb_buffer = 0, xfb_offset = 0) vec4 gl_Position;
};
#else
#define CONFVIS_XFB(offset)
#endif

#endif
