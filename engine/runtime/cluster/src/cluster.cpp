#include "confvis/runtime/cluster.hpp"

#include <cstdio>

#include <nlohmann/json.hpp>
#include <arpa/inet.h>
#include <ifaddrs.h>
#include <netinet/in.h>
#include <unistd.h>

#include "cluster_maps.hpp"
#include "cluster_transport.hpp"
#include "confvis/base/checksum.hpp"
#include "confvis/engine/version.hpp"
#include "confvis/runtime/wall_assignment.hpp"

namespace confvis {
namespace {

using namespace detail;
using json = nlohmann::json;

std::string hostName() {
  char name[256] = {};
  if (gethostname(name, sizeof name - 1) != 0) return "unknown";
  return name;
}

// This host's IPv4 and IPv6 addresses: configs (SGCT's) name nodes by address as often as by name.
std::vector<std::string> hostAddresses() {
  std::vector<std::string> addresses;
  ifaddrs* list = nullptr;
  if (getifaddrs(&list) != 0) return addresses;
  for (const ifaddrs* a = list; a; a = a->ifa_next) {
    if (!a->ifa_addr) continue;
    char text[INET6_ADDRSTRLEN] = {};
    const int family = a->ifa_addr->sa_family;
    const void* raw = family == AF_INET
                          ? static_cast<const void*>(&reinterpret_cast<const sockaddr_in*>(a->ifa_addr)->sin_addr)
                      : family == AF_INET6
                          ? static_cast<const void*>(&reinterpret_cast<const sockaddr_in6*>(a->ifa_addr)->sin6_addr)
                          : nullptr;
    if (raw && inet_ntop(family, raw, text, sizeof text)) addresses.push_back(text);
  }
  freeifaddrs(list);
  return addresses;
}

// The root's answer to the start-up check: the hosts of all ranks, or why the cluster cannot run.
json verdict(const std::vector<json>& hellos) {
  const json& root = hellos.front();
  for (std::size_t r = 1; r < hellos.size(); ++r) {
    const json& h = hellos[r];
    for (const char* key : {"version", "hash"})
      if (h.at(key) != root.at(key))
        return {{"error", "rank " + std::to_string(r) + " (host " + h.at("host").get<std::string>() +
                              ") has " + (std::string(key) == "version" ? "confvis " : "config hash ") +
                              h.at(key).get<std::string>() + " (display '" +
                              h.at("display").get<std::string>() + "') where rank 0 (host " +
                              root.at("host").get<std::string>() + ") has " +
                              root.at(key).get<std::string>() + " (display '" +
                              root.at("display").get<std::string>() +
                              "'): every rank must run the same confvis on the same config"}};
  }
  json hosts = json::array();
  for (const json& h : hellos) {
    json names = h.at("addresses");
    names.insert(names.begin(), h.at("host"));
    hosts.push_back(names);
  }
  return {{"hosts", hosts}};
}

}  // namespace

Cluster::Cluster(MPI_Comm comm, const DisplayConfig& display, ClusterOptions options)
    : options_(options), transfer_(std::make_unique<MapTransfer>()) {
  if (!(options_.timeoutSeconds > 0.0) || options_.mapChunkBytes == 0)
    throw Error(ErrorCode::InvalidInput, "cluster: the timeout and the map chunk size must be > 0");
  checkMpi(MPI_Comm_dup(comm, &comm_), "MPI_Comm_dup");
  checkMpi(MPI_Comm_set_errhandler(comm_, MPI_ERRORS_RETURN), "MPI_Comm_set_errhandler");
  int size = 0;
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &size);
  hosts_.assign(size, "unknown");
  const json hello = {{"host", hostName()}, {"addresses", hostAddresses()}, {"hash", fnv1a64Hex(toJson(display).dump())},
                      {"version", versionString()}, {"display", display.name}};
  const auto deadline = deadlineIn(options_.timeoutSeconds);
  json answer;
  if (isRoot()) {
    std::vector<json> hellos{hello};
    for (int r = 1; r < size; ++r) {
      const auto bytes = receiveBytes(comm_, r, kTagHello, deadline);
      if (!bytes) lost(r, "the start-up check");
      hellos.push_back(json::parse(*bytes));
      hosts_[r] = hellos.back().at("host");
    }
    answer = verdict(hellos);
    const std::string text = answer.dump();
    std::vector<MPI_Request> sends(size - 1, MPI_REQUEST_NULL);
    for (int r = 1; r < size; ++r)
      checkMpi(MPI_Isend(text.data(), static_cast<int>(text.size()), MPI_BYTE, r, kTagVerdict,
                         comm_, &sends[r - 1]),
               "MPI_Isend");
    if (const int late = waitUntil(sends, deadlineIn(options_.timeoutSeconds)); late >= 0)
      lost(late + 1, "the start-up check");
  } else {
    const std::string text = hello.dump();
    std::vector<MPI_Request> send(1, MPI_REQUEST_NULL);
    checkMpi(MPI_Isend(text.data(), static_cast<int>(text.size()), MPI_BYTE, 0, kTagHello, comm_,
                       &send[0]),
             "MPI_Isend");
    // Twice the root's deadline: a rank the root waits for is named by the root first.
    const auto late = deadlineIn(2 * options_.timeoutSeconds);
    const auto bytes = receiveBytes(comm_, 0, kTagVerdict, late);
    if (!bytes || waitUntil(send, late) >= 0) lost(0, "the start-up check");
    answer = json::parse(*bytes);
  }
  if (answer.contains("error"))
    throw ClusterError(ErrorCode::InvalidInput, "cluster: " + answer.at("error").get<std::string>());
  const auto names = answer.at("hosts").get<std::vector<std::vector<std::string>>>();
  for (std::size_t r = 0; r < names.size(); ++r) hosts_[r] = names[r].front();
  walls_ = assignWalls(display, names);
}

Cluster::~Cluster() {
  // A cluster that lost a rank may never free its communicator (MPI would wait for the rank).
  if (comm_ != MPI_COMM_NULL && !failed_) MPI_Comm_free(&comm_);
}

std::string Cluster::describe(int rank) const {
  std::string text = "rank " + std::to_string(rank) + " (host " +
                     (rank < size() ? hosts_[rank] : "unknown");
  if (rank < static_cast<int>(walls_.size())) {
    const auto& walls = walls_[rank];
    text += walls.empty() ? ", no walls" : walls.size() == 1 ? ", wall " : ", walls ";
    for (std::size_t i = 0; i < walls.size(); ++i) text += (i ? ", " : "") + walls[i];
  }
  return text + ")";
}

void Cluster::lost(int rank, const std::string& during) {
  failed_ = true;
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%g", options_.timeoutSeconds);
  throw ClusterError(ErrorCode::IoFailure, "cluster: rank " + std::to_string(rank_) + ": lost " +
                                               describe(rank) + ": no answer within " + seconds +
                                               " s during " + during);
}

void Cluster::exchangeFrameBytes(void* data, std::size_t bytes, double patienceSeconds) {
  std::vector<MPI_Request> requests;
  if (isRoot()) {
    requests.assign(size() - 1, MPI_REQUEST_NULL);
    for (int r = 1; r < size(); ++r)
      checkMpi(MPI_Isend(data, static_cast<int>(bytes), MPI_BYTE, r, kTagFrame, comm_,
                         &requests[r - 1]),
               "MPI_Isend");
    if (const int late = waitUntil(requests, deadlineIn(options_.timeoutSeconds)); late >= 0)
      lost(late + 1, "the frame state's broadcast");
  } else {
    requests.assign(1, MPI_REQUEST_NULL);
    checkMpi(MPI_Irecv(data, static_cast<int>(bytes), MPI_BYTE, 0, kTagFrame, comm_, &requests[0]),
             "MPI_Irecv");
    // Maps the root shares before this frame arrive while waiting for it.
    if (waitUntil(requests, deadlineIn(2 * options_.timeoutSeconds + patienceSeconds),
                  [this] { progressMaps(); }) >= 0)
      lost(0, "the wait for the next frame state");
  }
}

void Cluster::swapLock(double patienceSeconds) {
  // A star through the root, not MPI_Barrier: the root learns which rank is missing and tells
  // the others, so every message names the same lost rank.
  int lostRank = -1;
  if (isRoot()) {
    std::vector<char> arrived(size(), 0);
    std::vector<MPI_Request> readies(size() - 1, MPI_REQUEST_NULL);
    for (int r = 1; r < size(); ++r)
      checkMpi(MPI_Irecv(&arrived[r], 1, MPI_BYTE, r, kTagReady, comm_, &readies[r - 1]),
               "MPI_Irecv");
    if (const int late = waitUntil(readies, deadlineIn(options_.timeoutSeconds + patienceSeconds));
        late >= 0)
      lostRank = late + 1;
    std::vector<MPI_Request> gos(size() - 1, MPI_REQUEST_NULL);
    for (int r = 1; r < size(); ++r)
      if (r != lostRank)
        checkMpi(MPI_Isend(&lostRank, 1, MPI_INT, r, kTagGo, comm_, &gos[r - 1]), "MPI_Isend");
    const int lateGo = waitUntil(gos, deadlineIn(lostRank >= 0 ? 1.0 : options_.timeoutSeconds));
    if (lostRank >= 0) lost(lostRank, "the swap lock");
    if (lateGo >= 0) lost(lateGo + 1, "the swap lock");
    for (MPI_Request& r : readies) if (r != MPI_REQUEST_NULL) MPI_Request_free(&r);
  } else {
    const char ready = 1;
    std::vector<MPI_Request> requests(2, MPI_REQUEST_NULL);
    checkMpi(MPI_Isend(&ready, 1, MPI_BYTE, 0, kTagReady, comm_, &requests[0]), "MPI_Isend");
    checkMpi(MPI_Irecv(&lostRank, 1, MPI_INT, 0, kTagGo, comm_, &requests[1]), "MPI_Irecv");
    if (waitUntil(requests, deadlineIn(2 * options_.timeoutSeconds + patienceSeconds)) >= 0)
      lost(0, "the swap lock");
    if (lostRank >= 0) lost(lostRank, "the swap lock");
  }
}

}  // namespace confvis
