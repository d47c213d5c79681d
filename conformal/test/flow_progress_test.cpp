// The display map gives a graded mesh's direct spherical flow up early where it is not converging
// (flow_progress.hpp, issue 22), and only there.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../src/flow_progress.hpp"
#include "confvis/conformal/display_map.hpp"
#include "display_test_configs.hpp"

using namespace confvis;

namespace {

// Whether the rule gives the flow up at some step of `errors` (the errors after steps 1, 2, ...),
// and at which (1-based; 0: never).
int givenUpAt(const std::vector<double>& errors) {
  std::vector<double> seen;
  for (double e : errors) {
    seen.push_back(e);
    if (detail::flowIsNotConverging(seen)) return static_cast<int>(seen.size());
  }
  return 0;
}

}  // namespace

// Measured error histories (graded 30 degrees, 1/64). Converging: every one, the slow starts
// included; failing: given up well before the 12-step cap.
TEST(FlowProgress, GivesUpCrawlingFlowsAndNeverConvergingOnes) {
  // cave5's source at 10 cm: quadratic from the start.
  EXPECT_EQ(givenUpAt({9.443e-02, 7.897e-04, 1.213e-07, 1.310e-14}), 0);
  // cave3's source at 20 cm: two crawling steps, then quadratic.
  EXPECT_EQ(givenUpAt({4.206e-01, 2.951e-02, 6.343e-03, 6.136e-03, 2.124e-03, 2.951e-05,
                       1.164e-07, 1.164e-13}),
            0);
  // flat-wall's target at 10 cm: the slowest converging start measured.
  EXPECT_EQ(givenUpAt({3.449e-02, 3.162e-02, 8.340e-03, 1.089e-02, 6.881e-04, 1.174e-05,
                       2.135e-09, 1.910e-14}),
            0);
  // cave3's target at 10 cm: 1.6 % a step.
  EXPECT_EQ(givenUpAt({1.632e-01, 1.606e-01, 1.506e-01, 1.412e-01, 1.324e-01, 1.283e-01}), 4);
  // cave3's source at 10 cm: halves at first, then crawls at 0.015.
  EXPECT_EQ(givenUpAt({9.490e-02, 4.855e-02, 4.677e-02, 2.936e-02, 2.206e-02, 1.529e-02,
                       1.528e-02, 1.529e-02, 1.527e-02, 1.525e-02, 1.523e-02, 1.513e-02}),
            7);
  // Near the tolerance a flow is not judged (rounding can stall the last digits).
  EXPECT_EQ(givenUpAt({1e-9, 1e-9, 1e-9, 1e-9}), 0);
}

// In the display map: cave3's graded target (30 degrees, as the accurate preset) is given up and
// mapped spherically from the Euclidean route's hemisphere, as before; cave5's converges directly
// and is not.
TEST(FlowProgress, DisplayMapGivesUpOnlyTheFailingDirectFlow) {
  DisplayMapOptions options;
  options.edgeLength = 0.2;
  options.grading = {.radiusDegrees = 30, .minScale = 1.0 / 64};
  const DisplayMap cave3 = computeDisplayMap(confvis::testing::shipped("cave3"), options);
  EXPECT_EQ(cave3.stats["target"]["route"], "spherical");
  ASSERT_TRUE(cave3.stats["target"].contains("direct_spherical_flow")) << cave3.stats.dump();
  EXPECT_NE(cave3.stats["target"]["direct_spherical_flow"].get<std::string>().find(
                "not converging"),
            std::string::npos);
  EXPECT_EQ(cave3.stats["source"]["route"], "spherical");
  EXPECT_FALSE(cave3.stats["source"].contains("direct_spherical_flow"));  // converges in 8

  const DisplayMap cave5 = computeDisplayMap(confvis::testing::shipped("cave5"), options);
  for (const char* side : {"source", "target"}) {
    EXPECT_EQ(cave5.stats[side]["route"], "spherical");
    EXPECT_FALSE(cave5.stats[side].contains("direct_spherical_flow")) << side;
    EXPECT_LE(cave5.stats[side]["flow_iterations"].get<int>(), 4) << side;
  }
}
