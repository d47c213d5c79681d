#pragma once
// The files of a baked display: what `confvis bake -o DIR` writes, and what each cache entry
// holds (bake_display.hpp).
//   ray.exr, geom.exr     the RetargetMap: float32 OpenEXR cube environment maps (EXR layout,
//                         confvis/base/cube_map.hpp; convert with toVulkanLayout for upload)
//   bake.json             the sidecar: format version, config hash and effective config,
//                         reference point, resolution, mesh sizes, timings per stage (with
//                         DisplayMap.stats), quality of the baked map, sizes of the other files
//   source.obj, target.obj  the sphere meshes, disk coordinates as `vt`
//   ray.png, geom.png     cube-cross previews of the stored directions, RGB = (d + 1) / 2
//   ray-checker.png, geom-checker.png   a checkerboard cube seen through each map
//   source-disk.png, target-disk.png    the aligned disks with the checkerboard (Fig. 8.2)
// Every file is written atomically, bake.json last: a directory whose bake.json lists files of
// other sizes or checksums, or whose EXRs do not read back at the recorded resolution, is corrupt.
#include <filesystem>

#include <nlohmann/json.hpp>

#include "confvis/base/export.hpp"
#include "confvis/conformal/bake.hpp"
#include "confvis/conformal/display_map.hpp"
#include "confvis/conformal/retarget_map.hpp"

namespace confvis CONFVIS_API {

struct DisplayConfig;

inline constexpr const char* kBakeFormat = "confvis-bake";
// 2: round trips split at the cut; 3: measured across it; 4: aligned at the forward direction,
// checked; 5: "files" holds each file's bytes and FNV-1a 64 checksum
// ({"ray.exr": {"bytes": N, "fnv1a64": "..."}}). Older cache entries are stale.
inline constexpr int kBakeFormatVersion = 5;

// The sidecar for a fresh bake of `config` (the effective config, overrides applied). Measures
// the baked map's quality (baked_map_quality.hpp) on every `qualityStride`-th texel; 0 picks a
// stride that keeps about 128 x 128 samples per face.
nlohmann::json makeBakeSidecar(const DisplayConfig& config, const DisplayMap& displayMap,
                               const RetargetMap& map, const BakeTimings& timings,
                               int qualityStride = 0, bool showProgress = false);

// Writes every file into `directory` (created if missing), bake.json last with the sizes of the
// others added under "files"; returns what it wrote to bake.json. Throws Error(IoFailure)
// naming the file that failed.
nlohmann::json writeBakeDirectory(const std::filesystem::path& directory, const DisplayMap& displayMap,
                        const RetargetMap& map, nlohmann::json sidecar, int threads = 0,
                        bool showProgress = false);

// A map directory without the meshes and previews: ray.exr, geom.exr and a bake.json with the
// map's reference point, resolution and the two files' sizes and checksums (no config, quality
// or timings). For maps made otherwise than by a bake (tests, analytic maps); `confvis render
// --map` reads it like a bake directory. Returns what it wrote to bake.json.
nlohmann::json writeRetargetMapDirectory(const std::filesystem::path& directory,
                                         const RetargetMap& map);

struct LoadedBake {
  RetargetMap map;
  nlohmann::json sidecar;
};

// Reads a bake directory back. Throws Error(FileNotFound) if bake.json is missing and
// Error(IoFailure) naming the directory and the culprit if it is corrupt or partial: unreadable
// sidecar, other format version, a listed file missing or of another size or checksum, an EXR that does not
// read back at the recorded resolution or holds non-finite texels.
LoadedBake loadBakeDirectory(const std::filesystem::path& directory);

// Copies the files of a bake directory (each atomically, bake.json last).
void copyBakeDirectory(const std::filesystem::path& from, const std::filesystem::path& to);

}  // namespace confvis
