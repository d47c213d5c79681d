#include "confvis/runtime/wall_assignment.hpp"

#include <algorithm>
#include <cctype>
#include <map>

#include "confvis/base/error.hpp"

namespace confvis {
namespace {

bool isRankNumber(const std::string& node) {
  return !node.empty() && node.size() < 10 &&
         std::all_of(node.begin(), node.end(), [](unsigned char c) { return std::isdigit(c); });
}

std::string hostList(const std::vector<std::vector<std::string>>& rankHosts) {
  std::vector<std::string> hosts;
  for (const auto& names : rankHosts) hosts.push_back(names.empty() ? "?" : names.front());
  std::sort(hosts.begin(), hosts.end());
  hosts.erase(std::unique(hosts.begin(), hosts.end()), hosts.end());
  std::string list;
  for (const std::string& h : hosts) list += (list.empty() ? "" : ", ") + h;
  return list;
}

}  // namespace

std::vector<std::vector<std::string>> assignWalls(
    const DisplayConfig& display, const std::vector<std::vector<std::string>>& rankHosts) {
  const int ranks = static_cast<int>(rankHosts.size());
  if (ranks <= 0) throw Error(ErrorCode::InvalidInput, "a cluster needs at least one rank");
  std::vector<std::vector<std::string>> walls(ranks);
  std::map<std::string, std::size_t> dealtOnHost;  // next of the host's ranks to get a wall
  int nextRank = 0;
  for (const Wall& wall : display.walls) {
    const std::string where = "display '" + display.name + "': wall '" + wall.name + "'";
    if (wall.node.empty()) {
      walls[nextRank++ % ranks].push_back(wall.name);
    } else if (isRankNumber(wall.node)) {
      const long rank = std::stol(wall.node);
      if (rank >= ranks)
        throw Error(ErrorCode::InvalidInput, where + ": node " + wall.node + " names rank " +
                                                 wall.node + ", but the cluster has " +
                                                 std::to_string(ranks) + " ranks (0.." +
                                                 std::to_string(ranks - 1) + ")");
      walls[rank].push_back(wall.name);
    } else {
      std::vector<int> onHost;
      for (int r = 0; r < ranks; ++r)
        if (std::find(rankHosts[r].begin(), rankHosts[r].end(), wall.node) != rankHosts[r].end())
          onHost.push_back(r);
      if (onHost.empty())
        throw Error(ErrorCode::InvalidInput, where + ": node '" + wall.node +
                                                 "' runs no rank of this cluster (hosts: " +
                                                 hostList(rankHosts) + ")");
      std::size_t& next = dealtOnHost[wall.node];
      walls[onHost[next++ % onHost.size()]].push_back(wall.name);
    }
  }
  return walls;
}

}  // namespace confvis
