#include "surface_packet.hpp"

#include <algorithm>

namespace confvis::embree {

namespace {

using Lanes = std::array<float, kPacketSize>;

// What the surface needs per lane, from the hit lanes' meshes (zero elsewhere): vertex normals
// and uvs of the hit triangle, the texture, the material factor. With kOneTriangle (every lane
// hit the same triangle, as most packets of neighbouring pixels do) only lane 0 is filled and
// the arithmetic broadcasts it. Every field used is written (no blanket zeroing).
struct Vertices {
  alignas(32) Lanes n0x, n0y, n0z, n1x, n1y, n1z, n2x, n2y, n2z;
  alignas(32) Lanes s0, t0, s1, t1, s2, t2;
  alignas(32) Lanes width, height;  // of the texture; 0 without one
  alignas(32) std::array<int, kPacketSize> texelsPerRow;  // of the texture; 0 without one
  alignas(32) Lanes factorRed, factorGreen, factorBlue;
  std::array<const Texture*, kPacketSize> texture;
};

// Where each lane's texture footprint lies: inside the image (the common case: four texels read
// directly from `texel` on) or not (untextured, or across the border).
struct FootprintPlace {
  alignas(32) std::array<int, kPacketSize> inside, texel;
  alignas(32) Lanes fx, fy;  // bilinear weights along x and y
};

// Texels a, b (row y) and c, d (row y + 1) of one channel of each lane's footprint.
struct Footprint {
  alignas(32) Lanes a, b, c, d;
};

bool oneTriangle(const PacketHits& hits) {
  const RTCHit8& hit = hits.rayhit.hit;
  bool same = true;
  for (int lane = 0; lane < kPacketSize; ++lane)
    same &= hits.hit[lane] & (hit.geomID[lane] == hit.geomID[0]) &
            (hit.primID[lane] == hit.primID[0]);
  return same;
}

template <bool kOneTriangle>
void gatherVertices(const EmbreeScene& scene, const PacketHits& hits, Vertices& g) {
  for (int lane = 0; lane < (kOneTriangle ? 1 : kPacketSize); ++lane) {
    const EmbreeScene::ShadingMesh* mesh =
        hits.hit[lane] ? &scene.shadingMesh(hits.rayhit.hit.geomID[lane]) : nullptr;
    const glm::uvec3 t = mesh ? mesh->triangles[hits.rayhit.hit.primID[lane]] : glm::uvec3(0);
    // Without vertex normals zero: the geometric normal steps in (surfaceAt).
    const glm::vec3 zero(0.0f);
    const bool normals = mesh && mesh->normals;
    const glm::vec3& n0 = normals ? mesh->normals[t.x] : zero;
    const glm::vec3& n1 = normals ? mesh->normals[t.y] : zero;
    const glm::vec3& n2 = normals ? mesh->normals[t.z] : zero;
    g.n0x[lane] = n0.x, g.n0y[lane] = n0.y, g.n0z[lane] = n0.z;
    g.n1x[lane] = n1.x, g.n1y[lane] = n1.y, g.n1z[lane] = n1.z;
    g.n2x[lane] = n2.x, g.n2y[lane] = n2.y, g.n2z[lane] = n2.z;
    const glm::vec4 factor = mesh ? mesh->factor : glm::vec4(0.0f);
    g.factorRed[lane] = factor.r, g.factorGreen[lane] = factor.g, g.factorBlue[lane] = factor.b;
    const Texture* texture = mesh ? mesh->texture : nullptr;
    g.texture[lane] = texture;
    g.texelsPerRow[lane] = texture ? texture->width : 0;
    g.width[lane] = texture ? static_cast<float>(texture->width) : 0.0f;
    g.height[lane] = texture ? static_cast<float>(texture->height) : 0.0f;
    const glm::vec2 none(0.0f);
    const glm::vec2& uv0 = texture ? mesh->uvs[t.x] : none;
    const glm::vec2& uv1 = texture ? mesh->uvs[t.y] : none;
    const glm::vec2& uv2 = texture ? mesh->uvs[t.z] : none;
    g.s0[lane] = uv0.x, g.t0[lane] = uv0.y, g.s1[lane] = uv1.x, g.t1[lane] = uv1.y;
    g.s2[lane] = uv2.x, g.t2[lane] = uv2.y;
  }
}

// Texture::sample's footprint for every lane: the four texels of each channel; `place` comes
// from surfaceOf, and fx, fy are set to 0 where the footprint is not inside. Untextured lanes
// read white (the bilinear blend then gives exactly 1), footprints that leave the image take
// Texture::sampleWrapped's colour.
template <bool kOneTriangle>
void gatherTexels(const Vertices& g, const Lanes& s, const Lanes& t, FootprintPlace& place,
                  Footprint (&channels)[3]) {
  for (int lane = 0; lane < kPacketSize; ++lane) {
    const int i = kOneTriangle ? 0 : lane;
    const Texture* texture = g.texture[i];
    if (place.inside[lane]) {
      const float* row0 = texture->rgba.data() + 4 * static_cast<std::size_t>(place.texel[lane]);
      const float* row1 = row0 + 4 * static_cast<std::size_t>(g.texelsPerRow[i]);
      for (int c = 0; c < 3; ++c) {
        Footprint& f = channels[c];
        f.a[lane] = row0[c], f.b[lane] = row0[4 + c], f.c[lane] = row1[c], f.d[lane] = row1[4 + c];
      }
      continue;
    }
    place.fx[lane] = place.fy[lane] = 0.0f;
    const glm::vec4 colour = texture ? texture->sampleWrapped({s[lane], t[lane]}) : glm::vec4(1.0f);
    for (int c = 0; c < 3; ++c) {
      Footprint& f = channels[c];
      f.a[lane] = f.b[lane] = f.c[lane] = f.d[lane] = colour[c];
    }
  }
}

// Structure of arrays: the gathers (vertex data, texels) per lane, the arithmetic over all 8
// lanes without branches, which the compiler vectorises; Embree's hit record is already laid
// out this way. The arithmetic follows glm's order of operations in Scene::baseColorAt and
// Texture::sample.
template <bool kOneTriangle>
void surfaceOf(const EmbreeScene& scene, const PacketHits& hits, SurfacePacket& out) {
  const RTCHit8& hit = hits.rayhit.hit;
  Vertices g;
  gatherVertices<kOneTriangle>(scene, hits, g);
  alignas(32) Lanes s, t;
  FootprintPlace place;
  for (int lane = 0; lane < kPacketSize; ++lane) {
    const int i = kOneTriangle ? 0 : lane;
    const float u = hit.u[lane], v = hit.v[lane], w = 1.0f - u - v;
    const float nx = w * g.n0x[i] + u * g.n1x[i] + v * g.n2x[i];
    const float ny = w * g.n0y[i] + u * g.n1y[i] + v * g.n2y[i];
    const float nz = w * g.n0z[i] + u * g.n1z[i] + v * g.n2z[i];
    // No vertex normals, or degenerate ones: the geometric normal. A blend by 1 or 0 rather than
    // a select, which GCC 12 does not vectorise here (both terms are finite).
    const float keep = nx * nx + ny * ny + nz * nz > 1e-40f ? 1.0f : 0.0f;
    out.nx[lane] = keep * nx + (1.0f - keep) * hit.Ng_x[lane];
    out.ny[lane] = keep * ny + (1.0f - keep) * hit.Ng_y[lane];
    out.nz[lane] = keep * nz + (1.0f - keep) * hit.Ng_z[lane];
    s[lane] = w * g.s0[i] + u * g.s1[i] + v * g.s2[i];
    t[lane] = w * g.t0[i] + u * g.t1[i] + v * g.t2[i];
    // Texture::sample: the footprint at (x, y) = uv * size - 0.5 lies inside when x, y >= 0 and
    // below size - 1 (never without a texture: size 0). Clamped before the integer conversion,
    // which is then defined on every lane.
    const float x = s[lane] * g.width[i] - 0.5f, y = t[lane] * g.height[i] - 0.5f;
    place.inside[lane] =
        (x >= 0.0f) & (y >= 0.0f) & (x < g.width[i] - 1.0f) & (y < g.height[i] - 1.0f);
    const int ix = static_cast<int>(std::min(std::max(0.0f, x), g.width[i]));
    const int iy = static_cast<int>(std::min(std::max(0.0f, y), g.height[i]));
    place.fx[lane] = x - static_cast<float>(ix);
    place.fy[lane] = y - static_cast<float>(iy);
    place.texel[lane] = iy * g.texelsPerRow[i] + ix;
  }
  const bool textured =
      std::any_of(g.texture.begin(), g.texture.begin() + (kOneTriangle ? 1 : kPacketSize),
                  [](const Texture* texture) { return texture != nullptr; });
  if (!textured) {  // untextured meshes and background: the factor alone
    for (int lane = 0; lane < kPacketSize; ++lane) {
      const int i = kOneTriangle ? 0 : lane;
      out.red[lane] = g.factorRed[i], out.green[lane] = g.factorGreen[i];
      out.blue[lane] = g.factorBlue[i];
    }
    return;
  }
  Footprint channels[3];
  gatherTexels<kOneTriangle>(g, s, t, place, channels);
  const Lanes &fx = place.fx, &fy = place.fy;
  for (int lane = 0; lane < kPacketSize; ++lane) {
    const int i = kOneTriangle ? 0 : lane;
    auto bilinear = [&](const Footprint& f) {
      const float top = f.a[lane] * (1.0f - fx[lane]) + f.b[lane] * fx[lane];
      const float bottom = f.c[lane] * (1.0f - fx[lane]) + f.d[lane] * fx[lane];
      return top * (1.0f - fy[lane]) + bottom * fy[lane];
    };
    out.red[lane] = g.factorRed[i] * bilinear(channels[0]);
    out.green[lane] = g.factorGreen[i] * bilinear(channels[1]);
    out.blue[lane] = g.factorBlue[i] * bilinear(channels[2]);
  }
}

}  // namespace

void surfaceAt(const EmbreeScene& scene, const PacketHits& hits, SurfacePacket& surface) {
  if (std::none_of(hits.hit.begin(), hits.hit.end(), [](bool hit) { return hit; })) {
    for (auto* lanes : {&surface.nx, &surface.ny, &surface.nz, &surface.red, &surface.green,
                        &surface.blue})
      lanes->fill(0.0f);  // background only
    return;
  }
  if (oneTriangle(hits))
    surfaceOf<true>(scene, hits, surface);
  else
    surfaceOf<false>(scene, hits, surface);
}

}  // namespace confvis::embree
