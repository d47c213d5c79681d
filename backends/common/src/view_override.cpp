#include "confvis/backends/view_override.hpp"

#include <algorithm>
#include <cmath>

#include "confvis/backends/render_plan.hpp"
#include "confvis/base/error.hpp"

namespace confvis {

const ViewOverride* findViewOverride(const std::vector<ViewOverride>& views,
                                     const std::string& wall, Eye eye) {
  for (const ViewOverride& v : views)
    if (v.wall == wall && v.eye == eye) return &v;
  return nullptr;
}

glm::dmat4 withReverseDepth(const glm::dmat4& projection, double near) {
  glm::dmat4 p = projection;  // column-major: p[column][row]
  for (int column = 0; column < 4; ++column) p[column][2] = 0.0;
  p[3][2] = near;
  return p;
}

glm::dvec3 overrideEyePosition(const ViewOverride& view) {
  return glm::dvec3(glm::inverse(view.view)[3]);
}

OverrideRays overrideRays(const ViewOverride& view, double width, double height, double depth) {
  // With depth row (0, 0, 0, 1), clip (x, y, 1, 1) is the eye-space point at z = -1 that
  // projects to NDC (x, y): affine in x and y, so three points give every direction.
  const glm::dmat4 unproject = glm::inverse(withReverseDepth(view.projection, 1.0) * view.view);
  OverrideRays rays;
  rays.eye = overrideEyePosition(view);
  const auto direction = [&](double px, double py) {
    const glm::dvec4 p = unproject * glm::dvec4(2.0 * px / width - 1.0, 2.0 * py / height - 1.0,
                                                1.0, 1.0);
    return depth * (glm::dvec3(p) / p.w - rays.eye);
  };
  rays.base = direction(0.0, 0.0);
  rays.stepX = direction(1.0, 0.0) - rays.base;
  rays.stepY = direction(0.0, 1.0) - rays.base;
  return rays;
}

void checkViewOverrides(const std::vector<ViewOverride>& views,
                        const std::vector<std::string>& knownWalls) {
  for (std::size_t i = 0; i < views.size(); ++i) {
    const ViewOverride& v = views[i];
    const std::string culprit =
        "view override of wall '" + v.wall + "' (" + eyeName(v.eye) + " eye): ";
    if (std::find(knownWalls.begin(), knownWalls.end(), v.wall) == knownWalls.end())
      throw Error(ErrorCode::InvalidInput, culprit + "the display has no such wall");
    for (std::size_t j = 0; j < i; ++j)
      if (views[j].wall == v.wall && views[j].eye == v.eye)
        throw Error(ErrorCode::InvalidInput, culprit + "given twice");
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        if (!std::isfinite(v.view[c][r]) || !std::isfinite(v.projection[c][r]))
          throw Error(ErrorCode::InvalidInput, culprit + "a matrix entry is not finite");
    if (v.view[0][3] != 0.0 || v.view[1][3] != 0.0 || v.view[2][3] != 0.0 || v.view[3][3] != 1.0 ||
        !(std::abs(glm::determinant(glm::dmat3(v.view))) > 1e-12))
      throw Error(ErrorCode::InvalidInput,
                  culprit + "the view is not an invertible affine transform");
    if (!(std::abs(glm::determinant(withReverseDepth(v.projection, 1.0))) > 1e-12))
      throw Error(ErrorCode::InvalidInput,
                  culprit + "the projection's x, y and w rows are degenerate (no ray per pixel)");
  }
}

}  // namespace confvis
