#pragma once
// Whether a Newton flow is on its way to converging, judged from its error history: the display
// map gives up a graded mesh's direct spherical flow early when it is not (its fallback, the
// Euclidean route's hemisphere, converges in ~4 steps; display_map.cpp).
#include <cstddef>
#include <vector>

namespace confvis::detail {

// Max curvature errors after Newton steps 1, 2, ... of one flow. A flow that converges more than
// halves its error every three steps, from the start: quadratic convergence, after at most a
// step or two of crawling (measured on the graded templates at 30 degrees, 1/64: cave4, cave5 and
// cave6 fall 100x per step from step 1; cave3's source at 20 cm 0.42 -> 0.0061 in 3 steps and
// flat-wall's target, the slowest, 0.034 -> 0.011). The failing ones do not: cave3's target at 20
// and 10 cm falls 5 to 13 % in 3 steps (0.163 -> 0.141), its source at 10 cm halves at first but
// then crawls (0.029 -> 0.015 -> 0.015 ... at steps 4, 7, 12). So: not converging when, from the
// fourth step on, the error is above half the error three steps before (and well above any
// tolerance).
inline bool flowIsNotConverging(const std::vector<double>& errors) {
  constexpr std::size_t kWindow = 3;
  constexpr double kLeast = 0.5;    // the least fall over kWindow steps
  constexpr double kFloor = 1e-8;   // below this a flow is in its final, quadratic steps
  const std::size_t n = errors.size();
  return n > kWindow && errors[n - 1] > kFloor && errors[n - 1] > kLeast * errors[n - 1 - kWindow];
}

}  // namespace confvis::detail
