#pragma once
// The refinement edge length a display gets when its config gives none ("edge_length" absent, as
// in every imported SGCT or ParaView file): small panels get small edges. The 20 cm that suits a
// 3 m CAVE seen from 1.5 m (7.6 degrees) is scaled down with the nearest wall's distance from the
// reference point, and no wall gets fewer than four edges across its shorter side:
//   min(0.2 m, 0.2 m * (nearest wall plane distance / 1.5 m), shortest wall side / 4).
// A 4-monitor desktop rig (0.53 m x 0.30 m panels at 0.65 m) gets 7.5 cm.
#include "confvis/base/export.hpp"
#include "confvis/engine/display_config.hpp"

namespace confvis CONFVIS_API {

double defaultEdgeLength(const std::vector<Wall>& walls, const glm::dvec3& reference);

}  // namespace confvis
