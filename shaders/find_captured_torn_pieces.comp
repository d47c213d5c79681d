#version 450
#extension GL_GOOGLE_include_directive : require
// The once-a-frame capture's torn pieces (confvis_captured_split.glsl), one region of the
// captured buffer: lists each deferred split by its first triangle (the one holding vertex 0),
// so that split_captured_at_cut.comp runs in SIMD groups of torn pieces only.
#include "confvis_captured_split.glsl"

layout(local_size_x = 64) in;

void main() {
  uint t = gl_GlobalInvocationID.x;
  // Whole splits only: a region that overflowed is captured again.
  uint written = min(primitives[split.region].x, split.capacity);
  if (t + 2u >= written) return;
  uint v = 3u * (split.firstTriangle + t);
  if (deferredVertex(v) != 0 && deferredVertex(v + 1u) != 0 && deferredVertex(v + 2u) != 0)
    return;
  uint slot = atomicAdd(tornCount, 1u);
  tornFirstTriangle[slot] = split.firstTriangle + t;
  atomicMax(splitGroups[0], slot / kSplitGroup + 1u);
}
