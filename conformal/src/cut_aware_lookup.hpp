#pragma once
// Bilinear lookups that keep to one side of a jump in a direction cube map: the source's cut in
// `geom` (two sides of the cut land on different stretches of the display's rim). A plain bilinear
// blend of a footprint that straddles the cut lands between the two sides, in the middle of a wall.
#include <algorithm>
#include <optional>

#include "confvis/base/cube_map.hpp"
#include "confvis/base/vec3.hpp"
#include "confvis/conformal/retarget_map.hpp"

namespace confvis::detail {

struct OneSidedSample {
  Vec3d direction{0.0};           // unit
  float alpha = 0;           // blended over the footprint texels on this side
  bool straddles = false;    // the footprint spans a jump (else: the plain bilinear lookup)
  double footprintSpread = 0;  // largest angle between the blended values (this side's), radians
};

// A side of the 2x2 footprint block spans a jump where it is longer than `jumpChord` (lengths
// are chords between unit directions) and than three times the block's shortest side (a
// conformal map keeps the block nearly square, also where it magnifies without bound next to a
// display corner). The texels joined to the side's anchor by the other block sides are this
// side: side 0 is anchored at the nearest footprint texel, side 1 at the heaviest texel off side
// 0 (nullopt where the footprint spans no jump). A texel on the other side is replaced by a
// linear extrapolation from this side (the parallelogram of three footprint corners, or the line
// through a footprint corner and the texel beyond it), so a point between the cut and its side's
// last texel centre continues that side's map instead of clamping to it; one that cannot be
// extrapolated drops out of the blend. Throws like sampleBilinear.
std::optional<OneSidedSample> sampleOneSide(const CubeMap& map, const Vec3d& dir, int side,
                                            double jumpChord);

// The jump threshold of the map lookups and measurements, as a chord of unit directions: eight
// neighbour spacings at the centre of a face (2 / n each), as confvis_warp.glsl's.
inline double jumpChord(int faceSize) { return std::min(16.0 / faceSize, 1.5); }

// RetargetMap::toPhysical's lookup: geom on the side of the cut that v lies on. Within a texel of
// the cut the nearest texel can sit across it: the side whose physical direction ray takes back
// to v (and finds on the display) wins.
OneSidedSample lookupGeomAcrossCut(const RetargetMap& map, const Vec3d& virtualDir);

}  // namespace confvis::detail
