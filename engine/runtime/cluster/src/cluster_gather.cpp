// Offline cluster runs: every rank's wall images to the root, which writes the outputs exactly as
// a single process would.
#include <map>
#include <utility>

#include <nlohmann/json.hpp>

#include "cluster_transport.hpp"
#include "confvis/runtime/cluster.hpp"

namespace confvis {

using namespace detail;

RenderResult Cluster::gatherImages(const RenderResult& mine, const DisplayConfig& display,
                                   const std::vector<Eye>& eyes, double renderSeconds) {
  const double patience = options_.timeoutSeconds + std::max(0.0, renderSeconds);
  if (!isRoot()) {
    nlohmann::json header = nlohmann::json::array();
    for (const WallImage& w : mine.images)
      header.push_back({{"wall", w.wall}, {"eye", static_cast<int>(w.eye)},
                        {"width", w.image.width}, {"height", w.image.height}});
    const std::string text = header.dump();
    std::vector<MPI_Request> sends(1, MPI_REQUEST_NULL);
    checkMpi(MPI_Isend(text.data(), static_cast<int>(text.size()), MPI_BYTE, 0, kTagImageHeader,
                       comm_, &sends[0]),
             "MPI_Isend");
    for (const WallImage& w : mine.images) {
      sends.emplace_back();
      checkMpi(MPI_Isend(w.image.pixels.data(), static_cast<int>(w.image.pixels.size()),
                         MPI_FLOAT, 0, kTagImage, comm_, &sends.back()),
               "MPI_Isend");
    }
    if (waitUntil(sends, deadlineIn(2 * patience)) >= 0) lost(0, "the gathering of images");
    return {};
  }
  std::map<std::pair<std::string, int>, ImageRGBA> images;
  for (const WallImage& w : mine.images) images[{w.wall, static_cast<int>(w.eye)}] = w.image;
  const auto deadline = deadlineIn(patience);
  for (int r = 1; r < size(); ++r) {
    const auto text = receiveBytes(comm_, r, kTagImageHeader, deadline);
    if (!text) lost(r, "the gathering of images");
    std::vector<MPI_Request> receives;
    for (const auto& item : nlohmann::json::parse(*text)) {
      ImageRGBA& image = images[{item.at("wall"), item.at("eye").get<int>()}];
      image = ImageRGBA(item.at("width").get<int>(), item.at("height").get<int>());
      receives.emplace_back();
      checkMpi(MPI_Irecv(image.pixels.data(), static_cast<int>(image.pixels.size()), MPI_FLOAT, r,
                         kTagImage, comm_, &receives.back()),
               "MPI_Irecv");
    }
    if (waitUntil(receives, deadline) >= 0) lost(r, "the gathering of images");
  }
  RenderResult all;
  all.stats = mine.stats;
  for (const Wall& wall : display.walls)
    for (const Eye eye : eyes)
      if (auto it = images.find({wall.name, static_cast<int>(eye)}); it != images.end())
        all.images.push_back({wall.name, eye, std::move(it->second)});
  return all;
}

}  // namespace confvis
