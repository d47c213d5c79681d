#pragma once
// Writing a render to a directory, the same for every backend:
//   WALL.exr        one per wall, named after it; a stereo pair as one OpenEXR multi-view file
//                   (views "left" and "right"), a single eye as an ordinary RGBA file (half);
//                   other eye combinations get the eye in the name (WALL-center.exr, ...)
//   WALL.png        8-bit sRGB preview beside each EXR (stereo: left | right side by side)
//   overview.png    every wall unfolded (overviewImage), centre or left eye
//   render.json     settings, timings, rays per second, the files written
// Every file is written atomically.
#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "confvis/backends/render_backend.hpp"
#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

// Returns the report written to render.json: `extra` (e.g. the CLI's scene and timing entries)
// merged over the entries this function fills in. Throws Error naming a file that cannot be
// written, or Error(InvalidInput) for an empty result.
nlohmann::json writeRenderOutput(const std::filesystem::path& directory,
                                 const DisplayConfig& config, const RenderSettings& settings,
                                 const RenderResult& result,
                                 const nlohmann::json& extra = nlohmann::json::object());

// All walls of one eye in one picture. A CAVE-like display (every wall facing the reference
// point along a different axis) is unfolded into the vertical cross of the dissertation's
// Fig. 8.6, one square cell per cube face, each wall turned to keep the cross's edges
// continuous:       [ceiling]
//             [left][front][right]
//                   [floor]
//                   [back]          (upside down, continuing below the floor)
// Other displays (tiled walls) are laid out as seen from the reference point: columns by
// azimuth, rows by elevation. Walls without an image of `eye` are left empty; cells without a
// wall are transparent black.
ImageRGBA overviewImage(const DisplayConfig& config, const std::vector<WallImage>& images,
                        Eye eye);

}  // namespace confvis
