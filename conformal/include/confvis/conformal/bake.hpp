#pragma once
// Baking a DisplayMap into the two direction cube maps of a RetargetMap (design note §3 step 7).
//
// ray texel d (physical direction): d is located in the target sphere mesh by rasterising its
// triangles into the cube map (exact coverage, the triangles being the flat chords between
// their unit-vector corners); its barycentric coordinates give the disk point z; z is located in
// the source disk; the source triangle's barycentric coordinates give the virtual direction,
// normalised. alpha = 1 on lit target triangles, 0 on bezels and outside the display.
// geom texel v: the same the other way round; alpha = 1 where v lies in the source field.
//
// The two maps are exact inverses of each other as piecewise-linear maps (a point's barycentric
// coordinates survive the round trip), so baked maps differ from their inverse only by texel
// interpolation. Where one disk polygon pokes out of the other (both are inscribed in the unit
// circle with different boundary vertices) the point is clamped to the nearest boundary point.
//
// Texels outside the covered region are filled by extending the map past its boundary: the first
// ring by linear extrapolation from the two nearest covered texels along a face row or column,
// the rest with the value of the nearest filled texel (breadth-first over the cube's texel grid,
// across face edges). So bilinear lookups next to the boundary stay accurate and no texel is
// ever NaN. Runs on `threads` threads.
#include "confvis/base/export.hpp"
#include "confvis/conformal/display_map.hpp"
#include "confvis/conformal/map_interpolation.hpp"
#include "confvis/conformal/retarget_map.hpp"

namespace confvis CONFVIS_API {

struct BakeOptions {
  glm::dvec3 reference{};  // the reference point stored in the map (DisplayMap is relative to it)
  int threads = 0;    // 0: one per hardware thread
  bool showProgress = false;
  // Between the mesh vertices: linear per chord triangle, or Möbius blending (smooth).
  MapInterpolation interpolation = kDefaultMapInterpolation;
};

struct BakeTimings {  // seconds
  double locators = 0;  // point-location structures of both disks
  double ray = 0;       // rasterising the target and evaluating T_ray
  double geom = 0;      // rasterising the source and evaluating T_geom
  double extend = 0;    // filling uncovered texels past the boundary
  double total = 0;
};

// Throws Error(InvalidInput) naming the mesh ("source"/"target") and the culprit for malformed
// input (sizes, indices, non-unit or non-finite vertices, disk points outside the unit disk, no
// triangles) and for a resolution outside 1..8192.
RetargetMap bakeRetargetMap(const DisplayMap& map, int resolution, const BakeOptions& options = {},
                            BakeTimings* timings = nullptr);
// The same bake into `out`, reusing its cube maps' storage when they already have `resolution`
// texels per face (every texel is rewritten): a tracked head re-bakes without allocating and
// first-touching 2 x 6 N^2 RGBA floats each time. The result equals bakeRetargetMap's.
void bakeRetargetMapInto(const DisplayMap& map, int resolution, const BakeOptions& options,
                         RetargetMap& out, BakeTimings* timings = nullptr);

// The mesh checks of bakeRetargetMap, also used before writing a DisplayMap to files.
void validateDisplayMap(const DisplayMap& map);

}  // namespace confvis
