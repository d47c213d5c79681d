#version 450
#extension GL_GOOGLE_include_directive : require
// Splits the pre-pass's flat list (classify_triangles.comp: the mesh's whole range, degenerate
// triangles where not flat) into one list per wall: a triangle goes to a wall's list unless, for
// every eye of that wall, its three clip-space corners lie outside the same side plane of the
// wall's frustum (the same viewProj and warped point warp_simple.vert uses), so that each wall's
// pass runs the vertex shader, clipping and binning of its own triangles only (lavapipe
// otherwise does it for the whole list once per wall). backends/vulkan/src/flat_wall_cull.cpp
// records it every conformal frame, also where the pre-pass is reused (the frusta follow the
// head).
#include "confvis_frame.glsl"

layout(local_size_x = 64) in;

struct View {  // confvis_render_common.glsl
  mat4 viewProj;
  vec4 eyeVirtual;
  vec4 params;
};
layout(set = 0, binding = 1, std430) readonly buffer Views { View views[]; };

layout(set = 1, binding = 0, std430) readonly buffer FlatIndices { uint flatIndices[]; };
layout(set = 1, binding = 1, std430) readonly buffer Warped { vec4 warped[]; };
// Wall w's list starts at w * wallStride; mesh m's part of it at w * wallStride + its firstIndex.
layout(set = 1, binding = 2, std430) writeonly buffer WallIndices { uint wallIndices[]; };
struct DrawCommand {  // VkDrawIndexedIndirectCommand
  uint indexCount;
  uint instanceCount;
  uint firstIndex;
  int vertexOffset;
  uint firstInstance;
};
// Per wall and mesh (index w * meshes + m); the host sets them to empty lists.
layout(set = 1, binding = 3, std430) buffer WallCommands { DrawCommand commands[]; };

layout(push_constant) uniform Cull {
  uint triangles;   // the mesh's
  uint firstIndex;  // the mesh's
  int vertexOffset;
  uint mesh;
  uint meshes;
  uint walls;
  uint eyes;        // views per wall: wall w's are views[w * eyes + e]
  uint wallStride;  // indices per wall's list (the scene's)
  uint broken;      // tests: cull against the next wall's frusta
} cull;

// True where all three points lie outside one side plane of the view's frustum. A triangle
// is cut by the homogeneous half-space test before the divide, so this holds for points behind
// the eye too; the margin keeps rounding from ever dropping a triangle that touches the frustum.
bool outside(mat4 viewProj, vec3 p[3]) {
  vec4 beyond = vec4(1e30);  // per side plane: how far the nearest corner lies beyond it
  for (int k = 0; k < 3; ++k) {
    vec4 c = viewProj * vec4(p[k], 1.0);
    float margin = 1e-4 * abs(c.w) + 1e-6;
    beyond = min(beyond, vec4(-c.x, c.x, -c.y, c.y) - vec4(c.w + margin));
  }
  return any(greaterThan(beyond, vec4(0.0)));
}

void main() {
  uint t = gl_GlobalInvocationID.x;
  if (t >= cull.triangles) return;
  uint at = cull.firstIndex + 3u * t;
  uint i[3] = uint[3](flatIndices[at], flatIndices[at + 1u], flatIndices[at + 2u]);
  if (i[0] == i[1] && i[1] == i[2]) return;  // degenerate: not in the flat list
  vec3 p[3];
  for (int k = 0; k < 3; ++k) p[k] = frame.warpCentre.xyz + warped[cull.vertexOffset + int(i[k])].xyz;
  for (uint w = 0u; w < cull.walls; ++w) {
    uint frustum = cull.broken != 0u ? (w + 1u) % cull.walls : w;
    bool seen = false;
    for (uint e = 0u; e < cull.eyes; ++e)
      seen = seen || !outside(views[frustum * cull.eyes + e].viewProj, p);
    if (!seen) continue;
    uint command = w * cull.meshes + cull.mesh;
    uint slot = atomicAdd(commands[command].indexCount, 3u);
    uint to = w * cull.wallStride + cull.firstIndex + slot;
    wallIndices[to] = i[0]; wallIndices[to + 1u] = i[1]; wallIndices[to + 2u] = i[2];
  }
}
