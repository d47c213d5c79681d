#pragma once
// Geometric validation of a parsed display (private to confvis_engine). Every check throws one
// Error(InvalidInput) prefixed with `sourceName` and naming the wall(s) at fault.
#include <string>

#include "confvis/engine/display_config.hpp"

namespace confvis::detail {

// Tolerances in metres: configs are hand-written to millimetres, so 1 µm is "zero".
inline constexpr double kLengthTolerance = 1e-6;
// Relative tolerance of the right angle between a wall's sides (|cos| of the corner angle).
inline constexpr double kRightAngleTolerance = 1e-6;
// Corners and the reference point lie within this many metres of the origin on every axis: a
// display larger than 10 km is a typo (or millimetres), and would hang the mesh builders.
inline constexpr double kMaxCoordinateMetres = 1e4;

// Side lengths, right angle, bezels leaving a lit area.
void checkWallShape(const Wall& wall, const std::string& sourceName);

// Reference point in front of every wall plane (this is also the hull test: c inside the
// intersection of the walls' front half-spaces), never on a plane.
void checkFacesReference(const Wall& wall, const glm::dvec3& reference,
                         const std::string& sourceName);

// True when the relative interiors of the two rectangles intersect, i.e. the walls overlap in
// more than a shared edge or corner (T-junctions, where one wall's edge touches the other's
// face, count as touching, not overlapping).
bool wallsOverlap(const Wall& a, const Wall& b);

// Duplicate names, then overlaps: walls may overlap only as projectors on one plane do, forming
// one display surface (display_surfaces.hpp).
void checkWallSet(const DisplayConfig& config, const std::string& sourceName);

}  // namespace confvis::detail
