#pragma once
// A physical display: planar rectangular walls around a reference point c (design note §2).
// Frame: metres, right-handed, +y up, -z forward. A wall is given by three corners as seen by a
// viewer standing at c and looking at it (lower-left, lower-right, upper-left), the SGCT /
// ParaView .pvx / VR Juggler convention; the upper-right corner is implied.
//
// JSON schema (also in configs/README.md); unknown keys are errors at every level:
//   {
//     "name": "cave5",                          required, non-empty string
//     "reference": [0, 0, 0],                   optional, default [0,0,0]
//     "source": {"field": "sphere",             optional: "sphere" (default) | "hemisphere"
//                "axis": [0, 0, -1]},           optional, hemisphere centre direction
//     "edge_length": 0.2,                       optional, metres, > 0
//     "cube_resolution": 256,                   optional, texels per face, 8..8192
//     "stereo": {"eye_separation": 0.064},      optional, metres, >= 0
//     "tracking": {...},                        optional, the head tracker (tracking_config.hpp)
//     "edge_blend": {"gamma": 2.2},             optional: blend ramps where projector walls
//                                               overlap (display_surfaces.hpp)
//     "walls": [{                               required, at least one
//       "name": "front",                        required, unique
//       "lower_left": [x,y,z], "lower_right": [x,y,z], "upper_left": [x,y,z],   required
//       "resolution": [width, height],          required, pixels of the lit area
//       "bezel": {"left": 0, "right": 0, "bottom": 0, "top": 0}   optional, metres
//       "node": "render-3" | 3                  optional: the cluster host or rank that draws it
//       "preview": true                         optional: a window showing part of the display
//                                               again (a master's preview), no display surface
//       "window": {...}, "stereo_output": "mono"   optional, live display (display_output.hpp)
//     }]
//   }
#include <filesystem>
#include <array>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "confvis/base/export.hpp"
#include "confvis/engine/tracking_config.hpp"
#include "confvis/engine/display_output.hpp"

namespace confvis CONFVIS_API {

// Unlit frame inside a wall rectangle, metres from each edge. The wall's pixels cover only the
// lit area, so a tiled wall is modelled by rectangles that share edges, with bezels inside them.
struct Bezel {
  double left = 0, right = 0, bottom = 0, top = 0;
};

// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct Wall {
  std::string name;
  glm::dvec3 lowerLeft{0.0}, lowerRight{0.0}, upperLeft{0.0};
  int width = 0, height = 0;  // pixels of the lit area
  Bezel bezel;
  WallOutput output;  // where its pixels go on a live display; not part of the hash
  std::string node;  // cluster host name or rank number that draws this wall; empty: any. Not
                     // part of the hash
  // A window that shows part of the display again (an operator's preview spanning the projector
  // walls it covers): rendered like any wall, but no display surface of its own, so the map and
  // the edge blend ignore it. It must lie inside the walls it repeats (display_surfaces.hpp).
  bool preview = false;

  glm::dvec3 upperRight() const;
  // Lower-left, lower-right, upper-right, upper-left: counter-clockwise seen from the front.
  std::array<glm::dvec3, 4> corners() const;
  glm::dvec3 right() const;   // unit, lower-left -> lower-right
  glm::dvec3 up() const;      // unit, lower-left -> upper-left
  glm::dvec3 normal() const;  // unit, right x up: points to the viewer's side
  double widthMetres() const;
  double heightMetres() const;
  // s along right(), t along up(), both in [0,1] over this rectangle.
  glm::dvec3 pointAt(double s, double t) const;
  // Centre of pixel (x, y) of this rectangle, image convention: row 0 at the top. Pixels span the
  // lit area, so for a wall with bezels call litRectangle().pixelCenter(...).
  glm::dvec3 pixelCenter(int x, int y) const;
  // The wall shrunk by its bezels, same name and resolution, zero bezel.
  Wall litRectangle() const;
};

enum class SourceField { FullSphere, Hemisphere };

// Edge blending of overlapping projector walls (display_surfaces.hpp, edge_blend.hpp): in an
// overlap each projector's light ramps down linearly towards its own edge so the projectors' light
// sums to one projector's; the ramp is applied to the pixel signal as weight^(1/gamma), gamma
// being the projectors' response (signal^gamma = light).
struct EdgeBlend {
  bool enabled = false;
  double gamma = 2.2;
};

// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct DisplayConfig {
  std::string name;
  std::vector<Wall> walls;
  glm::dvec3 reference{0.0};
  SourceField source = SourceField::FullSphere;
  glm::dvec3 hemisphereAxis{0.0, 0.0, -1.0};  // unit
  double edgeLength = 0.20;                  // template refinement threshold, metres
  int cubeResolution = 256;                  // baked cube-map face size, texels
  double eyeSeparation = 0.064;              // metres
  TrackingConfig tracking;                   // live head tracker; not part of the hash
  EdgeBlend edgeBlend;                       // not part of the hash (it changes no map)
  // Hex FNV-1a 64 of toJson(*this).dump() without "tracking", "edge_blend" and the walls' outputs
  // and nodes: identifies a display for caches of baked maps (none of those change a map).
  std::string hash;

  // Throws Error(InvalidInput) naming the unknown wall and listing the known ones.
  const Wall& wall(const std::string& wallName) const;
};

// Reads and validates a config; Error(FileNotFound) naming the path if it cannot be read,
// Error(InvalidInput) naming the file and the culprit (wall, key) for any invalid content.
// SGCT configs (JSON, XML) and ParaView .pvx files load too, imported with default options
// (display_import.hpp).
DisplayConfig loadDisplayConfig(const std::filesystem::path& path);

// Validates `json`; sourceName (usually the file name) prefixes every error message.
DisplayConfig parseDisplayConfig(const nlohmann::json& json, const std::string& sourceName);

// Canonical form: every field written out, defaults included, so equal displays dump equally.
nlohmann::json toJson(const DisplayConfig& config);

}  // namespace confvis
