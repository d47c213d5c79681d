#pragma once
// Internal to the backends (not part of the API): the SSE blend of one cell's four corners, four
// components at a time, shared by WallMapGrid::at's batched path and the Embree tail grid so both
// round alike (the tests compare their results bit for bit).
#if defined(__SSE2__)
#include <emmintrin.h>

namespace confvis::detail {

// mix(mix(n00, n00[right], tx), mix(n01, n01[right], tx), ty) as a (1 - t) + b t, where `n00`
// and `n01` point at the cell's lower corners in two rows and `right` is the float offset of
// each one's neighbour to the right.
inline __m128 blendCellCorners(const float* n00, const float* n01, int right, float tx, float ty) {
  const __m128 x = _mm_set1_ps(tx), y = _mm_set1_ps(ty);
  const __m128 kx = _mm_sub_ps(_mm_set1_ps(1.0f), x), ky = _mm_sub_ps(_mm_set1_ps(1.0f), y);
  const __m128 top = _mm_add_ps(_mm_mul_ps(_mm_loadu_ps(n00), kx),
                                _mm_mul_ps(_mm_loadu_ps(n00 + right), x));
  const __m128 bottom = _mm_add_ps(_mm_mul_ps(_mm_loadu_ps(n01), kx),
                                   _mm_mul_ps(_mm_loadu_ps(n01 + right), x));
  return _mm_add_ps(_mm_mul_ps(top, ky), _mm_mul_ps(bottom, y));
}

}  // namespace confvis::detail
#endif
