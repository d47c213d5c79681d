// CameraRays' per-packet stereo rays (fast targets, exact tails): float, structure of arrays, in
// loops the compiler vectorises; the grid lookups four components at a time.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "camera_rays.hpp"
#include "tail_grid.hpp"

namespace confvis::embree {

namespace {

using Lanes = std::array<float, kPacketSize>;

}  // namespace

void CameraRays::pixelSamples(const float* px, const float* py, int count, float* fx, float* fy,
                              float* fz, float* alpha, float* wallX, float* wallY,
                              float* wallZ) const {
  if (custom_) {  // an override's ray meets the wall elsewhere than its pixel: mapSample's rule
    for (int lane = 0; lane < kPacketSize; ++lane) {
      glm::dvec3 wallPoint;
      const WallMapGrid::Sample s = mapSample(px[lane], py[lane], wallPoint);
      fx[lane] = s.direction.x, fy[lane] = s.direction.y, fz[lane] = s.direction.z;
      alpha[lane] = lane < count ? s.alpha : 0.0f;
      if (!wallX) continue;
      const glm::vec3 w(wallPoint - reference_);
      wallX[lane] = w.x, wallY[lane] = w.y, wallZ[lane] = w.z;
    }
    return;
  }
  grid_->at(kPacketSize, px, py, fx, fy, fz, alpha);
  for (int lane = count; lane < kPacketSize; ++lane) alpha[lane] = 0.0f;
  if (!wallX) return;
  const PacketGeometry& g = packet_;
  for (int lane = 0; lane < kPacketSize; ++lane) {
    wallX[lane] = g.corner.x + px[lane] * g.across.x + py[lane] * g.down.x;
    wallY[lane] = g.corner.y + px[lane] * g.across.y + py[lane] * g.down.y;
    wallZ[lane] = g.corner.z + px[lane] * g.across.z + py[lane] * g.down.z;
  }
}

void CameraRays::mapDirections(const float* x, const float* y, const float* z, int count,
                               float* fx, float* fy, float* fz) const {
  const PacketGeometry& g = packet_;
  alignas(32) Lanes wallPx, wallPy, alpha;
  alignas(32) std::array<int, kPacketSize> inside;
  for (int lane = 0; lane < kPacketSize; ++lane) {
    // Where c + t fromC meets the wall's plane, relative to the eye, in wall pixels.
    const float towardWall = x[lane] * g.normal.x + y[lane] * g.normal.y + z[lane] * g.normal.z;
    const float t = (-g.nearDistance - g.cNormal) / towardWall;
    const float right = x[lane] * g.right.x + y[lane] * g.right.y + z[lane] * g.right.z;
    const float up = x[lane] * g.up.x + y[lane] * g.up.y + z[lane] * g.up.z;
    const float wx = (g.cRight + t * right - g.left) * g.pixelsPerMetreX;
    const float wy = (g.top - (g.cUp + t * up)) * g.pixelsPerMetreY;
    const bool in = towardWall < 0.0f && t > 0.0f && wx >= 0.0f && wy >= 0.0f &&
                    wx <= g.width && wy <= g.height;
    inside[lane] = in ? 1 : 0;
    wallPx[lane] = in ? wx : 0.0f;
    wallPy[lane] = in ? wy : 0.0f;
  }
  grid_->at(kPacketSize, wallPx.data(), wallPy.data(), fx, fy, fz, alpha.data());
  for (int lane = 0; lane < count; ++lane) {
    if (inside[lane]) continue;  // near the wall's edges only
    const glm::dvec3 mapped = warp_->direction(glm::dvec3(x[lane], y[lane], z[lane]));
    fx[lane] = static_cast<float>(mapped.x);
    fy[lane] = static_cast<float>(mapped.y);
    fz[lane] = static_cast<float>(mapped.z);
  }
}

void CameraRays::fastTargets(const float* px, const float* py, int count, float* run) const {
  alignas(32) Lanes fx, fy, fz, alpha, wx, wy, wz;
  pixelSamples(px, py, count, fx.data(), fy.data(), fz.data(), alpha.data(), wx.data(), wy.data(),
               wz.data());
  for (int lane = 0; lane < kPacketSize; ++lane) {
    // W(p) = c + |p - c| F / |F|.
    const float distance = std::sqrt(wx[lane] * wx[lane] + wy[lane] * wy[lane] + wz[lane] * wz[lane]);
    const float lengthF = std::sqrt(fx[lane] * fx[lane] + fy[lane] * fy[lane] + fz[lane] * fz[lane]);
    const bool lit = alpha[lane] >= 0.5f && lengthF > 0.0f;
    const float scale = lit ? distance / lengthF : 0.0f;
    run[lane] = fx[lane] * scale;
    run[kPacketSize + lane] = fy[lane] * scale;
    run[2 * kPacketSize + lane] = fz[lane] * scale;
  }
}

namespace {

// The closed form of one sample's curve (tailGeometry): the physical ray's unit direction
// u towards the wall point base + px stepX + py stepY, the eye's offset a = e - c across it
// (curvedRay's foot relative to c), its length h, and the curve's reach. Divisions by constants
// are multiplications by their reciprocals (no division is exact either way; the reach's margin
// covers the rounding).
struct LaneCurve {
  float x, y, z, perpX, perpY, perpZ, h, lastDistance, reach;
  bool onLine;
};

struct CurveConstants {
  glm::vec3 base, stepX, stepY, eye;
  float eyeDistance, tanAsymptote, inverseSin;
};

CurveConstants curveConstants(const glm::vec3& base, const glm::vec3& stepX,
                              const glm::vec3& stepY, const glm::vec3& eye) {
  return {base, stepX, stepY, eye, std::sqrt(eye.x * eye.x + eye.y * eye.y + eye.z * eye.z),
          static_cast<float>(std::tan(kAsymptoteAngle)),
          static_cast<float>(1.0 / std::sin(kAsymptoteAngle))};
}

inline LaneCurve laneCurve(const CurveConstants& k, float px, float py) {
  constexpr float kUnbounded = std::numeric_limits<float>::infinity();
  LaneCurve l;
  const float tx = k.base.x + px * k.stepX.x + py * k.stepY.x;
  const float ty = k.base.y + px * k.stepX.y + py * k.stepY.y;
  const float tz = k.base.z + px * k.stepX.z + py * k.stepY.z;
  const float inverseLength = 1.0f / std::sqrt(tx * tx + ty * ty + tz * tz);
  l.x = tx * inverseLength, l.y = ty * inverseLength, l.z = tz * inverseLength;
  const glm::vec3& a = k.eye;
  const float along = a.x * l.x + a.y * l.y + a.z * l.z;
  l.perpX = a.x - along * l.x, l.perpY = a.y - along * l.y, l.perpZ = a.z - along * l.z;
  l.h = std::sqrt(l.perpX * l.perpX + l.perpY * l.perpY + l.perpZ * l.perpZ);
  // The angle between u and dir(e - c), atan2(h, along), at most kAsymptoteAngle: a line
  // through c, for curvedPath.
  l.onLine = !(l.h > along * k.tanAsymptote);
  // The last vertex, where the angle at c is kAsymptoteAngle: h / sin(angle) from c. The
  // curve's vertices lie between |e - c| and that from c; the margin covers float rounding
  // (the clearance query reaches 1 % beyond the widest reach, curvedReach).
  l.lastDistance = l.h * k.inverseSin;
  l.reach = l.onLine ? kUnbounded : 1.0001f * std::max(k.eyeDistance, l.lastDistance);
  return l;
}

}  // namespace

void CameraRays::tailGeometry(const float* px, const float* py, TailGeometry& out) const {
  const PacketGeometry& g = packet_;
  const CurveConstants k = curveConstants(g.base, g.stepX, g.stepY, g.eye);
  const float toLastPerH = 1.0f / k.tanAsymptote;
  // Into locals, which the compiler knows alias nothing (the loop then vectorises).
  alignas(32) Lanes positionX, positionY;
  std::memcpy(positionX.data(), px, sizeof positionX);
  std::memcpy(positionY.data(), py, sizeof positionY);
  TailGeometry geometry;
  for (int lane = 0; lane < kPacketSize; ++lane) {
    const LaneCurve l = laneCurve(k, positionX[lane], positionY[lane]);
    const float toLast = l.h * toLastPerH;
    geometry.lastDistance[lane] = l.lastDistance;
    // A ray through c (h = 0 behind the eye) has its last vertex at c itself: any direction
    // serves the lookup (a zero one would not; lattice nodes can sit exactly there).
    const bool throughCentre = l.onLine || !(l.h > 0.0f);
    geometry.lastX[lane] = throughCentre ? l.x : l.perpX + toLast * l.x;
    geometry.lastY[lane] = throughCentre ? l.y : l.perpY + toLast * l.y;
    geometry.lastZ[lane] = throughCentre ? l.z : l.perpZ + toLast * l.z;
    geometry.ux[lane] = l.x, geometry.uy[lane] = l.y, geometry.uz[lane] = l.z;
    geometry.h[lane] = l.h;
    geometry.reach[lane] = l.reach;
  }
  out = geometry;
}

void CameraRays::tailsAt(const float* px, const float* py, int count, TailGeometry& geometry,
                         float* tails) const {
  tailGeometry(px, py, geometry);
  if (tailGrid_ && asymptoteTails(px, py, count, geometry, tails)) return;
  alignas(32) Lanes tailX, tailY, tailZ, fx, fy, fz;
  mapDirections(geometry.ux.data(), geometry.uy.data(), geometry.uz.data(), count, tailX.data(),
                tailY.data(), tailZ.data());
  mapDirections(geometry.lastX.data(), geometry.lastY.data(), geometry.lastZ.data(), count,
                fx.data(), fy.data(), fz.data());
  for (int lane = 0; lane < kPacketSize; ++lane) {  // F(u) normalised, W(last) relative to c
    const float tailLength =
        std::sqrt(tailX[lane] * tailX[lane] + tailY[lane] * tailY[lane] + tailZ[lane] * tailZ[lane]);
    const float lastLength = std::sqrt(fx[lane] * fx[lane] + fy[lane] * fy[lane] + fz[lane] * fz[lane]);
    const float tailScale = 1.0f / tailLength;
    const float lastScale = geometry.lastDistance[lane] / lastLength;  // W(last) = |last| F
    tails[lane] = tailX[lane] * tailScale;
    tails[kPacketSize + lane] = tailY[lane] * tailScale;
    tails[2 * kPacketSize + lane] = tailZ[lane] * tailScale;
    tails[3 * kPacketSize + lane] = fx[lane] * lastScale;
    tails[4 * kPacketSize + lane] = fy[lane] * lastScale;
    tails[5 * kPacketSize + lane] = fz[lane] * lastScale;
  }
}

float CameraRays::maskTails(const float* alpha, const float* laneReach, const float* tails,
                            float* run, float* reach) {
  float packetReach = 0.0f;
  for (int lane = 0; lane < kPacketSize; ++lane) {
    reach[lane] = alpha[lane] >= 0.5f ? laneReach[lane] : 0.0f;
    const bool lit = reach[lane] > 0.0f;  // unlit lanes: zeros (lit ones have a unit direction)
    for (int component = 0; component < 6; ++component)
      run[component * kPacketSize + lane] = lit ? tails[component * kPacketSize + lane] : 0.0f;
    packetReach = std::max(packetReach, reach[lane]);
  }
  return packetReach;
}

void CameraRays::pixelAlpha(const float* px, const float* py, int count, float* alpha) const {
  alignas(32) Lanes fx, fy, fz;
  pixelSamples(px, py, count, fx.data(), fy.data(), fz.data(), alpha);
}

bool CameraRays::asymptoteTails(const float* px, const float* py, int count,
                                const TailGeometry& geometry, float* tails) const {
  const AsymptoteFrame& f = asymptote_;
  alignas(32) Lanes positionX, positionY, qx, qy;
  std::memcpy(positionX.data(), px, sizeof positionX);
  std::memcpy(positionY.data(), py, sizeof positionY);
  for (int lane = 0; lane < kPacketSize; ++lane) {
    qx[lane] = f.scale * positionX[lane] + f.offsetX;
    qy[lane] = f.scale * positionY[lane] + f.offsetY;
  }
  alignas(32) std::array<float, 9 * kPacketSize> grid;  // F, A, B
  if (!tailGrid_->at(qx.data(), qy.data(), count, grid.data())) return false;
  const float eyeDistance = glm::length(packet_.eye);
  alignas(32) Lanes out[6];
  for (int lane = 0; lane < kPacketSize; ++lane) {
    const float fx = grid[lane], fy = grid[kPacketSize + lane], fz = grid[2 * kPacketSize + lane];
    const float inverseLength = 1.0f / std::sqrt(fx * fx + fy * fy + fz * fz);
    const float dx = fx * inverseLength, dy = fy * inverseLength, dz = fz * inverseLength;
    const float a = f.aBase + f.aPerPx * positionX[lane];
    const float b = f.bBase + f.bPerPy * positionY[lane];
    const float mx = a * grid[3 * kPacketSize + lane] + b * grid[6 * kPacketSize + lane];
    const float my = a * grid[4 * kPacketSize + lane] + b * grid[7 * kPacketSize + lane];
    const float mz = a * grid[5 * kPacketSize + lane] + b * grid[8 * kPacketSize + lane];
    const float onD = mx * dx + my * dy + mz * dz;  // M w is across F; the blend nearly so
    const float ox = mx - onD * dx, oy = my - onD * dy, oz = mz - onD * dz;
    // The start on the line, as far out as the lane's curve reaches (every vertex lies within
    // max(|e - c|, |last|) of c, a line through c's too): where that lies inside the empty ball,
    // a tail alone is traced, and Embree does not start among the scene's boxes.
    const float inside = 0.9999f * std::max(eyeDistance, geometry.lastDistance[lane]);
    const float along = std::sqrt(std::max(0.0f, inside * inside - (ox * ox + oy * oy + oz * oz)));
    out[0][lane] = dx, out[1][lane] = dy, out[2][lane] = dz;
    out[3][lane] = ox + along * dx, out[4][lane] = oy + along * dy, out[5][lane] = oz + along * dz;
  }
  for (int component = 0; component < 6; ++component)
    std::memcpy(tails + component * kPacketSize, out[component].data(), sizeof(Lanes));
  return true;
}

float CameraRays::exactTails(const float* px, const float* py, int count, float* run,
                             float* reach) const {
  alignas(32) Lanes alpha;
  pixelAlpha(px, py, count, alpha.data());
  TailGeometry geometry;
  alignas(32) std::array<float, 6 * kPacketSize> tails;
  tailsAt(px, py, count, geometry, tails.data());
  return maskTails(alpha.data(), geometry.reach.data(), tails.data(), run, reach);
}

}  // namespace confvis::embree
