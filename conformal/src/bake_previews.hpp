#pragma once
// PNG previews of a bake, for people (the EXR files are what programs read):
//  - a disk map: the unit disk with each mesh triangle coloured by the checkerboard of its sphere
//    point and the mesh edges drawn thin, like the dissertation's Fig. 8.2 (B, D); the two disks
//    of a DisplayMap are aligned, so equal disk points are corresponding directions;
//  - a cube map's contents: stored directions as colours, and the checkerboard seen through the
//    map (what a checkerboard sphere around the viewer looks like on the display, Fig. 8.6).
#include "confvis/base/cube_map.hpp"
#include "confvis/base/image.hpp"
#include "confvis/conformal/display_map.hpp"

namespace confvis::detail {

// The 6-sided CAVE's colour code of Fig. 8.6 (red left/right, green top/bottom, blue front/back)
// with an 8 x 8 checkerboard on each cube face, linear RGB.
Vec3d checkerColour(const Vec3d& direction);

// size x size image of the unit disk (+imaginary up); outside the mesh's disk transparent.
// Unlit triangles are drawn darker.
ImageRGBA diskPreview(const SphereDiskMesh& mesh, int size);

// RGB = (direction + 1) / 2; texels with alpha 0 (extension past the boundary) at a quarter.
CubeMap directionPreview(const CubeMap& map);
// RGB = checkerColour(stored direction); texels with alpha 0 at a quarter.
CubeMap checkerPreview(const CubeMap& map);

}  // namespace confvis::detail
