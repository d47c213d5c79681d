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
enum Field { N0X, N0Y, N0Z, N1X, N1Y, N1Z, N2X, N2Y, N2Z, S0, T0, S1, T1, S2, T2, MATERIAL };

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
  // The texture's RGBA floats, or kNoTexels where no footprint can lie inside (no texture, or
  // under 2 x 2 texels): every lane loads the first two texels of two rows from here at least.
  std::array<const float*, kPacketSize> texels;
  bool textured = false;  // any lane
};

// Stands in for the texels of lanes whose footprint is not inside a texture (the first two texels
// of "row 0" and "row 1" are both these); those lanes are sampled apart afterwards.
alignas(16) constexpr float kNoTexels[8] = {};

// What a lane reads of its material.
struct MaterialLane {
  const Texture* texture;
  const float* texels;
  int width, height;
  float red, green, blue;
};

MaterialLane materialLane(const EmbreeScene::ShadingMaterial& material) {
  const Texture* texture = material.texture;
  const int width = texture ? texture->width : 0, height = texture ? texture->height : 0;
  return {texture, width >= 2 && height >= 2 ? texture->rgba.data() : kNoTexels, width, height,
          material.factor.r, material.factor.g, material.factor.b};
}

// `materialBits` holds each lane's material index (the records' last field). Where the packet
// has one material (nearly always), every array is filled with whole-vector stores: the loops
// after this read them as vectors, and a vector load waits until eight scalar stores it overlaps
// have reached the cache (no store-to-load forwarding).
void gatherMaterials(const EmbreeScene& scene, const float (&materialBits)[kPacketSize],
                     Materials& out) {
  std::array<std::uint32_t, kPacketSize> material;
  std::memcpy(material.data(), materialBits, sizeof material);
  bool one = true;
  for (int lane = 1; lane < kPacketSize; ++lane) one &= material[lane] == material[0];
  if (one) {
    const MaterialLane m = materialLane(scene.shadingMaterial(material[0]));
    out.texture.fill(m.texture), out.texels.fill(m.texels);
    out.texelsPerRow.fill(m.width);
    out.width.fill(static_cast<float>(m.width)), out.height.fill(static_cast<float>(m.height));
    out.factorRed.fill(m.red), out.factorGreen.fill(m.green), out.factorBlue.fill(m.blue);
    out.textured = m.texture != nullptr;
    return;
  }
  out.textured = false;
  for (int lane = 0; lane < kPacketSize; ++lane) {
    const MaterialLane m = materialLane(scene.shadingMaterial(material[lane]));
    out.texture[lane] = m.texture, out.texels[lane] = m.texels;
    out.texelsPerRow[lane] = m.width;
    out.width[lane] = static_cast<float>(m.width), out.height[lane] = static_cast<float>(m.height);
    out.factorRed[lane] = m.red, out.factorGreen[lane] = m.green, out.factorBlue[lane] = m.blue;
    out.textured |= m.texture != nullptr;
  }
}

// Where each lane's texture footprint lies (Texture::sample): inside the image, the four texels
// from `row0` on and from `row1` on (texel indices; 0 for both where not inside), with bilinear
// weights fx, fy; or not (untextured, or across the border).
struct Footprints {
  alignas(32) std::array<int, kPacketSize> inside, row0, row1;
  alignas(32) Lanes fx, fy, s, t;
};

// The red, green and blue of one texel corner of every lane's footprint, as structure of arrays
// (alpha is never used).
struct CornerColours {
  alignas(32) Lanes red, green, blue;
};

// The four texels of every lane's footprint, transposed into structure of arrays with shuffles
// four lanes at a time (blending each lane's texels RGBA at a time and storing three scalars a
// lane left the vector loads after it waiting on store forwarding).
struct Corners {
  CornerColours topLeft, topRight, bottomLeft, bottomRight;
};

const float* texelAt(const Materials& m, int lane, int texel) {
  return m.texels[lane] + 4 * static_cast<std::size_t>(texel);
}

#if defined(__SSE2__) && !defined(__AVX__)
// Lanes' RGBA in v0..v3 -> red, green, blue of those four lanes from out + at on.
void storeTransposed(__m128 v0, __m128 v1, __m128 v2, __m128 v3, int at, CornerColours& out) {
  _MM_TRANSPOSE4_PS(v0, v1, v2, v3);
  _mm_store_ps(out.red.data() + at, v0);
  _mm_store_ps(out.green.data() + at, v1);
  _mm_store_ps(out.blue.data() + at, v2);
}
#endif

#if defined(__AVX__)
// Lanes i and i + 4 of v[i] (low and high halves) -> red, green, blue of all 8 lanes.
void storeTransposed(const __m256 (&v)[4], CornerColours& out) {
  const __m256 t0 = _mm256_unpacklo_ps(v[0], v[1]), t1 = _mm256_unpackhi_ps(v[0], v[1]);
  const __m256 t2 = _mm256_unpacklo_ps(v[2], v[3]), t3 = _mm256_unpackhi_ps(v[2], v[3]);
  _mm256_store_ps(out.red.data(), _mm256_shuffle_ps(t0, t2, 0x44));
  _mm256_store_ps(out.green.data(), _mm256_shuffle_ps(t0, t2, 0xee));
  _mm256_store_ps(out.blue.data(), _mm256_shuffle_ps(t1, t3, 0x44));
}

__m256 loadPair(const float* low, const float* high) {
  return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(low)), _mm_loadu_ps(high), 1);
}
#endif

void loadCorners(const Materials& m, const Footprints& place, Corners& out) {
#if defined(__AVX__)
  __m256 topLeft[4], topRight[4], bottomLeft[4], bottomRight[4];
  for (int i = 0; i < 4; ++i) {
    const float* top0 = texelAt(m, i, place.row0[i]);
    const float* top1 = texelAt(m, i + 4, place.row0[i + 4]);
    const float* bottom0 = texelAt(m, i, place.row1[i]);
    const float* bottom1 = texelAt(m, i + 4, place.row1[i + 4]);
    topLeft[i] = loadPair(top0, top1);
    topRight[i] = loadPair(top0 + 4, top1 + 4);
    bottomLeft[i] = loadPair(bottom0, bottom1);
    bottomRight[i] = loadPair(bottom0 + 4, bottom1 + 4);
  }
  storeTransposed(topLeft, out.topLeft);
  storeTransposed(topRight, out.topRight);
  storeTransposed(bottomLeft, out.bottomLeft);
  storeTransposed(bottomRight, out.bottomRight);
#elif defined(__SSE2__)
  for (int half = 0; half < kPacketSize; half += 4) {
    const float* top[4];
    const float* bottom[4];
    for (int i = 0; i < 4; ++i) {
      top[i] = texelAt(m, half + i, place.row0[half + i]);
      bottom[i] = texelAt(m, half + i, place.row1[half + i]);
    }
    storeTransposed(_mm_loadu_ps(top[0]), _mm_loadu_ps(top[1]), _mm_loadu_ps(top[2]),
                    _mm_loadu_ps(top[3]), half, out.topLeft);
    storeTransposed(_mm_loadu_ps(top[0] + 4), _mm_loadu_ps(top[1] + 4), _mm_loadu_ps(top[2] + 4),
                    _mm_loadu_ps(top[3] + 4), half, out.topRight);
    storeTransposed(_mm_loadu_ps(bottom[0]), _mm_loadu_ps(bottom[1]), _mm_loadu_ps(bottom[2]),
                    _mm_loadu_ps(bottom[3]), half, out.bottomLeft);
    storeTransposed(_mm_loadu_ps(bottom[0] + 4), _mm_loadu_ps(bottom[1] + 4),
                    _mm_loadu_ps(bottom[2] + 4), _mm_loadu_ps(bottom[3] + 4), half,
                    out.bottomRight);
  }
#else
  const auto put = [](const float* texel, int lane, CornerColours& corner) {
    corner.red[lane] = texel[0], corner.green[lane] = texel[1], corner.blue[lane] = texel[2];
  };
  for (int lane = 0; lane < kPacketSize; ++lane) {
    const float* top = texelAt(m, lane, place.row0[lane]);
    const float* bottom = texelAt(m, lane, place.row1[lane]);
    put(top, lane, out.topLeft), put(top + 4, lane, out.topRight);
    put(bottom, lane, out.bottomLeft), put(bottom + 4, lane, out.bottomRight);
  }
#endif
}

// One colour channel of the bilinear blend, as glm::mix does it (a (1 - f) + b f, in that
// order), over all lanes.
void blendChannel(const Lanes& a, const Lanes& b, const Lanes& c, const Lanes& d,
                  const Lanes& fx, const Lanes& fy, Lanes& out) {
  for (int lane = 0; lane < kPacketSize; ++lane) {
    const float top = a[lane] * (1.0f - fx[lane]) + b[lane] * fx[lane];
    const float bottom = c[lane] * (1.0f - fx[lane]) + d[lane] * fx[lane];
    out[lane] = top * (1.0f - fy[lane]) + bottom * fy[lane];
  }
}

// Texture::sample per lane: the inside footprints blended over all lanes at once, then the
// others through sampleWrapped (white untextured).
void sampleTextures(const Materials& m, const Footprints& place, Lanes& red, Lanes& green,
                    Lanes& blue) {
  Corners c;
  loadCorners(m, place, c);
  blendChannel(c.topLeft.red, c.topRight.red, c.bottomLeft.red, c.bottomRight.red, place.fx,
               place.fy, red);
  blendChannel(c.topLeft.green, c.topRight.green, c.bottomLeft.green, c.bottomRight.green,
               place.fx, place.fy, green);
  blendChannel(c.topLeft.blue, c.topRight.blue, c.bottomLeft.blue, c.bottomRight.blue, place.fx,
               place.fy, blue);
  int inside = 1;
  for (int lane = 0; lane < kPacketSize; ++lane) inside &= place.inside[lane];
  if (inside) return;
  for (int lane = 0; lane < kPacketSize; ++lane) {
    if (place.inside[lane]) continue;
    const glm::vec4 colour =
        m.texture[lane] ? m.texture[lane]->sampleWrapped({place.s[lane], place.t[lane]})
                        : glm::vec4(1.0f);
    red[lane] = colour.r, green[lane] = colour.g, blue[lane] = colour.b;
  }
}

}  // namespace

// Structure of arrays: gathers per lane (one record, the material, texels), the arithmetic over
// all 8 lanes without branches, which the compiler vectorises. The arithmetic follows glm's
// order of operations in Scene::baseColorAt and Texture::sample.
void shadeSurface(const EmbreeScene& scene, const PacketHits& hits, const glm::vec3* pointLight,
                  PacketColours& __restrict colours, SurfaceNormals& __restrict out) {
  const RTCHit8& hit = hits.rayhit.hit;
  // The hit flags as bytes (0 or 1), read as one word (traceStraight stores them so), which the
  // loops below read as numbers and vectorise.
  static_assert(sizeof(bool) == 1);
  std::array<std::uint8_t, kPacketSize> hitLane;
  std::memcpy(hitLane.data(), hits.hit.data(), sizeof hitLane);
  const Triangle* const triangles = scene.shadingTriangles();
  const Triangle* record[kPacketSize];
  for (int lane = 0; lane < kPacketSize; ++lane)  // branch-free: misses at silhouettes
    record[lane] = triangles + (hitLane[lane] ? scene.shadingTriangleIndex(hit.geomID[lane],
                                                                           hit.primID[lane])
                                              : 0);
  Fields g;
  transposeRecords(record, g);
  Materials m;
  gatherMaterials(scene, g.field[MATERIAL], m);
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
    const int texel = iy * m.texelsPerRow[lane] + ix;
    place.row0[lane] = place.inside[lane] ? texel : 0;
    place.row1[lane] = place.inside[lane] ? texel + m.texelsPerRow[lane] : 0;
  }
  alignas(32) Lanes red, green, blue;  // the texture's, 1 without one (factor x 1 = factor)
  if (m.textured) {
    sampleTextures(m, place, red, green, blue);
  } else {
    red.fill(1.0f), green.fill(1.0f), blue.fill(1.0f);
  }
  // The headlight: light from the eye along the ray, or from a point light at the hit's
  // distance, two-sided; lanes without a hit carry zeros through and come out black.
  const RTCRay8& ray = hits.rayhit.ray;
  alignas(32) Lanes lightScale;  // |n . d| -> |n . l| / |l| per lane, 1 along the ray
  lightScale.fill(1.0f);
  alignas(32) Lanes towardsX, towardsY, towardsZ;  // the light's direction at the hit
  for (int lane = 0; lane < kPacketSize; ++lane) {
    towardsX[lane] = ray.dir_x[lane], towardsY[lane] = ray.dir_y[lane];
    towardsZ[lane] = ray.dir_z[lane];
  }
  if (pointLight != nullptr) {
    for (int lane = 0; lane < kPacketSize; ++lane) {
      const float t = ray.tfar[lane];
      const float lx = ray.org_x[lane] + t * ray.dir_x[lane] - pointLight->x;
      const float ly = ray.org_y[lane] + t * ray.dir_y[lane] - pointLight->y;
      const float lz = ray.org_z[lane] + t * ray.dir_z[lane] - pointLight->z;
      const float lengthSquared = lx * lx + ly * ly + lz * lz;
      const bool nonzero = lengthSquared > 0.0f;
      const float inverse = 1.0f / std::sqrt(nonzero ? lengthSquared : 1.0f);
      towardsX[lane] = lx, towardsY[lane] = ly, towardsZ[lane] = lz;
      lightScale[lane] = nonzero ? inverse : 0.0f;
    }
  }
  for (int lane = 0; lane < kPacketSize; ++lane) {
    const float nx = out.nx[lane], ny = out.ny[lane], nz = out.nz[lane];
    const float lengthSquared = nx * nx + ny * ny + nz * nz;
    const float facing = nx * ray.dir_x[lane] + ny * ray.dir_y[lane] + nz * ray.dir_z[lane];
    const float lit = (nx * towardsX[lane] + ny * towardsY[lane] + nz * towardsZ[lane]) *
                      lightScale[lane];
    // 1 / |n|, 0 for a zero normal (a missed lane); computed unconditionally so that the loop
    // vectorises (the compiler may not speculate a division by zero).
    const bool nonzero = lengthSquared > 0.0f;
    const float root = std::sqrt(nonzero ? lengthSquared : 1.0f);
    const float inverse = 1.0f / root;
    const float inverseLength = nonzero ? inverse : 0.0f;
    // Two-sided: the normal turned towards the viewer, so files with either winding shade alike;
    // Lambert with the headlight is then |n . d| / |n|.
    out.towardsViewer[lane] = facing > 0.0f ? -inverseLength : inverseLength;
    const float lambert = std::abs(lit) * inverseLength;
    colours.red[lane] = m.factorRed[lane] * red[lane] * lambert;
    colours.green[lane] = m.factorGreen[lane] * green[lane] * lambert;
    colours.blue[lane] = m.factorBlue[lane] * blue[lane] * lambert;
  }
  for (int lane = 0; lane < kPacketSize; ++lane)
    colours.alpha[lane] = static_cast<float>(hitLane[lane]);
}

}  // namespace confvis::embree::CONFVIS_SIMD_NAMESPACE
