#include "camera_packet.hpp"

#include <cstring>

#include "direction_table.hpp"
#include "tail_lattice.hpp"

namespace confvis::embree {

void packetPositions(const TileJob& job, const PacketSamples& samples,
                     std::array<float, kPacketSize>& px, std::array<float, kPacketSize>& py) {
  if (job.samplesPerPixel == 1) {  // at the pixel centres, as the benchmark's raw loop
    pixelCentres(samples.x, samples.y, samples.columns, samples.count, job.pixelToWall.x,
                 job.pixelToWall.y, px, py);
    return;
  }
  for (int lane = 0; lane < kPacketSize; ++lane) {
    const int from = std::min(lane, samples.count - 1);
    const glm::dvec2 p = samplePosition(job, samples.laneX(from), samples.laneY(from),
                                        samples.sample,
                                        samples.pixelSeeds[static_cast<std::size_t>(from)]);
    px[lane] = static_cast<float>(p.x);
    py[lane] = static_cast<float>(p.y);
  }
}

namespace {

using Lanes = std::array<float, kPacketSize>;

glm::dvec2 lanePosition(const TileJob& job, const PacketSamples& samples, int lane) {
  return samplePosition(job, samples.laneX(lane), samples.laneY(lane), samples.sample,
                        samples.pixelSeeds[static_cast<std::size_t>(lane)]);
}

// Plain rays: the affine directions of the whole packet at once.
void plainPacket(const CameraRays& rays, const TileJob& job, const PacketSamples& samples,
                 PacketHits& hits) {
  alignas(32) Lanes px, py;
  packetPositions(job, samples, px, py);
  for (int lane = 0; lane < kPacketSize; ++lane) hits.valid[lane] = lane < samples.count ? -1 : 0;
  RTCRay8& ray = hits.rayhit.ray;
  rays.plainDirections().at(px, py, ray.dir_x, ray.dir_y, ray.dir_z);
}

// Rays from a run of a packet's straight rays (a DirectionTable's packet, or one computed for this
// frame by CameraRays::fastTargets or exactTails): the stored vectors, less the camera's
// targetShift, turned by the camera and normalised, as CameraRays::centreDirection does (glm's
// order of operations), and, for runs with origins, the stored origins placed as
// CameraRays::placeOffset does, for the whole packet at once (runs without origins: the rays'
// origins are set already). Unlit samples hold a zero vector. Runs with origins (exact tails)
// hold unit directions (CameraRays::exactTails, TailLattice::tails) and no shift: only turned.
void runPacket(const CameraRays& rays, const float* run, bool withOrigins, PacketHits& hits) {
  // Copied into locals, which the compiler knows alias nothing (the loop then vectorises).
  alignas(32) Lanes fx, fy, fz;
  std::memcpy(fx.data(), run, sizeof fx);
  std::memcpy(fy.data(), run + kPacketSize, sizeof fy);
  std::memcpy(fz.data(), run + 2 * kPacketSize, sizeof fz);
  const glm::mat3& m = rays.rotation();
  const glm::vec3 shift = rays.targetShift();
  RTCRay8& ray = hits.rayhit.ray;
  if (withOrigins) {  // exact tails: unit directions already (the rotation keeps them so)
    for (int lane = 0; lane < kPacketSize; ++lane) {
      const float sx = fx[lane], sy = fy[lane], sz = fz[lane];
      ray.dir_x[lane] = m[0][0] * sx + m[1][0] * sy + m[2][0] * sz;
      ray.dir_y[lane] = m[0][1] * sx + m[1][1] * sy + m[2][1] * sz;
      ray.dir_z[lane] = m[0][2] * sx + m[1][2] * sy + m[2][2] * sz;
      hits.valid[lane] = sx != 0.0f || sy != 0.0f || sz != 0.0f ? -1 : 0;
    }
  } else {
    for (int lane = 0; lane < kPacketSize; ++lane) {
      const float sx = fx[lane] - shift.x, sy = fy[lane] - shift.y, sz = fz[lane] - shift.z;
      const float x = m[0][0] * sx + m[1][0] * sy + m[2][0] * sz;
      const float y = m[0][1] * sx + m[1][1] * sy + m[2][1] * sz;
      const float z = m[0][2] * sx + m[1][2] * sy + m[2][2] * sz;
      // Unlit (zero) lanes are not traced; their direction only has to stay finite (a blend,
      // not a select, so that the loop vectorises).
      const bool lit = fx[lane] != 0.0f || fy[lane] != 0.0f || fz[lane] != 0.0f;
      const float unlit = lit ? 0.0f : 1.0f;
      const float inverseLength = 1.0f / std::sqrt(x * x + y * y + z * z + unlit);
      ray.dir_x[lane] = x * inverseLength;
      ray.dir_y[lane] = y * inverseLength;
      ray.dir_z[lane] = z * inverseLength;
      hits.valid[lane] = lit ? -1 : 0;
    }
  }
  if (!withOrigins) return;
  alignas(32) Lanes ox, oy, oz;
  std::memcpy(ox.data(), run + 3 * kPacketSize, sizeof ox);
  std::memcpy(oy.data(), run + 4 * kPacketSize, sizeof oy);
  std::memcpy(oz.data(), run + 5 * kPacketSize, sizeof oz);
  const glm::vec3& c = rays.placedCentre();
  for (int lane = 0; lane < kPacketSize; ++lane) {
    ray.org_x[lane] = c.x + (m[0][0] * ox[lane] + m[1][0] * oy[lane] + m[2][0] * oz[lane]);
    ray.org_y[lane] = c.y + (m[0][1] * ox[lane] + m[1][1] * oy[lane] + m[2][1] * oz[lane]);
    ray.org_z[lane] = c.z + (m[0][2] * ox[lane] + m[1][2] * oy[lane] + m[2][2] * oz[lane]);
  }
}

// The packet's straight rays written into hits (valid lanes, origins, directions).
void setUpStraightPacket(const CameraRays& rays, const TileJob& job, const PacketSamples& samples,
                         PacketHits& hits) {
  RTCRay8& ray = hits.rayhit.ray;
  const glm::vec3& origin = rays.origin();
  for (int lane = 0; lane < kPacketSize; ++lane) {
    ray.org_x[lane] = origin.x;
    ray.org_y[lane] = origin.y;
    ray.org_z[lane] = origin.z;
  }
  if (job.directions) {
    runPacket(rays, job.directions->packet(samples.x, samples.y, samples.sample), false, hits);
  } else if (rays.plain()) {
    plainPacket(rays, job, samples, hits);
  } else if (!rays.centreEyeConformal()) {  // fast stereo rays: towards W(p), per packet
    alignas(32) Lanes px, py;
    alignas(32) std::array<float, 3 * kPacketSize> run;
    packetPositions(job, samples, px, py);
    rays.fastTargets(px.data(), py.data(), samples.count, run.data());
    runPacket(rays, run.data(), false, hits);
  } else {  // a map lookup per sample
    hits.valid.fill(0);
    for (int lane = 0; lane < samples.count; ++lane) {
      const glm::dvec2 p = lanePosition(job, samples, lane);
      glm::vec3 direction;
      if (rays.straightDirection(p.x, p.y, direction))
        hits.setStraightRay(lane, origin, direction);
    }
  }
}

// Exact stereo rays: where every lit curve of the packet bends inside the empty ball
// (CameraRays::setEmptyRadius), its tails are written into hits as straight rays and true is
// returned, so that they trace as plain rays do; else the packet's paths (tails where a lane's
// curve bends inside the ball, whole curves elsewhere).
bool setUpPaths(const CameraRays& rays, const TileJob& job, const PacketSamples& samples,
                std::array<RayPath, kPacketSize>& paths, PacketHits& hits, TailLattice* tails) {
  // A table of the tails, where every curve of the packet bends inside the empty ball.
  if (job.directions && job.directions->hasOrigins() &&
      job.directions->reach(samples.x, samples.y, samples.sample) < rays.emptyRadius()) {
    runPacket(rays, job.directions->packet(samples.x, samples.y, samples.sample), true, hits);
    return true;
  }
  alignas(32) Lanes px, py, reach;
  alignas(32) std::array<float, 6 * kPacketSize> run;
  packetPositions(job, samples, px, py);
  RTCRay8& ray = hits.rayhit.ray;
  if (tails && tails->straightRays(samples, px.data(), py.data(),
                                   rays.emptyRadius(),
                                   {ray.org_x, ray.org_y, ray.org_z, ray.dir_x, ray.dir_y,
                                    ray.dir_z, hits.valid.data()}))
    return true;  // the lattice's tails placed at once, as runPacket places them
  const float packetReach =
      tails ? tails->tails(samples, px.data(), py.data(), run.data(), reach.data())
            : rays.exactTails(px.data(), py.data(), samples.count, run.data(), reach.data());
  if (packetReach < rays.emptyRadius()) {
    runPacket(rays, run.data(), true, hits);
    return true;
  }
  bool straight = true;
  for (int lane = 0; lane < samples.count; ++lane) {
    RayPath& path = paths[static_cast<std::size_t>(lane)];
    path.vertexCount = 1;
    path.lit = reach[lane] > 0.0f;
    if (!path.lit) continue;
    if (reach[lane] < rays.emptyRadius()) {  // the tail alone, as the straight packets trace it
      const auto at = [&](int component) { return run[component * kPacketSize + lane]; };
      path.vertices[0] = rays.placeOffset({at(3), at(4), at(5)});
      path.tail = rays.centreDirection({at(0), at(1), at(2)});
    } else {
      rays.curvedPath(px[lane], py[lane], path);
    }
    straight = straight && path.vertexCount == 1;
  }
  if (!straight) return false;
  hits.valid.fill(0);
  for (int lane = 0; lane < samples.count; ++lane) {
    const RayPath& path = paths[static_cast<std::size_t>(lane)];
    if (path.lit) hits.setStraightRay(lane, path.vertices[0], path.tail);
  }
  return true;
}

}  // namespace

std::uint64_t traceCameraPacket(const EmbreeScene& scene, const CameraRays& rays,
                                const TileJob& job, const PacketSamples& samples,
                                PacketHits& hits, TailLattice* tails) {
  if (rays.straight()) {
    setUpStraightPacket(rays, job, samples, hits);
    return traceStraight(scene.handle(), samples.count, samples.columns, hits);
  }
  std::array<RayPath, kPacketSize> paths;
  if (setUpPaths(rays, job, samples, paths, hits, tails))
    return traceStraight(scene.handle(), samples.count, samples.columns, hits);
  return tracePaths(scene.handle(), paths.data(), samples.count, samples.columns, hits);
}

std::uint64_t traceCameraPacketPair(const EmbreeScene& scene, const CameraRays& rays,
                                    const TileJob& job, const std::array<PacketSamples, 2>& samples,
                                    std::array<PacketHits, 2>& hits, TailLattice* tails) {
  if (samples[1].count == 0)
    return traceCameraPacket(scene, rays, job, samples[0], hits[0], tails);
  if (!rays.straight()) {
    std::array<std::array<RayPath, kPacketSize>, 2> paths;
    const bool straight0 = setUpPaths(rays, job, samples[0], paths[0], hits[0], tails);
    const bool straight1 = setUpPaths(rays, job, samples[1], paths[1], hits[1], tails);
    if (!straight0 || !straight1) {
      const auto trace = [&](int half, bool straight) {
        return straight ? traceStraight(scene.handle(), samples[half].count,
                                        samples[half].columns, hits[half])
                        : tracePaths(scene.handle(), paths[half].data(), samples[half].count,
                                     samples[half].columns, hits[half]);
      };
      return trace(0, straight0) + trace(1, straight1);
    }
  } else {
    for (int half = 0; half < 2; ++half) setUpStraightPacket(rays, job, samples[half], hits[half]);
  }
  return traceStraightPair(scene.handle(), {samples[0].count, samples[1].count},
                           {samples[0].columns, samples[1].columns}, hits, scene.nativeRay16());
}

}  // namespace confvis::embree
