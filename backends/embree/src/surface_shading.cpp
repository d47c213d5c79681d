// Compiled twice (see surface_shading.hpp): CONFVIS_SIMD_NAMESPACE names the variant. Nothing
// here may be an inline function shared with other translation units (the linker could pick the
// AVX2 copy for baseline code): everything is in an anonymous namespace or the variant's own.
#include "surface_shading.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#ifndef CONFVIS_SIMD_NAMESPACE
#define CONFVIS_SIMD_NAMESPACE sse2
#endif

namespace confvis::embree::CONFVIS_SIMD_NAMESPACE {

namespace {

using Triangle = EmbreeScene::ShadingTriangle;

// The floats of 8 triangle records, transposed: record field k of lane i at field[k][i], in the
// record's order (normals n0, n1, n2; uvs; the material's bits).
struct Fields {
  alignas(32) float field[16][kPacketSize];
};
enum Field { N0X, N0Y, N0Z, N1X, N1Y, N1Z, N2X, N2Y, N2Z, S0, T0, S1, T1, S2, T2 };

// Four 16-byte quarters of every record, transposed four lanes at a time with shuffles instead
// of 120 scalar loads and stores.
void transposeRecords(const Triangle* const (&record)[kPacketSize], Fields& out) {
#if defined(__AVX__)
  for (int q = 0; q < 4; ++q) {
    __m256 v[4];
    for (int i = 0; i < 4; ++i) {
      const __m128 low = _mm_load_ps(reinterpret_cast<const float*>(record[i]) + 4 * q);
      const __m128 high = _mm_load_ps(reinterpret_cast<const float*>(record[i + 4]) + 4 * q);
      v[i] = _mm256_insertf128_ps(_mm256_castps128_ps256(low), high, 1);
    }
    const __m256 t0 = _mm256_unpacklo_ps(v[0], v[1]), t1 = _mm256_unpackhi_ps(v[0], v[1]);
    const __m256 t2 = _mm256_unpacklo_ps(v[2], v[3]), t3 = _mm256_unpackhi_ps(v[2], v[3]);
    _mm256_store_ps(out.field[4 * q + 0], _mm256_shuffle_ps(t0, t2, 0x44));
    _mm256_store_ps(out.field[4 * q + 1], _mm256_shuffle_ps(t0, t2, 0xee));
    _mm256_store_ps(out.field[4 * q + 2], _mm256_shuffle_ps(t1, t3, 0x44));
    _mm256_store_ps(out.field[4 * q + 3], _mm256_shuffle_ps(t1, t3, 0xee));
  }
#elif defined(__SSE2__)
  for (int half = 0; half < 2; ++half)
    for (int q = 0; q < 4; ++q) {
      __m128 v0 = _mm_load_ps(reinterpret_cast<const float*>(record[4 * half + 0]) + 4 * q);
      __m128 v1 = _mm_load_ps(reinterpret_cast<const float*>(record[4 * half + 1]) + 4 * q);
      __m128 v2 = _mm_load_ps(reinterpret_cast<const float*>(record[4 * half + 2]) + 4 * q);
      __m128 v3 = _mm_load_ps(reinterpret_cast<const float*>(record[4 * half + 3]) + 4 * q);
      _MM_TRANSPOSE4_PS(v0, v1, v2, v3);
      _mm_store_ps(out.field[4 * q + 0] + 4 * half, v0);
      _mm_store_ps(out.field[4 * q + 1] + 4 * half, v1);
      _mm_store_ps(out.field[4 * q + 2] + 4 * half, v2);
      _mm_store_ps(out.field[4 * q + 3] + 4 * half, v3);
    }
#else
  for (int lane = 0; lane < kPacketSize; ++lane) {
    float floats[16];
    std::memcpy(floats, record[lane], sizeof floats);
    for (int k = 0; k < 16; ++k) out.field[k][lane] = floats[k];
  }
#endif
}

// The material of every lane: its texture (null: none) and factor.
struct Materials {
  alignas(32) Lanes width, height;  // of the texture; 0 without one
  alignas(32) std::array<int, kPacketSize> texelsPerRow;
  alignas(32) Lanes factorRed, factorGreen, factorBlue;
  std::array<const Texture*, kPacketSize> texture;
  bool textured = false;  // any lane
};

void setMaterial(const EmbreeScene::ShadingMaterial& m, int lane, Materials& out) {
  const Texture* texture = m.texture;
  out.texture[lane] = texture;
  out.texelsPerRow[lane] = texture ? texture->width : 0;
  out.width[lane] = texture ? static_cast<float>(texture->width) : 0.0f;
  out.height[lane] = texture ? static_cast<float>(texture->height) : 0.0f;
  out.factorRed[lane] = m.factor.r, out.factorGreen[lane] = m.factor.g;
  out.factorBlue[lane] = m.factor.b;
  out.textured |= texture != nullptr;
}

void gatherMaterials(const EmbreeScene& scene, const Triangle* const (&record)[kPacketSize],
                     Materials& out) {
  bool one = true;
  for (int lane = 1; lane < kPacketSize; ++lane) one &= record[lane]->material == record[0]->material;
  if (!one) {
    for (int lane = 0; lane < kPacketSize; ++lane)
      setMaterial(scene.shadingMaterial(record[lane]->material), lane, out);
    return;
  }
  setMaterial(scene.shadingMaterial(record[0]->material), 0, out);  // then broadcast
  for (int lane = 1; lane < kPacketSize; ++lane) {
    out.texture[lane] = out.texture[0], out.texelsPerRow[lane] = out.texelsPerRow[0];
    out.width[lane] = out.width[0], out.height[lane] = out.height[0];
    out.factorRed[lane] = out.factorRed[0], out.factorGreen[lane] = out.factorGreen[0];
    out.factorBlue[lane] = out.factorBlue[0];
  }
}

// Where each lane's texture footprint lies (Texture::sample): inside the image, the four texels
// from `texel` on, with bilinear weights fx, fy; or not (untextured, or across the border).
struct Footprints {
  alignas(32) std::array<int, kPacketSize> inside, texel;
  alignas(32) Lanes fx, fy, s, t;
};

// A GCC/Clang vector of 4 floats: one RGBA texel; SSE on x86-64, VEX-encoded in the AVX2 build.
using Float4 = float __attribute__((vector_size(16)));

Float4 load4(const float* p) {
  Float4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// Texture::sample per lane, RGBA at a time: the inside footprints blended as glm::mix does
// (a (1 - f) + b f, in that order), the others through sampleWrapped (white untextured).
void sampleTextures(const Materials& m, const Footprints& place, Lanes& red, Lanes& green,
                    Lanes& blue) {
  for (int lane = 0; lane < kPacketSize; ++lane) {
    Float4 colour;
    if (place.inside[lane]) {
      const float* row0 =
          m.texture[lane]->rgba.data() + 4 * static_cast<std::size_t>(place.texel[lane]);
      const float* row1 = row0 + 4 * static_cast<std::size_t>(m.texelsPerRow[lane]);
      const float fx = place.fx[lane], fy = place.fy[lane];
      const Float4 top = load4(row0) * (1.0f - fx) + load4(row0 + 4) * fx;
      const Float4 bottom = load4(row1) * (1.0f - fx) + load4(row1 + 4) * fx;
      colour = top * (1.0f - fy) + bottom * fy;
    } else {
      const glm::vec4 c =
          m.texture[lane] ? m.texture[lane]->sampleWrapped({place.s[lane], place.t[lane]})
                          : glm::vec4(1.0f);
      colour = Float4{c.r, c.g, c.b, c.a};
    }
    red[lane] = colour[0], green[lane] = colour[1], blue[lane] = colour[2];
  }
}

}  // namespace

// Structure of arrays: gathers per lane (one record, the material, texels), the arithmetic over
// all 8 lanes without branches, which the compiler vectorises. The arithmetic follows glm's
// order of operations in Scene::baseColorAt and Texture::sample.
void shadeSurface(const EmbreeScene& scene, const PacketHits& hits, PacketColours& colours,
                  SurfaceNormals& out) {
  const RTCHit8& hit = hits.rayhit.hit;
  const Triangle* const triangles = scene.shadingTriangles();
  const Triangle* record[kPacketSize];
  for (int lane = 0; lane < kPacketSize; ++lane)
    record[lane] = triangles + (hits.hit[lane] ? scene.shadingTriangleIndex(hit.geomID[lane],
                                                                             hit.primID[lane])
                                               : 0);
  Fields g;
  transposeRecords(record, g);
  Materials m;
  gatherMaterials(scene, record, m);
  Footprints place;
  for (int lane = 0; lane < kPacketSize; ++lane) {
    const float u = hit.u[lane], v = hit.v[lane], w = 1.0f - u - v;
    const auto& f = g.field;
    const float nx = w * f[N0X][lane] + u * f[N1X][lane] + v * f[N2X][lane];
    const float ny = w * f[N0Y][lane] + u * f[N1Y][lane] + v * f[N2Y][lane];
    const float nz = w * f[N0Z][lane] + u * f[N1Z][lane] + v * f[N2Z][lane];
    // No vertex normals, or degenerate ones: the geometric normal. A blend by 1 or 0 rather than
    // a select, which GCC 12 does not vectorise here (both terms are finite).
    const float keep = nx * nx + ny * ny + nz * nz > 1e-40f ? 1.0f : 0.0f;
    out.nx[lane] = keep * nx + (1.0f - keep) * hit.Ng_x[lane];
    out.ny[lane] = keep * ny + (1.0f - keep) * hit.Ng_y[lane];
    out.nz[lane] = keep * nz + (1.0f - keep) * hit.Ng_z[lane];
    const float s = w * f[S0][lane] + u * f[S1][lane] + v * f[S2][lane];
    const float t = w * f[T0][lane] + u * f[T1][lane] + v * f[T2][lane];
    place.s[lane] = s, place.t[lane] = t;
    // Texture::sample: the footprint at (x, y) = uv * size - 0.5 lies inside when x, y >= 0 and
    // below size - 1 (never without a texture: size 0). Clamped before the integer conversion,
    // which is then defined on every lane.
    const float x = s * m.width[lane] - 0.5f, y = t * m.height[lane] - 0.5f;
    place.inside[lane] =
        (x >= 0.0f) & (y >= 0.0f) & (x < m.width[lane] - 1.0f) & (y < m.height[lane] - 1.0f);
    const int ix = static_cast<int>(std::min(std::max(0.0f, x), m.width[lane]));
    const int iy = static_cast<int>(std::min(std::max(0.0f, y), m.height[lane]));
    place.fx[lane] = x - static_cast<float>(ix);
    place.fy[lane] = y - static_cast<float>(iy);
    place.texel[lane] = iy * m.texelsPerRow[lane] + ix;
  }
  alignas(32) Lanes red, green, blue;  // the texture's, 1 without one (factor x 1 = factor)
  if (m.textured) {
    sampleTextures(m, place, red, green, blue);
  } else {
    red.fill(1.0f), green.fill(1.0f), blue.fill(1.0f);
  }
  // The headlight: light from the eye along the ray, two-sided; lanes without a hit carry
  // zeros through and come out black.
  const RTCRay8& ray = hits.rayhit.ray;
  for (int lane = 0; lane < kPacketSize; ++lane) {
    const float nx = out.nx[lane], ny = out.ny[lane], nz = out.nz[lane];
    const float lengthSquared = nx * nx + ny * ny + nz * nz;
    const float facing = nx * ray.dir_x[lane] + ny * ray.dir_y[lane] + nz * ray.dir_z[lane];
    // 1 / |n|, 0 for a zero normal (a missed lane); computed unconditionally so that the loop
    // vectorises (the compiler may not speculate a division by zero).
    const bool nonzero = lengthSquared > 0.0f;
    const float root = std::sqrt(nonzero ? lengthSquared : 1.0f);
    const float inverse = 1.0f / root;
    const float inverseLength = nonzero ? inverse : 0.0f;
    // Two-sided: the normal turned towards the viewer, so files with either winding shade alike;
    // Lambert with the headlight is then |n . d| / |n|.
    out.towardsViewer[lane] = facing > 0.0f ? -inverseLength : inverseLength;
    const float lambert = std::abs(facing) * inverseLength;
    colours.red[lane] = m.factorRed[lane] * red[lane] * lambert;
    colours.green[lane] = m.factorGreen[lane] * green[lane] * lambert;
    colours.blue[lane] = m.factorBlue[lane] * blue[lane] * lambert;
  }
  // Apart: reading the bool array in the loop above keeps GCC from vectorising it.
  for (int lane = 0; lane < kPacketSize; ++lane) colours.alpha[lane] = hits.hit[lane] ? 1.0f : 0.0f;
}

}  // namespace confvis::embree::CONFVIS_SIMD_NAMESPACE
