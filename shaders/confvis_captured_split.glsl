// The once-a-frame capture's torn pieces, split in compute (backends/vulkan/src/
// captured_cut_split.*): warp.geom's capture variant writes each torn piece as the seven vertices
// of its split (two strips: three triangles, nine records of confvis_warp_capture.glsl's layout),
// record w = -1 - the vertex's number, carrying the piece's corners;
// find_captured_torn_pieces.comp lists them, split_captured_at_cut.comp overwrites them with the
// split's vertices. Set 2 of these two passes; set 0 the frame, set 1 the warp maps.
#ifndef CONFVIS_CAPTURED_SPLIT_GLSL
#define CONFVIS_CAPTURED_SPLIT_GLSL

// The captured vertices, 48 bytes each: [0] gl_Position, [1] world.xyz normal.x,
// [2] normal.yz uv.
layout(set = 2, binding = 0, std430) buffer Captured { vec4 records[]; };
// The torn pieces found: their first triangles (indices into the captured buffer's triangles),
// and the split pass's indirect dispatch (one workgroup of kSplitGroup a piece group).
layout(set = 2, binding = 1, std430) buffer TornPieces {
  uint tornCount;
  uint splitGroups[3];
  uint tornFirstTriangle[];
};
// Per capture region, the transform-feedback query's primitives written and needed.
layout(set = 2, binding = 2, std430) readonly buffer Written { uvec2 primitives[]; };

layout(push_constant) uniform CapturedSplit {
  uint firstTriangle;  // the region's first triangle in the captured buffer
  uint capacity;       // its triangles
  uint region;         // its query
  uint snapToRim;      // 0 or 1: VulkanOptions::snapCutToRim
} split;

const uint kSplitGroup = 8u;  // lavapipe's SIMD width (AVX2)

// The marker of captured vertex `v`: the deferred split's vertex number (0-6), or -1 for a
// vertex drawn as captured (w = 1).
int deferredVertex(uint v) { return int(-records[3u * v].w + 0.5) - 1; }

#endif  // CONFVIS_CAPTURED_SPLIT_GLSL
