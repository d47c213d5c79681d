#pragma once
// How good a baked map is, measured on the cube maps alone (design note §6): conformality and
// orientation from finite differences of neighbouring texels on the sphere, the round trip
// through the inverse map, and whether the image of `ray` covers the source field. Used by the
// tests, by bake.json and by the benchmark. Angles are reported in texels: one texel is 2/N
// radians, the angular size of a texel at a face centre (the largest).
#include <cstddef>

#include <nlohmann/json_fwd.hpp>

#include "confvis/base/cube_map.hpp"
#include "confvis/base/export.hpp"
#include "confvis/conformal/retarget_map.hpp"

namespace confvis CONFVIS_API {

inline double texelAngle(int resolution) { return 2.0 / resolution; }

struct ConformalityOptions {
  int margin = 2;  // texels (4-neighbour steps, across faces) kept away from alpha < 0.5 texels
  // A texel whose forward and backward differences along x or y differ (as vectors) by more than
  // this fraction of their mean length straddles a discontinuity (the source cut, in geom) or a
  // kink too sharp to measure (the cut's ends, where the map has a branch point): skipped.
  double discontinuityTolerance = 0.5;
  int stride = 1;  // measure every stride-th texel along x and y
};

struct BakedConformality {
  std::size_t measured = 0;       // texels whose Jacobian was measured
  std::size_t nearBoundary = 0;   // valid texels skipped for the margin
  std::size_t discontinuous = 0;  // skipped as straddling a discontinuity
  std::size_t flipped = 0;        // measured texels where the map reverses orientation
  // Ratio of the Jacobian's singular values (1 = conformal) over the measured texels.
  double ratioMean = 1, ratioP50 = 1, ratioP95 = 1, ratioP99 = 1, ratioMax = 1;
};

// The Jacobian of d -> normalised RGB(d) at each texel, from central differences over its four
// neighbours (across face edges), as a map between the tangent planes of the unit sphere.
BakedConformality measureBakedConformality(const CubeMap& map,
                                           const ConformalityOptions& options = {});

// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct RoundTripErrors {
  std::size_t measured = 0;
  // Measured texels whose inverse lookup straddles a jump of the inverse map by more than
  // `discontinuityTexels` (the source cut, in geom): RetargetMap keeps to one side there.
  std::size_t acrossCut = 0;
  std::size_t invalid = 0;  // inverse lookup invalid (alpha < 0.5)
  double p50 = 0, p95 = 0, p99 = 0, max = 0;  // angle(inverse(forward(d)), d), texels
  // Of all valid texels (invalid ones counted as failures): error below one texel.
  double fractionBelowOneTexel = 0;
  // The error in units of the inverse lookup's own footprint: the largest angle between the
  // directions it blends (on its side of the cut), where that exceeds one texel. Where the
  // inverse map magnifies (the missing ceiling squeezed into the walls' top edges, in ray), one
  // of its texels spans several of the forward map's, and no lookup is finer than that.
  double maxInFootprints = 0;
  std::size_t beyondFootprint = 0;  // errors above max(1 texel, footprint)
  std::size_t valid() const { return measured + invalid; }
};

// The round trip over all valid texels, and split at the cut: a texel is on the boundary when it
// lies within `boundaryTexels` 4-neighbour steps of an edge of the forward map, or its image does
// of an edge of the inverse map. An edge is a texel with alpha < 0.5 (the display's rim) or one
// whose direction jumps by more than `discontinuityTexels` to a neighbour (the source cut).
struct RoundTripStats {
  int boundaryTexels = 2;
  RoundTripErrors all, interior, boundary;
};

enum class RoundTrip {
  RayThenGeom,  // d -> ray(d) -> toPhysical: errors in ray's texels
  GeomThenRay,  // v -> geom(v) -> toVirtual: errors in geom's texels
};

// For every texel of the forward map with alpha >= 0.5: its stored direction, looked up in the
// inverse map as RetargetMap::toPhysical / toVirtual do, compared with the texel's direction.
RoundTripStats measureRoundTrip(const RetargetMap& map, RoundTrip which, int stride = 1,
                                double discontinuityTexels = 8.0, int boundaryTexels = 2);

struct CoverageStats {
  std::size_t sourceTexels = 0;  // geom texels with alpha >= 0.5: directions v in S
  std::size_t covered = 0;       // v = ray(d) for the lit d = geom(v), within the tolerance
  std::size_t unlit = 0;         // geom(v) falls on an unlit part of the display (a bezel) or
                                 // within half a texel of its rim
  double fraction = 0;           // covered / sourceTexels
  double maxErrorTexels = 0;     // largest angle(ray(geom(v)), v) over lit v
};

// Whether the image of ray covers the source field: every v in S must be ray(d) for the lit
// display direction d = geom(v). The tolerance is `toleranceTexels`, or the spread of the
// directions ray's bilinear lookup at d blends where that is larger: where ray magnifies (the
// whole sphere shown on a few walls), one texel of the display spans several of the source,
// and no lookup can be closer than its own footprint.
CoverageStats measureCoverage(const RetargetMap& map, double toleranceTexels = 1.0, int stride = 1);

nlohmann::json toJson(const BakedConformality& stats);
nlohmann::json toJson(const RoundTripErrors& stats);
nlohmann::json toJson(const RoundTripStats& stats);
nlohmann::json toJson(const CoverageStats& stats);

}  // namespace confvis
