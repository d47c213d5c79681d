#pragma once
// Camera rays of one wall seen by one eye, in virtual space (design note §5):
//   plain:      the ordinary off-axis ray from the eye e through the wall point p;
//   conformal:  the physical eye ray e + t (p - e) carried into virtual space by the warp W,
//     - centre eye (e = c): exactly the straight ray from c along F(dir(p));
//     - Exact:  the bent curve W(e + t (p - e)), marched as straight segments;
//     - Fast:   one straight ray from e towards W(p).
// Virtual space is the physical frame placed by the VirtualCamera: x -> position + R (x - c).
#include <array>

#include <glm/glm.hpp>

#include "affine_directions.hpp"
#include "confvis/backends/conformal_warp.hpp"
#include "confvis/backends/render_backend.hpp"
#include "confvis/engine/view.hpp"
#include "confvis/backends/wall_map_grid.hpp"

namespace confvis::embree {

class TailGrid;

inline constexpr int kMaxCurvedSegments = 32;
// Camera samples traced together (one rtcIntersect8 packet).
inline constexpr int kPacketSize = 8;

// The angle (seen from c) at which the curved ray hands over to its straight tail along F(u).
// The curve's distance from its asymptote there is about h * angle * |F''| / 2, with h = |e - c|
// perpendicular to the ray (at most half the eye separation): ~0.1 mm for a 64 mm baseline, and
// the tail starts within h / angle (8 m) of c, so that scenes keeping that far from the viewer
// trace every exact stereo ray as one straight ray. Against a dense polyline of the curve on
// the analytic dilation map (CurvedRayBound.*), 12 segments stay within 0.25 px of a 960-px
// CAVE wall.
inline constexpr double kAsymptoteAngle = 4e-3;

// A polyline followed by an unbounded straight tail: what one camera sample traces.
struct RayPath {
  int vertexCount = 1;  // segment k joins vertices[k] and vertices[k + 1]; then the tail
  std::array<glm::vec3, kMaxCurvedSegments + 2> vertices;
  glm::vec3 tail{0.0f, 0.0f, -1.0f};  // unit direction of the last segment, from the last vertex
  bool lit = true;                    // false: no display behind the pixel, the sample is black
};

// The bent virtual ray W(e + t u), t >= 0, as vertices (in the warped physical frame, before the
// camera placement) and the direction of its asymptote F(u). Samples are spaced geometrically
// in the angle the physical ray subtends at c, from the eye down to 1e-3 rad, where W bends
// most. Returns the number of vertices (1 when the ray points straight away from c, 2 when it
// passes through c). `segments` in 1..kMaxCurvedSegments.
// `emptyRadius`: no scene lies closer than this to c (W keeps distances to c, so in virtual space
// too). The leading segments inside that ball cannot hit anything and are left out: the curve
// starts at its last vertex inside the ball (and is then often just its straight tail), the hits
// stay those of the whole curve.
int curvedRay(const ConformalWarp& warp, const glm::dvec3& eye, const glm::dvec3& unitDirection,
              int segments, glm::dvec3* vertices, glm::dvec3& tail, double emptyRadius = 0.0);

class CameraRays {
 public:
  // Plain rays. `custom`: the application's view and projection (view_override.hpp) give the
  // rays instead of `view`, which must then be the off-axis view from the override's eye.
  CameraRays(const WallView& view, const VirtualCamera& camera, const glm::dvec3& reference,
             const ViewOverride* custom = nullptr);
  // Conformal rays; `warp` and `grid` (the map seen from this view's wall) must outlive this
  // object.
  CameraRays(const WallView& view, const VirtualCamera& camera, const ConformalWarp& warp,
             const WallMapGrid& grid, StereoRays stereoRays, int curvedSegments,
             const ViewOverride* custom = nullptr);

  // Exact stereo rays: no scene lies within `radius` of the warp's centre (clearance.hpp); the
  // curves' segments inside that ball are not traced.
  void setEmptyRadius(double radius) { emptyRadius_ = radius; }
  // The farthest any curve's vertex lies from the warp's centre (beyond, every ray is straight).
  double curvedReach() const;

  double emptyRadius() const { return emptyRadius_; }

  // Exact stereo rays: exactTails takes each tail as the curve's asymptote from `grid`
  // (tail_grid.hpp; built for this view's wall, must outlive this object) wherever the packet's
  // rays from c meet the grid; elsewhere, and for an override's rays, from the last vertex.
  void setTailGrid(const TailGrid* grid);
  const TailGrid* tailGrid() const { return tailGrid_; }

  // Per packet, in float, structure of arrays in a DirectionTable packet's layout, for `count`
  // (1..kPacketSize) samples at wall-pixel positions (px, py) (lanes from `count` on repeat a
  // valid position and are written as unlit). The per-sample rays and the tables both come from
  // these, so a table holds exactly what a frame without one computes. Unlit: zeros.
  //
  // Fast stereo rays: W(p) relative to the warp's centre, p the sample's wall point, at
  // [0, 3 kPacketSize): independent of the eye, so one table serves every head position (the
  // ray is from the eye towards W(p); packets turn it with targetShift()).
  void fastTargets(const float* px, const float* py, int count, float* run) const;
  // Exact stereo rays: the straight tail of the bent ray, its direction F(u) at [0, 3 kPacketSize)
  // and its start relative to the warp's centre at [3, 6 kPacketSize): the asymptote from the
  // tail grid where one is set (tailsAt), else W(last vertex) from the wall's grid (where the
  // ray from c along u, or the last vertex, misses the wall: the cube map), and per lane
  // `reach`, the farthest from c the curve bends (the eye's distance included; 0 where unlit,
  // infinite where the ray lies on a line through c and needs curvedPath). Where the scene
  // keeps beyond a lane's reach (setEmptyRadius), the tail alone is traced. Returns the largest
  // reach of the lit lanes.
  float exactTails(const float* px, const float* py, int count, float* run, float* reach) const;
  // exactTails' pieces, for TailLattice (tail_lattice.hpp), which interpolates the tails:
  // per lane, in closed form, the physical ray's unit direction u, the eye's distance h across
  // it, the last vertex (and its distance from c) and the unmasked reach.
  struct TailGeometry {
    alignas(32) std::array<float, kPacketSize> ux, uy, uz, h, lastX, lastY, lastZ, lastDistance,
        reach;
  };
  void tailGeometry(const float* px, const float* py, TailGeometry& geometry) const;
  // tailGeometry and the unmasked tails (exactTails' run layout, unlit lanes included) of 8
  // positions, `count` of them meaningful (the cube map is asked only for those).
  // With a tail grid (setTailGrid), the tails are the curves' asymptotes from it where every
  // lane's ray from c meets it (asymptoteTails).
  void tailsAt(const float* px, const float* py, int count, TailGeometry& geometry,
               float* tails) const;
  // tailsAt's tails from the tail grid: the asymptote c + M(v) w + s F(v), started on its line
  // as far from c as the curve reaches (`geometry`: tailGeometry's); false where a lane's ray
  // from c misses the grid (nothing written).
  bool asymptoteTails(const float* px, const float* py, int count, const TailGeometry& geometry,
                      float* tails) const;
  // The map's alpha at the samples' wall points (lanes from `count` on: 0).
  void pixelAlpha(const float* px, const float* py, int count, float* alpha) const;
  // exactTails' last step: `tails` into `run` where lit (alpha >= 0.5), zeros elsewhere; per
  // lane reach (0 where unlit); returns the largest.
  static float maskTails(const float* alpha, const float* laneReach, const float* tails,
                         float* run, float* reach);
  // The physical ray directions' affine form (unturned; base + px stepX + py stepY) and the eye
  // relative to c, in float.
  const glm::vec3& rayBase() const { return packet_.base; }
  const glm::vec3& rayStepX() const { return packet_.stepX; }
  const glm::vec3& rayStepY() const { return packet_.stepY; }
  const glm::vec3& eyeFromCentre() const { return packet_.eye; }
  // The wall's map grid (conformal cameras), whose alpha pixelAlpha reads (not an override's).
  const WallMapGrid* mapGrid() const { return grid_; }
  // The whole bent path of the sample at (px, py) (curvedRay, the segments inside the empty ball
  // left out), placed by the camera; lit.
  void curvedPath(double px, double py, RayPath& path) const;
  // What a packet subtracts from a run's vectors before turning them (fast stereo: the eye
  // relative to c, as runs hold W(p); others: zero).
  const glm::vec3& targetShift() const { return targetShift_; }
  // A point given relative to the warp's centre, placed by the camera (in float, as the table
  // packets do: camera position + rotation x offset).
  glm::vec3 placeOffset(const glm::vec3& offset) const { return placedCentre_ + rotationF_ * offset; }
  const glm::vec3& placedCentre() const { return placedCentre_; }

  // Straight cameras trace one unbounded ray per sample, from origin(): plain, conformal centre
  // eye and fast stereo rays (exact stereo rays bend).
  bool straight() const { return !warp_ || eyeAtReference_ || stereoRays_ == StereoRays::Fast; }
  const glm::vec3& origin() const { return placedEye_; }
  // Plain and conformal centre-eye cameras: the unit direction through (px, py); false where the
  // sample is unlit (fast stereo rays: fastTargets).
  bool straightDirection(double px, double py, glm::vec3& direction) const;
  bool plain() const { return !warp_; }
  // Plain cameras: the direction through (px, py) is affine in the position (evaluated in float).
  const AffineDirections& plainDirections() const { return plain_; }
  // Conformal centre eye only (centreEyeConformal()): the unit direction of a sample whose map
  // direction F (unnormalised) is already known, the direction straightDirection() gives.
  glm::vec3 centreDirection(const glm::vec3& mapDirection) const {
    return glm::normalize(rotationF_ * mapDirection);
  }
  // The virtual camera's rotation in float (centreDirection turns F with it).
  const glm::mat3& rotation() const { return rotationF_; }
  bool centreEyeConformal() const { return warp_ && eyeAtReference_; }
  // The rays are an override's: a pixel is not the wall's pixel at the same position (no
  // per-wall-pixel direction table).
  bool overridden() const { return custom_; }

 private:
  CameraRays(const WallView& view, const OverrideRays& rays, const VirtualCamera& camera,
             const glm::dvec3& reference);
  glm::vec3 place(const glm::dvec3& physicalPoint) const;
  // F(dir(fromC)) for kPacketSize vectors fromC (relative to c, in float), not normalised:
  // bilinear from this wall's map grid where the ray from c meets the wall (samples half a map
  // texel apart: within ~1e-5 rad of the cube map's lookup, at a fraction of its cost), from the
  // cube map where it meets the wall's plane outside the wall (lanes from `count` on: finite).
  void mapDirections(const float* x, const float* y, const float* z, int count, float* fx,
                     float* fy, float* fz) const;
  // mapSample for kPacketSize samples: F and alpha at each sample's wall point, and (where
  // `wallX` is given) the wall point relative to c. Lanes from `count` on get alpha 0.
  void pixelSamples(const float* px, const float* py, int count, float* fx, float* fy, float* fz,
                    float* alpha, float* wallX = nullptr, float* wallY = nullptr,
                    float* wallZ = nullptr) const;
  glm::vec3 turn(const glm::dvec3& physicalDirection) const;
  // The map at the wall point that the ray through (px, py) meets (`wallPoint`, physical
  // frame): the grid's sample of that wall pixel; for an override's ray that meets the wall's
  // plane outside the wall, or not at all, the map's exact lookup.
  WallMapGrid::Sample mapSample(double px, double py, glm::dvec3& wallPoint) const;

  WallView view_;
  // rayDirection is affine in the pixel position: base + px stepX + py stepY.
  glm::dvec3 directionBase_, directionStepX_, directionStepY_;
  glm::dvec3 reference_;
  glm::dvec3 cameraPosition_;
  glm::dmat3 rotation_;
  glm::vec3 placedEye_;
  glm::vec3 placedCentre_;  // the camera position: where the warp's centre is placed
  glm::mat3 rotationF_;
  // The same affine direction, turned by the camera, in float: plain rays need nothing else.
  AffineDirections plain_;
  // mapDirections' wall plane, from the view matrix (WallView::rayDirection): the wall's right,
  // up and normal, the eye-to-c offset along each, and wall pixels per metre across and down.
  glm::dvec3 wallRight_, wallUp_, wallNormal_;
  double cRight_ = 0.0, cUp_ = 0.0, cNormal_ = 0.0, pixelsPerMetreX_ = 0.0, pixelsPerMetreY_ = 0.0;
  // The same in float for the per-packet lookups, with the rays' affine direction towards the
  // wall (unturned) and the eye relative to c.
  struct PacketGeometry {
    glm::vec3 right{0.0f}, up{0.0f}, normal{0.0f};
    float cRight = 0, cUp = 0, cNormal = 0, nearDistance = 0, left = 0, top = 0;
    float pixelsPerMetreX = 0, pixelsPerMetreY = 0, width = 0, height = 0;
    glm::vec3 base{0.0f}, stepX{0.0f}, stepY{0.0f};
    glm::vec3 eye{0.0f};  // e - c
    // The wall point of pixel (px, py) relative to c: corner + px across + py down, from the
    // wall alone, so that every eye computes the same W(p) (fast rays' shared table).
    glm::vec3 corner{0.0f}, across{0.0f}, down{0.0f};
  } packet_;
  glm::vec3 targetShift_{0.0f};
  // The tail grid and this eye's constants for it (setTailGrid): q = scale p + offset in wall
  // pixels; M w = a A + b B with a = aBase + aPerPx px, b = bBase + bPerPy py.
  const TailGrid* tailGrid_ = nullptr;
  struct AsymptoteFrame {
    float scale = 1, offsetX = 0, offsetY = 0, aBase = 0, aPerPx = 0, bBase = 0, bPerPy = 0;
  } asymptote_;
  const ConformalWarp* warp_ = nullptr;
  const WallMapGrid* grid_ = nullptr;
  StereoRays stereoRays_ = StereoRays::Exact;
  int curvedSegments_ = 0;
  bool eyeAtReference_ = false;
  bool custom_ = false;
  double emptyRadius_ = 0.0;
};

}  // namespace confvis::embree
