#pragma once
// Display surfaces: what the conformal map sees of a display whose windows overlap, as the
// projectors of a projection wall do (SGCT clusters with edge-blend zones).
//
// A wall of a config is a window: it renders its own pixels. Most displays have one window per
// surface (walls meet at most along edges). Projectors that overlap on one plane (edge-blend
// zones) are several windows on one surface: coplanar walls with parallel sides whose interiors
// overlap form one surface, the rectangle their union fills (a union that is not a rectangle
// is an error naming the walls). A preview wall (Wall::preview, an operator's window spanning
// the projectors it shows again) belongs to no surface: it must lie inside one. The map's
// target template is built from the surfaces, never from the overlapping walls themselves.
//
// Edge blending (DisplayConfig::edgeBlend): in an overlap each projector's light weight falls
// linearly towards its own edges that lie inside the surface (edges on the surface's outline
// never fade): w_i = d_i / sum_j d_j, d_i the distance from the point to projector i's nearest
// inner edge, so the weights of the projectors covering a point sum to 1. The signal a projector
// is fed is scaled by w_i^(1/gamma) (its light is signal^gamma), edgeBlendSignal's mask.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "confvis/base/export.hpp"
#include "confvis/engine/display_config.hpp"

namespace confvis CONFVIS_API {

struct DisplaySurface {
  Wall rectangle;          // a lone wall as it is; a group: the union, named "a+b+...", no bezel
  std::vector<int> walls;  // indices into config.walls, in config order; never a preview
};

// The surfaces of a validated config, in the order of their first walls.
std::vector<DisplaySurface> displaySurfaces(const DisplayConfig& config);

// The config with its walls replaced by its surfaces' rectangles (name, hash and everything
// else kept): what the map's templates are built from. Unchanged when no walls overlap and none
// is a preview.
DisplayConfig surfaceConfig(const DisplayConfig& config);

// Light weight of config.walls[wall] at physical point `point` on its plane: 1 outside any
// overlap (and for previews, or without other walls on the surface), falling linearly across an
// overlap to 0 at the wall's inner edge; 0 outside the wall.
double edgeBlendWeight(const DisplayConfig& config, const std::vector<DisplaySurface>& surfaces,
                       int wall, const glm::dvec3& point);

// Per pixel of a width x height image of config.walls[wall] (row 0 at the top; the wall's
// resolution, or a scaled one), the factor its signal is scaled by: edgeBlendWeight^(1/gamma) at
// the pixel centre. Empty when the wall needs none (blending off, a preview, a wall that
// overlaps no other).
std::vector<float> edgeBlendSignal(const DisplayConfig& config, int wall, int width, int height);

namespace detail CONFVIS_API {
// Whether `inner` lies on the plane of `outer`, within its outline (the preview test).
bool wallCovers(const Wall& outer, const Wall& inner);

// The validation behind displaySurfaces: every error is Error(InvalidInput) prefixed with
// sourceName and naming the walls (overlaps off one plane, a union that is no rectangle, a
// wall covering another without being marked a preview, a preview outside every surface).
std::vector<DisplaySurface> groupSurfaces(const DisplayConfig& config,
                                          const std::string& sourceName);
}  // namespace detail

}  // namespace confvis
