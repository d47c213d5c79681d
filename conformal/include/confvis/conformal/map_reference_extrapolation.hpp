#pragma once
// Richardson extrapolation of a reference map from its refinement levels (issue 22, point 2).
//
// A reference map refined by halving its edges converges slowly where the display is singular,
// so the error of a good map against the finest affordable level is partly the level's own. The
// measured quantity per sample (measureMapError: where the reference shows the test map's virtual
// direction on the wall) is extrapolated from the last two levels R_h, R_h/2 assuming an error
// C h^p: R = R_h/2 + (R_h/2 - R_h) / (2^p - 1). p is estimated per display from three levels,
// log2 of the ratio of two successive changes (at their p50/p95/p99). The extrapolated value's
// uncertainty per sample is |R(levels 1,2) - R(levels 2,3)| with three levels (the next order's
// term, an upper bound when that order exceeds 1), else the correction itself,
// |R_h/2 - R_h| / (2^p - 1). Evaluate the levels with Möbius blending: a piecewise-linear
// evaluation's error oscillates with a point's place in its triangle (h^2 f(x/h), not C(x) h^2)
// and is not removed by extrapolating.
#include <span>
#include <vector>

#include "confvis/base/export.hpp"
#include "confvis/base/vec3.hpp"
#include "confvis/conformal/map_accuracy.hpp"

namespace confvis CONFVIS_API {

// The limit of a quantity known at h (coarse) and h/2 (fine) whose error is C h^order.
Vec3d richardsonExtrapolate(const Vec3d& coarse, const Vec3d& fine, double order);
// The order from two successive changes (h -> h/2, then h/2 -> h/4): log2(coarse / fine).
double richardsonOrder(double coarseChange, double fineChange);

struct ReferenceConvergence {
  std::vector<ErrorPercentiles> changes;  // level k -> k+1, pixels of the wall
  // From the last two changes (three levels or more; 0 otherwise), at these percentiles.
  double orderP50 = 0, orderP95 = 0, orderP99 = 0;
};

// The levels' changes at the virtual directions the finest level shows at samplesPerSide^2
// points per wall. `levels`: one reference route at edge lengths halving level to level, coarse
// first, all of `config`.
ReferenceConvergence measureReferenceConvergence(
    const DisplayConfig& config, std::span<const DisplayMapEvaluator* const> levels,
    int samplesPerSide = 96, int threads = 0);

struct ExtrapolatedMapError {
  MapError error;               // against the extrapolated reference
  ErrorPercentiles uncertainty;  // of the extrapolated reference, per sample
  MapError finest;              // against the finest level alone
};

// measureMapError against the reference extrapolated from `levels` (at least two, as above)
// with `order`. Samples where any level shows nothing are left out.
ExtrapolatedMapError measureMapErrorExtrapolated(
    const DisplayConfig& config, const DisplayMapEvaluator& test,
    std::span<const DisplayMapEvaluator* const> levels, double order, int samplesPerSide = 96,
    int threads = 0);

// One sample of measureMapErrorExtrapolated, to find where the worst lie and what the levels do
// there (a local order from successive changes).
struct ExtrapolatedSample {
  int wall = 0;
  double s = 0, t = 0;  // on the wall's lit rectangle
  Vec3d point{0.0};     // on the wall
  double error = 0, finestError = 0, uncertainty = 0;  // pixels
  std::vector<double> changes;  // level k -> k+1, pixels
};
std::vector<ExtrapolatedSample> extrapolatedErrorSamples(
    const DisplayConfig& config, const DisplayMapEvaluator& test,
    std::span<const DisplayMapEvaluator* const> levels, double order, int samplesPerSide = 96,
    int threads = 0);

}  // namespace confvis
