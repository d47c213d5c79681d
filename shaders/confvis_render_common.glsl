// Resources shared by the confvis Vulkan backend's shaders (backends/vulkan/src/pipelines.cpp
// creates the matching layouts). Not part of the public warp interface (confvis_warp.glsl).
#ifndef CONFVIS_RENDER_COMMON_GLSL
#define CONFVIS_RENDER_COMMON_GLSL

#extension GL_EXT_multiview : require

// Set 0: the frame.
#include "confvis_frame.glsl"

// One entry per (wall, eye), index wall * eyes + eye; a pass draws views viewBase + gl_ViewIndex.
// params: x = largest bend error (radians), y = largest segment angle (radians),
//         z = smallest cut gap (radians), w = 0 to draw the warp unsubdivided, else 1 to
//         tessellate, plus 1 to leave the ends of the pieces warp.geom splits at the cut at the
//         extrapolated limits instead of moving them out to the rim (VulkanOptions::snapCutToRim
//         off), plus 2 to drop those pieces (VulkanOptions::drawTornPiecesUpToTheCut off), plus
//         4 in the once-a-frame capture's view (no culling by view; warp_capture.cpp).
struct View {
  mat4 viewProj;     // physical frame -> Vulkan clip space of the wall for this eye
  vec4 eyeVirtual;   // xyz: where the headlight sits, in world coordinates
  vec4 params;
};
layout(set = 0, binding = 1, std430) readonly buffer Views { View views[]; };

// Edge levels of the tessellated triangles, 3 per slot of the pre-pass's tessellated lists
// (confvis_prepass_common.glsl): xyz = warped edge midpoint relative to c, w = segments.
layout(set = 0, binding = 2, std430) readonly buffer PatchLevels { vec4 patchLevels[]; };

layout(push_constant) uniform Push {
  vec4 baseColorFactor;
  uint viewBase;    // views[] index of this pass's view 0
  uint hasNormals;
  int vertexOffset;  // tessellated draws: the mesh's, added to the indices of the lists
} push;

View currentView() { return views[push.viewBase + gl_ViewIndex]; }
View wallView() { return views[push.viewBase]; }  // for the eye-independent params

// The geometry shader's switches in params.w: the torn pieces' ends are moved out to the
// display's rim (VulkanOptions::snapCutToRim; the tessellation evaluation's points next to the
// cut's leaves refined on the ray map with it), the torn pieces drawn up to the cut
// (VulkanOptions::drawTornPiecesUpToTheCut).
int switches() { return int(wallView().params.w + 0.5) - 1; }
bool snapsToRim() { return (switches() & 1) == 0; }
bool drawsTornPieces() { return (switches() & 2) == 0; }

#endif
