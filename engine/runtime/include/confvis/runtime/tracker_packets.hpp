#pragma once
// The two live tracking protocols confvis reads over UDP, parsed without sockets (so each rule
// is testable on its own). Parsers never throw: a packet is a pose or it is dropped.
//
// ART DTrack2 ASCII output, one frame per datagram, lines ending in CR LF (DTrack2 User Manual,
// Technical Appendix; the DTrackSDK parser reads the same):
//   fr 21753                                  frame counter
//   ts 39596.024831                           timestamp, seconds since midnight (UTC), optional
//   6dcal 2                                   calibrated bodies (ignored)
//   6d 2 [0 1.000][326.848 -187.216 1096.975 -143.0031 -33.8526 -109.6355][-0.221 ...]
//        [1 1.000][...][...]
// "6d N" is followed by N bodies, each three blocks: [id quality] (ids from 0, quality 0..1,
// negative: not tracked), [x y z] or [x y z eta theta phi] (millimetres; the angles are ignored,
// the matrix is authoritative), [b0 ... b8] the rotation matrix body -> room, column-wise
// (b0 b1 b2 is the body's x axis in room coordinates). Other lines (3d, 6df2, gl, ...) are
// ignored. The head body must be present and tracked, the matrix a rotation (orthonormal within
// 1e-3, determinant +1), every number finite.
//
// JSON lines, one pose per line, any number of lines per datagram (up to kMaxLinesPerDatagram):
//   {"t": 12.5, "pos": [x, y, z], "quat": [x, y, z, w]}
// "pos" in the tracker's unit (metres unless the config says "mm"), "quat" a unit quaternion
// (normalised; more than 10% off unit length is dropped), "t" optional seconds on the sender's
// clock (else the receive time). Unknown keys, wrong arity or types, non-finite numbers: dropped.
#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

// Bounds on the work one datagram can cause; beyond them it is dropped.
inline constexpr std::size_t kMaxDatagramBytes = 16384;
inline constexpr std::size_t kMaxLinesPerDatagram = 64;
inline constexpr std::size_t kMaxJsonLineBytes = 1024;

// A pose as the tracker measured it: its own frame and length unit.
struct RawTrackerPose {
  glm::dvec3 position{0.0};
  glm::dquat orientation{1.0, 0.0, 0.0, 0.0};
  std::optional<double> seconds;  // the sender's timestamp, when it sent one
};

// The head body's pose from one DTrack2 datagram; nullopt when the datagram is malformed or the
// head body is missing or untracked.
std::optional<RawTrackerPose> parseDTrackFrame(std::string_view datagram, int headBody);

// Every line of one JSON-lines datagram, in order: a pose, or nullopt for a dropped line. Blank
// lines are skipped; a datagram over kMaxLinesPerDatagram lines yields one nullopt.
std::vector<std::optional<RawTrackerPose>> parseJsonLines(std::string_view datagram);

// The rotation a column-wise 3x3 matrix represents; nullopt unless it is orthonormal within
// `tolerance` with determinant +1.
std::optional<glm::dquat> rotationFromColumns(const double (&columnWise)[9],
                                              double tolerance = 1e-3);

}  // namespace confvis
