#pragma once
// Private: how the source template closes or replaces the display (display_template.hpp).
#include <optional>
#include <utility>
#include <vector>

#include "confvis/conformal/display_template.hpp"
#include "display_template_parts.hpp"

namespace confvis::detail {

// Cells covering the uncovered region of a sphere source, with the cut tree (edges between
// template points) and its leaves on the display boundary.
struct SourceCap {
  SourceKind kind = SourceKind::Box;
  std::vector<FanCell> cells;
  std::vector<glm::dvec3> extraPoints;  // joints to insert into cell sides
  std::vector<std::pair<glm::dvec3, glm::dvec3>> cutEdges;
  std::vector<glm::dvec3> centres, leaves;
};

// The missing faces of a box display and the dissertation's cut tree; nullopt when the display
// is not a box with every face fully covered or empty (or is closed).
std::optional<SourceCap> boxCap(const DisplayConfig& config, const CoarseDisplay& display);

// One fan over the whole uncovered region from the direction that sees its boundary best;
// throws Error(InvalidInput) when no direction sees all of it.
SourceCap coneCap(const DisplayConfig& config, const CoarseDisplay& display);

// Boundary-loop vertices where the boundary turns on the sphere (reflexOnly: where the display's
// interior angle exceeds pi, i.e. the uncovered region is convex).
std::vector<int> boundaryCorners(const glm::dvec3& reference, const TemplateBuild& mesh,
                                 const std::vector<int>& loop, bool reflexOnly);

// The cut that opens a closed display: a star in the ceiling-most wall's lit area.
struct StarCut {
  glm::dvec3 centre{0.0};
  std::vector<glm::dvec3> leaves;
};
StarCut closedDisplayStar(const DisplayConfig& config, const CoarseDisplay& display);

// Half of a cube of half-size `radius` around the reference about the hemisphere axis, with rim
// points at the azimuths of `markerDirections`.
struct HalfCube {
  std::vector<FanCell> cells;
  std::vector<glm::dvec3> rimPoints;
};
HalfCube hemisphereHalfCube(const DisplayConfig& config, double radius,
                            const std::vector<glm::dvec3>& markerDirections);

}  // namespace confvis::detail
