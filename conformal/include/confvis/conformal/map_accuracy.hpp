#pragma once
// How accurate and how smooth a display map is (issue 22, points 2, 3 and 7), measured on the
// map itself before baking (design note §3 steps 6-7: the piecewise-linear map between the two
// chord-triangle meshes through their disks, exactly as the bake evaluates it per texel):
//
// - Map error against a reference (a converged map of the same display): for points p on the
//   walls' lit rectangles, the test map shows virtual direction v = T_ray(p) at p; the reference
//   shows v at the wall point along T_geom_ref(v). The distance between the two, in pixels of the
//   wall p lies on, is how far the content moves on the wall (the reference map is inverted,
//   angles are not scaled).
// - Kinks: a straight virtual line (a great-circle arc) is drawn on the display along the curve
//   T_geom(v(s)); where v(s) crosses an element boundary (an edge of the source mesh or of the
//   target mesh's pull-back) the curve's tangent turns. The turn angle, measured on the sphere of
//   physical directions from one-sided differences at the crossing, is 0 for a smooth map.
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "confvis/base/export.hpp"
#include "confvis/base/vec3.hpp"
#include "confvis/conformal/display_map.hpp"
#include "confvis/conformal/map_interpolation.hpp"
#include "confvis/engine/display_config.hpp"

namespace confvis CONFVIS_API {

namespace detail CONFVIS_API {
class SphereLocator;
class DiskLocator;
class MobiusBlend;
}  // namespace detail

// Evaluates T_ray and T_geom of a DisplayMap by point location (no cube maps). Keeps references
// into `map`, which must outlive it.
// Thread-safety: toVirtual and toPhysical are const and keep no state: call them from any
// number of threads at once.
class DisplayMapEvaluator {
 public:
  struct Image {
    Vec3d direction{0.0};
    int domainTriangle = -1, codomainTriangle = -1;  // the element: which triangle of each mesh
  };
  explicit DisplayMapEvaluator(const DisplayMap& map,
                               MapInterpolation interpolation = kDefaultMapInterpolation);
  ~DisplayMapEvaluator();
  DisplayMapEvaluator(const DisplayMapEvaluator&) = delete;
  DisplayMapEvaluator& operator=(const DisplayMapEvaluator&) = delete;

  // Physical direction -> virtual; nullopt where d is not on the display (target mesh).
  std::optional<Image> toVirtual(const Vec3d& physical) const;
  // Virtual direction -> physical; nullopt where v is outside the source field.
  std::optional<Image> toPhysical(const Vec3d& virtualDir) const;

 private:
  std::optional<Image> evaluate(const Vec3d& d, bool ray) const;
  const DisplayMap& map_;
  std::unique_ptr<detail::SphereLocator> sourceSphere_, targetSphere_;
  std::unique_ptr<detail::DiskLocator> sourceDisk_, targetDisk_;
  std::unique_ptr<detail::MobiusBlend> sourceBlend_, targetBlend_;  // null: linear
};

// The display's singular corners, where the map behaves like a power of the distance: target
// boundary vertices whose angle on the sphere differs from a straight boundary (π) by more than
// `minTurn` radians (cave5: the four top corners, 4π/3), and T_geom's images of such source
// boundary vertices (cave5: the cut leaves, at those corners, and the four copies of the cut's
// centre, π/2 each). Physical unit directions, without repeats.
std::vector<Vec3d> singularCorners(const DisplayMap& map, double minTurn = 0.2);

struct ErrorPercentiles {
  std::size_t samples = 0;
  double p50 = 0, p95 = 0, p99 = 0, max = 0;
};

struct MapError : ErrorPercentiles {  // pixels of the wall each sample lies on
  std::string worstWall;
  double worstS = 0, worstT = 0;  // where on that wall's lit rectangle (0..1)
};

// samplesPerSide^2 points per wall, at cell centres of its lit rectangle. Both maps must be of
// `config` (same reference point).
// `testInterpolation` and `referenceInterpolation` say how each map is evaluated.
MapError measureMapError(const DisplayConfig& config, const DisplayMap& test,
                         const DisplayMap& reference, int samplesPerSide = 96, int threads = 0,
                         MapInterpolation testInterpolation = kDefaultMapInterpolation,
                         MapInterpolation referenceInterpolation = kDefaultMapInterpolation);

struct KinkStats : ErrorPercentiles {  // degrees, per element-boundary crossing
  std::size_t lines = 0;
};

// A virtual great-circle arc: through `point` along `tangent` (unit, orthogonal to point),
// from -half to +half radians.
struct VirtualLine {
  Vec3d point{0.0}, tangent{0.0};
};

// The turn (degrees) of T_geom's image of each line at every element-boundary crossing, from
// one-sided differences at the crossing found by bisection; marched in steps of `step` radians.
// Crossings within `excludeDegrees` of a direction of `excluded` (physical) and jumps across the
// source's cut are left out.
std::vector<double> kinkTurns(const DisplayMapEvaluator& map, const std::vector<VirtualLine>& lines,
                              double half, double step, const std::vector<Vec3d>& excluded,
                              double excludeDegrees, int threads = 0);

// Virtual great-circle arcs of `arcDegrees` through T_ray of linesPerSide^2 points per wall, two
// directions each, marched in steps of `stepDegrees`; crossings within `excludeDegrees` of a
// singular corner, and jumps across the source's cut, are left out.
KinkStats measureKinks(const DisplayConfig& config, const DisplayMap& map, int linesPerSide = 10,
                       double arcDegrees = 10, double stepDegrees = 0.01,
                       double excludeDegrees = 3, int threads = 0,
                       MapInterpolation interpolation = kDefaultMapInterpolation);

}  // namespace confvis
