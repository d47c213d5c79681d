// The bake of real display configs through computeDisplayMap: the closed forms of the issue
// (6-sided CAVE and a front-hemisphere display give the identity) and the 5-sided CAVE's
// conformality, orientation, round trip and coverage, measured on the baked cube maps.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "confvis/conformal/bake.hpp"
#include "confvis/conformal/baked_map_quality.hpp"
#include "confvis/conformal/display_map.hpp"
#include "confvis/engine/display_config.hpp"

namespace confvis {
namespace {

DisplayConfig shipped(const std::string& name) {
  return loadDisplayConfig(std::filesystem::path(CONFVIS_SOURCE_DIR) / "configs" / name);
}

RetargetMap bake(const DisplayConfig& config, int resolution) {
  BakeOptions options;
  options.reference = {config.reference.x, config.reference.y, config.reference.z};
  return bakeRetargetMap(computeDisplayMap(config), resolution, options);
}

// Largest angle between each valid texel's stored direction and its own direction, in texels;
// also counts the valid texels.
double worstIdentityError(const CubeMap& map, std::size_t& valid) {
  const int n = map.faceSize;
  double worst = 0;
  valid = 0;
  for (CubeFace face : kCubeFaces)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const float* p = map.face(face).at(x, y);
        if (p[3] < 0.5f) continue;
        ++valid;
        worst = std::max(worst, angleBetween(Vec3d{p[0], p[1], p[2]}, texelDirection(face, x, y, n)));
      }
  return worst / texelAngle(n);
}

TEST(BakePipeline, SixSidedCaveGivesTheIdentity) {
  const int n = 64;
  const RetargetMap map = bake(shipped("cave6.json"), n);
  std::size_t rayValid = 0, geomValid = 0;
  const double ray = worstIdentityError(map.ray, rayValid);
  const double geom = worstIdentityError(map.geom, geomValid);
  std::printf("cave6 identity: max error ray %.4f, geom %.4f texels\n", ray, geom);
  EXPECT_LT(ray, 1.0);
  EXPECT_LT(geom, 1.0);
  EXPECT_GT(rayValid, 0.99 * 6 * n * n);  // the whole sphere is lit
  EXPECT_GT(geomValid, 0.99 * 6 * n * n);
}

TEST(BakePipeline, FrontHemisphereDisplayWithHemisphereSourceGivesTheIdentity) {
  // The front wall and the front halves of the four walls around it: the display covers
  // exactly the directions with z < 0, the hemisphere source's field. Source and target are
  // different meshes, so the map is the identity up to discretisation: below a texel at 10 cm
  // edges, and converging (the largest error sits at the axis, in the disk maps' removed face).
  auto wall = [](const char* name, std::array<double, 3> ll, std::array<double, 3> lr,
                 std::array<double, 3> ul) {
    return nlohmann::json{{"name", name}, {"lower_left", ll}, {"lower_right", lr},
                          {"upper_left", ul}, {"resolution", {1000, 1000}}};
  };
  const nlohmann::json json = {
      {"name", "front-hemisphere"},
      {"source", {{"field", "hemisphere"}, {"axis", {0, 0, -1}}}},
      {"walls",
       {wall("front", {-1, -1, -1}, {1, -1, -1}, {-1, 1, -1}),
        wall("left", {-1, -1, 0}, {-1, -1, -1}, {-1, 1, 0}),
        wall("right", {1, -1, -1}, {1, -1, 0}, {1, 1, -1}),
        wall("floor", {-1, -1, 0}, {1, -1, 0}, {-1, -1, -1}),
        wall("ceiling", {-1, 1, -1}, {1, 1, -1}, {-1, 1, 0})}}};
  DisplayConfig config = parseDisplayConfig(json, "front-hemisphere");
  const int n = 64;
  double previous = 1e9;
  for (double edge : {0.2, 0.1}) {
    config.edgeLength = edge;
    const RetargetMap map = bake(config, n);
    std::size_t rayValid = 0, geomValid = 0;
    const double ray = worstIdentityError(map.ray, rayValid);
    const double geom = worstIdentityError(map.geom, geomValid);
    std::printf("front hemisphere at %.2f m: max identity error ray %.4f, geom %.4f texels\n",
                edge, ray, geom);
    // The spherical route maps both meshes onto the same hemisphere: exact to float rounding
    // (1e-6 texels) at every edge length, else shrinking under refinement.
    EXPECT_LT(ray, std::max(0.7 * previous, 1e-4));
    previous = ray;
    EXPECT_NEAR(static_cast<double>(rayValid) / (6 * n * n), 0.5, 0.01);
    EXPECT_NEAR(static_cast<double>(geomValid) / (6 * n * n), 0.5, 0.01);
    if (edge < 0.15) {
      EXPECT_LT(ray, 1.0);
      EXPECT_LT(geom, 1.0);
    }
  }
}

TEST(BakePipeline, FiveSidedCaveIsConformalOrientedInvertibleAndCovering) {
  const int n = 128;
  const RetargetMap map = bake(shipped("cave5.json"), n);
  const BakedConformality ray = measureBakedConformality(map.ray);
  const BakedConformality geom = measureBakedConformality(map.geom);
  const RoundTripStats forth = measureRoundTrip(map, RoundTrip::RayThenGeom);
  const RoundTripStats back = measureRoundTrip(map, RoundTrip::GeomThenRay);
  const CoverageStats coverage = measureCoverage(map);
  std::printf("cave5 ray conformality %s\ncave5 geom conformality %s\n",
              toJson(ray).dump().c_str(), toJson(geom).dump().c_str());
  std::printf("cave5 round trips %s / %s\ncave5 coverage %s\n", toJson(forth).dump().c_str(),
              toJson(back).dump().c_str(), toJson(coverage).dump().c_str());
  // Orientation everywhere; conformal up to the 20 cm mesh's discretisation (p95 falls from
  // 1.25 to 1.08 to 1.02 at 20, 10, 5 cm; the largest ratios sit at the cut's branch points).
  EXPECT_EQ(ray.flipped, 0u);
  EXPECT_EQ(geom.flipped, 0u);
  EXPECT_GT(ray.measured, 0.7 * 6 * n * n);
  EXPECT_LT(ray.ratioP50, 1.05);
  EXPECT_LT(ray.ratioP95, 1.3);
  EXPECT_LT(geom.ratioP95, 1.3);
  // Inverses: every interior texel below one texel. Within two texels of the cut or the rim:
  // toPhysical keeps to a side of the cut (a bilinear blend of both sides lands mid-wall, up to
  // 30 texels off at 256: 62% of this band below one texel), and ray's lookups at the rim are only
  // as fine as ray's own texels, which span several of geom's there (the ceiling squeezed into
  // the walls' top edges).
  for (const RoundTripStats* trip : {&forth, &back}) {
    EXPECT_GT(trip->interior.measured, 0.9 * static_cast<double>(trip->all.valid()));
    EXPECT_EQ(trip->interior.acrossCut + trip->interior.invalid, 0u);
    EXPECT_LT(trip->interior.max, 1.0);
    EXPECT_LT(static_cast<double>(trip->boundary.valid()),
              0.03 * static_cast<double>(trip->all.valid()));
    EXPECT_EQ(trip->all.invalid, 0u);
  }
  EXPECT_GT(forth.boundary.acrossCut, 0u);
  EXPECT_GT(forth.boundary.fractionBelowOneTexel, 0.95);
  // Wrong sides: where the cut passes between v and its nearest texel and both sides land within
  // ray's resolution of the rim (next to the cut's ends, where the two sides meet).
  EXPECT_LT(forth.all.beyondFootprint, forth.boundary.valid() / 50);
  EXPECT_GT(back.boundary.fractionBelowOneTexel, 0.85);
  EXPECT_EQ(back.all.acrossCut, 0u);  // ray has no cut: its magnification at the rim is no jump
  EXPECT_LT(back.all.maxInFootprints, 1.0);
  // The image of ray covers the source.
  EXPECT_GT(coverage.fraction, 0.99);
}

}  // namespace
}  // namespace confvis
