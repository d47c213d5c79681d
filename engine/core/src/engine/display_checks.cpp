#include "display_checks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>

#include "confvis/base/error.hpp"
#include "confvis/engine/display_surfaces.hpp"

namespace confvis::detail {
namespace {

[[noreturn]] void failWall(const std::string& sourceName, const Wall& wall,
                           const std::string& what) {
  throw Error(ErrorCode::InvalidInput, sourceName + ": wall '" + wall.name + "' " + what);
}

std::string metres(double x) { return std::to_string(x) + " m"; }

// Open interval of line parameters lambda where base + lambda*dir lies strictly inside the
// rectangle (shrunk by the tolerance); empty when lo >= hi.
struct Interval {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool empty() const { return lo >= hi; }
};

// Restricts `interval` to tol < offset + slope*lambda < extent - tol.
void clip(Interval& interval, double offset, double slope, double extent) {
  const double lo = kLengthTolerance, hi = extent - kLengthTolerance;
  if (std::abs(slope) < 1e-12) {
    if (offset <= lo || offset >= hi) interval.lo = interval.hi = 0.0;
    return;
  }
  double a = (lo - offset) / slope, b = (hi - offset) / slope;
  if (a > b) std::swap(a, b);
  interval.lo = std::max(interval.lo, a);
  interval.hi = std::min(interval.hi, b);
}

Interval interiorAlongLine(const Wall& w, const glm::dvec3& base, const glm::dvec3& dir) {
  Interval interval;
  const glm::dvec3 r = w.right(), u = w.up();
  clip(interval, glm::dot(base - w.lowerLeft, r), glm::dot(dir, r), w.widthMetres());
  clip(interval, glm::dot(base - w.lowerLeft, u), glm::dot(dir, u), w.heightMetres());
  return interval;
}

// Coplanar rectangles: interiors are disjoint iff some side direction of either separates
// their projections (separating-axis theorem; touching projections count as separated).
bool coplanarInteriorsIntersect(const Wall& a, const Wall& b) {
  const std::array<glm::dvec3, 4> cornersA = a.corners(), cornersB = b.corners();
  for (const glm::dvec3& axis : {a.right(), a.up(), b.right(), b.up()}) {
    auto range = [&](const std::array<glm::dvec3, 4>& corners) {
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (const glm::dvec3& p : corners) {
        lo = std::min(lo, glm::dot(p, axis));
        hi = std::max(hi, glm::dot(p, axis));
      }
      return std::pair{lo, hi};
    };
    const auto [loA, hiA] = range(cornersA);
    const auto [loB, hiB] = range(cornersB);
    if (hiA <= loB + kLengthTolerance || hiB <= loA + kLengthTolerance) return false;
  }
  return true;
}

}  // namespace

void checkWallShape(const Wall& wall, const std::string& sourceName) {
  for (const glm::dvec3& corner : {wall.lowerLeft, wall.lowerRight, wall.upperLeft})
    for (int i = 0; i < 3; ++i)
      if (!(std::abs(corner[i]) <= kMaxCoordinateMetres))
        failWall(sourceName, wall, "has a corner coordinate of " + metres(corner[i]) +
                                       " (at most " + metres(kMaxCoordinateMetres) +
                                       " from the origin: a typo, not a display)");
  const double width = wall.widthMetres(), height = wall.heightMetres();
  if (width < kLengthTolerance)
    failWall(sourceName, wall, "is degenerate: lower_left and lower_right coincide (width " +
                                   metres(width) + ")");
  if (height < kLengthTolerance)
    failWall(sourceName, wall, "is degenerate: lower_left and upper_left coincide (height " +
                                   metres(height) + ")");
  const double cosine = glm::dot(wall.right(), wall.up());
  if (std::abs(cosine) > kRightAngleTolerance)
    failWall(sourceName, wall,
             "is not a rectangle: the sides at lower_left are not at a right angle (cos = " +
                 std::to_string(cosine) + ")");
  const Bezel& b = wall.bezel;
  if (b.left + b.right >= width - kLengthTolerance)
    failWall(sourceName, wall, "bezel leaves no lit area: left + right = " +
                                   metres(b.left + b.right) + " >= width " + metres(width));
  if (b.bottom + b.top >= height - kLengthTolerance)
    failWall(sourceName, wall, "bezel leaves no lit area: bottom + top = " +
                                   metres(b.bottom + b.top) + " >= height " + metres(height));
}

void checkFacesReference(const Wall& wall, const glm::dvec3& reference,
                         const std::string& sourceName) {
  const double distance = glm::dot(wall.normal(), reference - wall.lowerLeft);
  if (std::abs(distance) < kLengthTolerance)
    failWall(sourceName, wall, "contains the reference point in its plane");
  if (distance < 0.0)
    failWall(sourceName, wall,
             "faces away from the reference point (the reference is " + metres(-distance) +
                 " behind its plane, outside the display): corners must be lower_left, "
                 "lower_right, upper_left as seen from the reference");
}

bool wallsOverlap(const Wall& a, const Wall& b) {
  const glm::dvec3 na = a.normal(), nb = b.normal();
  const glm::dvec3 lineDir = glm::cross(na, nb);
  const double sinAngle = glm::length(lineDir);
  if (sinAngle < 1e-9) {  // parallel planes: overlap only if coplanar
    if (std::abs(glm::dot(na, b.lowerLeft - a.lowerLeft)) > kLengthTolerance) return false;
    return coplanarInteriorsIntersect(a, b);
  }
  // Transversal planes: the interiors meet iff their open intervals along the planes'
  // intersection line overlap (each interior crosses that line in an open segment).
  const double ha = glm::dot(na, a.lowerLeft), hb = glm::dot(nb, b.lowerLeft);
  const glm::dvec3 base =
      (ha * glm::cross(nb, lineDir) + hb * glm::cross(lineDir, na)) / (sinAngle * sinAngle);
  const glm::dvec3 dir = lineDir / sinAngle;
  const Interval ia = interiorAlongLine(a, base, dir), ib = interiorAlongLine(b, base, dir);
  if (ia.empty() || ib.empty()) return false;
  return std::min(ia.hi, ib.hi) - std::max(ia.lo, ib.lo) > kLengthTolerance;
}

void checkWallSet(const DisplayConfig& config, const std::string& sourceName) {
  std::set<std::string> names;
  for (const Wall& w : config.walls)
    if (!names.insert(w.name).second)
      throw Error(ErrorCode::InvalidInput,
                  sourceName + ": wall name '" + w.name + "' is used more than once");
  // Overlaps: allowed only between projectors of one plane, which form one display surface.
  groupSurfaces(config, sourceName);
}

}  // namespace confvis::detail
