#include "confvis/engine/default_edge_length.hpp"

#include <algorithm>
#include <cmath>

namespace confvis {

double defaultEdgeLength(const std::vector<Wall>& walls, const glm::dvec3& reference) {
  constexpr double kCaveEdge = 0.2, kCaveDistance = 1.5;
  double h = kCaveEdge;
  for (const Wall& w : walls) {
    const double distance = std::abs(glm::dot(reference - w.lowerLeft, w.normal()));
    if (distance > 0) h = std::min(h, kCaveEdge * distance / kCaveDistance);
    h = std::min(h, std::min(w.widthMetres(), w.heightMetres()) / 4);
  }
  return h;
}

}  // namespace confvis
