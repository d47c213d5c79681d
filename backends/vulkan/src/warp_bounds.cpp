// Per-wall warp bounds, navigation, projections and headlights: shared by the backend's frame
// plan and applications' own warp pipelines (byo_frame.hpp).
#include <algorithm>
#include <cmath>

#include "confvis/backends/vulkan/byo_frame.hpp"
#include "confvis/base/error.hpp"
#include "confvis/engine/view.hpp"
#include "error_walls.hpp"
#include "frame_plan.hpp"

namespace confvis::vulkan {
namespace {

// Smallest angle a pixel of `wall` (lit area, w x h output pixels) subtends at c.
double smallestPixelAngle(const Wall& wall, std::uint32_t w, std::uint32_t h,
                          const glm::dvec3& c) {
  const Wall lit = wall.litRectangle();
  const double pitch = std::min(lit.widthMetres() / w, lit.heightMetres() / h);
  const double perpendicular = std::abs(glm::dot(lit.normal(), lit.lowerLeft - c));
  double farthest = 0.0;
  for (const glm::dvec3& corner :
       {lit.lowerLeft, lit.lowerRight, lit.upperLeft, lit.upperRight()})
    farthest = std::max(farthest, glm::length(corner - c));
  // A pixel at distance D, seen at obliquity cos = perpendicular / D, spans pitch * cos / D.
  return std::max(pitch * perpendicular / (farthest * farthest), 1e-9);
}

}  // namespace

WallWarpBounds wallWarpBounds(const Wall& wall, std::uint32_t width, std::uint32_t height,
                              const glm::dvec3& warpCentre, const WarpTolerances& tolerances) {
  if (width == 0 || height == 0)
    throw Error(ErrorCode::InvalidInput,
                "wall '" + wall.name + "': warp bounds need a rendered size of at least 1 pixel");
  WallWarpBounds bounds;
  bounds.pixelAngle = smallestPixelAngle(wall, width, height, warpCentre);
  bounds.errorAngle = tolerances.errorPixels * bounds.pixelAngle;
  bounds.maxSegmentAngle = glm::radians(tolerances.maxSegmentDegrees);
  bounds.cutGapAngle = 4.0 * bounds.pixelAngle;
  return bounds;
}

// A bend of e radians seen from c, in direction d at obliquity cos to the wall (distance D of
// its plane), moves the drawn point by about e D / cos^2 on the wall, so errorPixels pixels of
// pitch p tolerate e = errorPixels p / D cos^2 (the smallest pixel angle alone is up to three
// times stricter at a CAVE wall's centre than at its corners).
ErrorWall errorWall(const Wall& wall, std::uint32_t w, std::uint32_t h, const glm::dvec3& c,
                    double errorPixels) {
  const Wall lit = wall.litRectangle();
  const double pitch = std::min(lit.widthMetres() / w, lit.heightMetres() / h);
  glm::dvec3 normal = lit.normal();
  double distance = glm::dot(normal, c - lit.lowerLeft);
  if (distance < 0.0) {
    normal = -normal;
    distance = -distance;
  }
  ErrorWall e;
  e.lowerLeft = glm::vec4(glm::vec3(lit.lowerLeft - c),
                          static_cast<float>(errorPixels * pitch / std::max(distance, 1e-9)));
  e.right = glm::vec4(glm::vec3(lit.right()), static_cast<float>(lit.widthMetres()));
  e.up = glm::vec4(glm::vec3(lit.up()), static_cast<float>(lit.heightMetres()));
  e.normal = glm::vec4(glm::vec3(normal), static_cast<float>(distance));
  return e;
}

glm::dmat4 worldToPhysical(const DisplayConfig& config, const VirtualCamera& camera) {
  // The inverse of p -> position + R (p - c).
  const glm::dmat3 rt = glm::transpose(camera.rotation());
  glm::dmat4 transform(rt);
  transform[3] = glm::dvec4(config.reference - rt * camera.position, 1.0);
  return transform;
}

glm::dmat4 wallViewProjection(const Wall& wall, const glm::dvec3& eye) {
  const WallView view = makeWallView(wall, eye);  // throws if the eye cannot see the wall
  // Reverse-Z without a far plane, the near plane a tiny fraction of the wall's distance: float
  // depth resolves the same relative distances in a scene of millimetres or of kilometres, and
  // clips nothing that the ray tracer (rays from t = 0) would show.
  return view.projectionVulkanReverseZ(kNearFractionOfWallDistance * view.nearDistance) *
         view.view;
}

}  // namespace confvis::vulkan
