#pragma once
// The source and target templates of a display (design note §3 steps 1-2, dissertation 8.3.2-
// 8.3.3), refined and still in physical space (metres). display_map.hpp projects them to the
// sphere and maps them to the disk.
//
// Target D: the walls. Bezels are *covered but unlit*: they belong to D, so the map has no gap
// at a seam, and their triangles carry lit = 0 so the bake gives alpha 0 there (a texel on a
// bezel shows nothing rather than squeezing the picture around it). A wall without bezels is one
// fan from the projection of the reference point c onto it (the dissertation's "green sphere")
// where that falls well inside the wall, else from its centre. A wall with bezels is a grid of
// quads (sides up to the edge length) over its lit area plus four mitred bezel strips cut into
// quads at most four bezel widths long, every quad split by a diagonal: no triangle crosses a
// bezel border, and thin strips become right triangles with angles above 14 degrees, which the
// flow flattens without Delaunay flips (with flips, thin triangles can fold in the result). Walls are stitched where they touch (shared
// edges and T-junctions get common vertices); refinement then splits edges at mid-points.
//
// Source S, by source field and display:
// - hemisphere: half of a cube around c about source.axis (the front face and four half side
//   faces), sized like the display; its rim gets vertices at the azimuths of three target
//   boundary corners, the markers.
// - sphere, closed display (the 6-sided CAVE): D has no boundary, so both templates are D cut
//   along the same star (from the fan centre of the ceiling-most wall to its lit corners): the
//   two meshes are identical and the map is the identity.
// - sphere, box display (every wall lies on a face of the bounding box of the walls, each box
//   face fully covered or empty, c inside the box): S is the closed box, D plus the missing
//   faces; each missing face is a fan from the projection of c onto it, and the cut is the
//   dissertation's tree: from each missing face's projection point to its corners that belong to
//   no other missing face (where the uncovered region is convex), and between adjacent missing
//   faces (a spanning tree) through the point of their shared edge nearest c. With fewer than
//   three such corners, every missing-face corner on the display boundary joins the cut.
// - sphere, any other display (angled walls, partly covered box faces): S is D plus one cap over
//   the uncovered region around the direction q that sees the whole display boundary best (the
//   Chebyshev centre of the kernel of the uncovered region on the sphere): a polar grid of
//   spokes from q to the boundary (spaced at the edge length) and rings along them, built at its
//   final density on a sphere around c. The cut runs along the spokes to the boundary corners
//   where the cap is convex (else to all boundary corners). If no direction sees the whole
//   boundary (the uncovered region is not star-shaped) the display is rejected: use a
//   hemisphere source. Known limit: with bezels on the display outline, the outline's short
//   bezel pieces give this cap needle-shaped cells and the flow may fail (Error Unreachable);
//   box caps and hemisphere sources handle bezels.
// The cut leaves on the display boundary are the markers: each appears once on both templates'
// boundaries, and three of them spread along the boundary are sent to 1, i, -1.
#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "confvis/base/export.hpp"
#include "confvis/engine/display_config.hpp"

namespace confvis CONFVIS_API {

struct TemplateMesh {
  std::vector<glm::dvec3> points;             // metres, physical frame
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from the reference
  std::vector<std::uint8_t> lit;              // per triangle (target only; empty on the source)
  std::vector<int> boundary;                  // counter-clockwise boundary loop
};

enum class SourceKind { Hemisphere, Closed, Box, Cone };
const char* toString(SourceKind kind);

struct DisplayTemplates {
  TemplateMesh source, target;
  std::array<int, 3> sourceMarkers{};  // corresponding boundary vertices, counter-clockwise
  std::array<int, 3> targetMarkers{};
  SourceKind sourceKind = SourceKind::Hemisphere;
  // Cut tree nodes off the display boundary (projection points and joints), metres; empty for
  // hemisphere sources.
  std::vector<glm::dvec3> cutCentres;
  // Every cut leaf on the display boundary (the markers are three of them), metres.
  std::vector<glm::dvec3> cutLeaves;
};

// Throws Error(InvalidInput) naming the culprit when the visible region is not a topological
// disk (or a closed sphere for a sphere source), when walls hide or touch each other as seen from
// the reference point without sharing an edge, or when a sphere source cannot be cut (see above).
// edgeLength <= 0 takes config.edgeLength.
// Meshes graded toward the map's singular points (issue 22): within `radiusDegrees` (seen from
// the reference) of a cut leaf or a display boundary corner, where the map behaves like a power
// of the distance, the edge length falls as (angle / radius)^exponent, to at least minScale x
// the edge length. radiusDegrees <= 0: uniform edges.
struct TemplateGrading {
  double radiusDegrees = 0;
  double exponent = 0.75;
  double minScale = 1.0 / 16;
};

DisplayTemplates buildDisplayTemplates(const DisplayConfig& config, double edgeLength = 0.0,
                                       const TemplateGrading& grading = {});

// True exactly when the display's conformal map is the identity and needs no bake: a sphere
// source and a closed display (walls enclosing the reference point) without bezels. A closed
// display with bezels maps by the identity too, but its bezels are unlit (alpha 0), so it is
// baked. Throws like checkVisibleRegion for a malformed display.
bool displayMapIsIdentity(const DisplayConfig& config);

// The checks of the visible region alone (walls hiding each other, touching without sharing an
// edge, not forming a disk), as buildDisplayTemplates runs them.
void checkVisibleRegion(const DisplayConfig& config);

}  // namespace confvis
