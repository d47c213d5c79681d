// Richardson extrapolation of a reference map (map_reference_extrapolation.hpp).
#include "confvis/conformal/map_reference_extrapolation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "confvis/base/error.hpp"
#include "display_test_configs.hpp"

namespace confvis {
namespace {

// A quantity with a pure C h^p error: extrapolating from h and h/2 gives its limit exactly, and
// the ratio of two successive changes gives p.
TEST(MapReferenceExtrapolation, RichardsonIsExactForAPurePowerError) {
  const Vec3d limit(0.3, -1.2, 2.0), c(0.7, 0.1, -0.4);
  for (double p : {1.0, 1.5, 2.0, 3.0}) {
    auto at = [&](double h) { return limit + std::pow(h, p) * c; };
    const Vec3d got = richardsonExtrapolate(at(0.2), at(0.1), p);
    EXPECT_LT(norm(got - limit), 1e-12) << p;
    const double change1 = norm(at(0.2) - at(0.1)), change2 = norm(at(0.1) - at(0.05));
    EXPECT_NEAR(richardsonOrder(change1, change2), p, 1e-9);
  }
  // With a next-order term D h^(p+1) the extrapolation's error is of that order, far below the
  // fine value's own: C h^2 + D h^3 at h = 0.1, p = 2: error D h^3 (1/8 - 1/4) / 3 ... exactly.
  const Vec3d d(1.0, 2.0, -1.0);
  auto at = [&](double h) { return limit + h * h * c + h * h * h * d; };
  const double h = 0.1;
  const Vec3d got = richardsonExtrapolate(at(h), at(h / 2), 2);
  const Vec3d expected = limit + (h * h * h / 8 + (h * h * h / 8 - h * h * h) / 3) * d;
  EXPECT_LT(norm(got - expected), 1e-14);
  EXPECT_LT(norm(got - limit), 0.2 * norm(at(h / 2) - limit));
}

DisplayMap mapAt(const DisplayConfig& config, double edge) {
  DisplayMapOptions options;
  options.edgeLength = edge;
  return computeDisplayMap(config, options);
}

// The front half of a box seen from its centre covers exactly the front hemisphere, the source:
// the true map is the identity. Measured with the identity as the test map, the error against the
// extrapolated reference is the extrapolation's own, and must be well below the finest level's.
// The levels are evaluated with Möbius blending: a piecewise-linear evaluation adds an error that
// oscillates with where a point sits in its triangle (h^2 f(x/h), not C(x) h^2), which
// extrapolation does not remove (linear levels here: p50 0.010 extrapolated against 0.0037).
TEST(MapReferenceExtrapolation, ExtrapolatedReferenceBeatsItsFinestLevelOnTheFrontHemisphere) {
  const DisplayConfig config = testing::frontHemisphereDisplay();
  std::vector<DisplayMap> maps;
  for (double edge : {0.4, 0.2, 0.1}) maps.push_back(mapAt(config, edge));
  std::vector<std::unique_ptr<DisplayMapEvaluator>> evaluators;
  std::vector<const DisplayMapEvaluator*> levels;
  for (const DisplayMap& map : maps) {
    evaluators.push_back(std::make_unique<DisplayMapEvaluator>(map, MapInterpolation::Mobius));
    levels.push_back(evaluators.back().get());
  }
  DisplayMap identity;
  identity.source = maps.back().target;
  identity.target = maps.back().target;
  const DisplayMapEvaluator exact(identity);

  const ReferenceConvergence convergence = measureReferenceConvergence(config, levels, 32);
  ASSERT_EQ(convergence.changes.size(), 2u);
  EXPECT_LT(convergence.changes[1].p50, convergence.changes[0].p50);
  // Piecewise-linear maps on uniform meshes: second order away from the corners.
  EXPECT_GT(convergence.orderP50, 1.5);
  EXPECT_LT(convergence.orderP50, 2.6);

  const double order = convergence.orderP50;
  const ExtrapolatedMapError three = measureMapErrorExtrapolated(config, exact, levels, order, 32);
  const ExtrapolatedMapError two = measureMapErrorExtrapolated(
      config, exact, std::span(levels).subspan(1), order, 32);
  EXPECT_GT(three.finest.p50, 1e-3);  // a real error to remove
  EXPECT_LT(three.error.p50, 0.2 * three.finest.p50);  // measured: 0.05x
  EXPECT_LT(three.error.p95, 0.3 * three.finest.p95);  // measured: 0.07x
  EXPECT_EQ(two.error.p50, three.error.p50);  // the same two last levels
  // The reported uncertainties bound the extrapolation's real error (in the bulk).
  EXPECT_LE(three.error.p50, three.uncertainty.p50);
  EXPECT_LE(three.error.p95, three.uncertainty.p95);
  EXPECT_LE(two.error.p50, two.uncertainty.p50);
  // A wrong order (here: assuming first order) over-corrects and is worse.
  const ExtrapolatedMapError wrong = measureMapErrorExtrapolated(config, exact, levels, 1.0, 32);
  EXPECT_GT(wrong.error.p50, 1.5 * three.error.p50);

  // Per sample (the bench's --worst): the same samples and worst values as the summary, and each
  // sample's own level changes, which fall at about the displays' order in the bulk.
  const auto samples = extrapolatedErrorSamples(config, exact, levels, order, 32);
  ASSERT_EQ(samples.size(), three.error.samples);
  double worst = 0, worstFinest = 0;
  std::vector<double> localOrders;
  for (const ExtrapolatedSample& x : samples) {
    worst = std::max(worst, x.error);
    worstFinest = std::max(worstFinest, x.finestError);
    ASSERT_EQ(x.changes.size(), 2u);
    if (x.changes[1] > 0) localOrders.push_back(richardsonOrder(x.changes[0], x.changes[1]));
  }
  EXPECT_EQ(worst, three.error.max);
  EXPECT_EQ(worstFinest, three.finest.max);
  std::nth_element(localOrders.begin(), localOrders.begin() + localOrders.size() / 2,
                   localOrders.end());
  EXPECT_NEAR(localOrders[localOrders.size() / 2], convergence.orderP50, 0.5);
}

TEST(MapReferenceExtrapolation, RefusesTooFewLevelsAndABadOrder) {
  const DisplayConfig config = testing::frontHemisphereDisplay();
  const DisplayMap map = mapAt(config, 0.4);
  const DisplayMapEvaluator eval(map);
  const DisplayMapEvaluator* one[] = {&eval};
  const DisplayMapEvaluator* pair[] = {&eval, &eval};
  EXPECT_THROW(measureMapErrorExtrapolated(config, eval, one, 2, 8), Error);
  EXPECT_THROW(measureMapErrorExtrapolated(config, eval, pair, 0, 8), Error);
  EXPECT_THROW(measureReferenceConvergence(config, one, 8), Error);
}

}  // namespace
}  // namespace confvis
