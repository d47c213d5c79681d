// confvis/confvis.hpp is "everything public": it includes every header under a module's
// include/confvis/ folder, so a header added later cannot be left out of it unnoticed. (That it
// compiles is shown by every test that includes it, and by the consumer test against the install.)
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>

namespace {

namespace fs = std::filesystem;

// "confvis/engine/view.hpp" for every public header of the source tree (build folders skipped).
std::set<std::string> publicHeaders(const fs::path& root) {
  std::set<std::string> headers;
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator();
       ++it) {
    const std::string name = it->path().filename().string();
    if (it->is_directory() && (name.rfind("build", 0) == 0 || name.rfind('.', 0) == 0 ||
                               name == "tests" || name == "out")) {
      it.disable_recursion_pending();
      continue;
    }
    if (!it->is_regular_file() || it->path().extension() != ".hpp") continue;
    const std::string path = it->path().generic_string();
    const auto at = path.find("/include/confvis/");
    if (at != std::string::npos) headers.insert(path.substr(at + 9));
  }
  return headers;
}

TEST(UmbrellaHeader, IncludesEveryPublicHeader) {
  const fs::path root = CONFVIS_SOURCE_DIR;
  const fs::path umbrella = root / "engine/runtime/include/confvis/confvis.hpp";
  std::ifstream in(umbrella);
  ASSERT_TRUE(in) << umbrella;
  std::set<std::string> included;
  const std::regex include(R"re(^#include "(confvis/[^"]+)")re");
  for (std::string line; std::getline(in, line);) {
    std::smatch match;
    if (std::regex_search(line, match, include)) included.insert(match[1]);
  }
  const std::set<std::string> headers = publicHeaders(root);
  ASSERT_GT(headers.size(), 40u);  // the scan found the modules' include folders
  for (const std::string& header : headers) {
    if (header == "confvis/confvis.hpp") continue;
    // The cluster is a component of its own (find_package(confvis COMPONENTS cluster)): it
    // needs MPI, which an application without a cluster must not have to find.
    if (header == "confvis/runtime/cluster.hpp") continue;
    // detail/: inline helpers the backends' libraries share (detail::), not the API.
    if (header.find("/detail/") != std::string::npos) continue;
    EXPECT_TRUE(included.count(header)) << "confvis.hpp does not include " << header;
  }
  for (const std::string& header : included)
    EXPECT_TRUE(headers.count(header)) << "confvis.hpp includes " << header << ", no public header";
}

}  // namespace
