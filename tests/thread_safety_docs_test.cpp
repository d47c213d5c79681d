// Every public class and every public struct with member functions states its thread-safety
// (a "Thread-safety:" line in the comment right above it), so an integrator never has to read
// the sources to know whether a backend, a follower or a map may be shared between threads.
#include <gtest/gtest.h>

#include "public_headers.hpp"

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace {

std::string withoutComment(const std::string& line) {
  const std::size_t at = line.find("//");
  return at == std::string::npos ? line : line.substr(0, at);
}

// A member function: a name and an opening parenthesis with no '=' or '{' before it (so not a
// member initialised by a call), ending in ';' or a body.
bool declaresMemberFunction(const std::string& code) {
  static const std::regex function(R"(^\s*[^={]*[~\w>]\s*\([^;]*(\)|,)\s*.*$)");
  static const std::regex declarationEnd(R"([;{,]\s*$|\)\s*$)");
  return std::regex_match(code, function) && std::regex_search(code, declarationEnd) &&
         code.find("return ") == std::string::npos;
}

// Classes and structs defined at namespace scope (column 0) in `header` that need a statement
// and lack one.
std::vector<std::string> undocumentedTypes(const std::filesystem::path& header) {
  std::ifstream in(header);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  static const std::regex definition(R"(^(class|struct)\s+(\w+)[^;]*$)");
  std::vector<std::string> missing;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::smatch match;
    if (!std::regex_match(lines[i], match, definition)) continue;
    bool behaviour = match[1] == "class";
    for (std::size_t k = i + 1; k < lines.size() && lines[k].rfind("};", 0) != 0; ++k)
      behaviour = behaviour || declaresMemberFunction(withoutComment(lines[k]));
    if (!behaviour) continue;
    bool stated = false;
    for (std::size_t j = i; j-- > 0 && lines[j].rfind("//", 0) == 0;)
      stated = stated || lines[j].find("Thread-safety") != std::string::npos;
    if (!stated)
      missing.push_back(header.filename().string() + ":" + std::to_string(i + 1) + " " +
                        match[2].str());
  }
  return missing;
}

TEST(ThreadSafetyDocs, TheCheckFindsAStructWithAMemberFunctionAndNoStatement) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "confvis_thread_safety_probe.hpp";
  std::ofstream(file) << "// A value.\nstruct Plain {\n  int x = 0;  // f(y)\n};\n"
                      << "// A thing.\nstruct Busy {\n  int size() const;\n};\n"
                      << "// Thread-safety: none.\nclass Stated {\n public:\n  void go();\n};\n"
                      << "class Bare {\n};\n";
  const std::vector<std::string> missing = undocumentedTypes(file);
  std::filesystem::remove(file);
  ASSERT_EQ(missing.size(), 2u);
  EXPECT_EQ(missing[0], "confvis_thread_safety_probe.hpp:6 Busy");
  EXPECT_EQ(missing[1], "confvis_thread_safety_probe.hpp:14 Bare");
}

TEST(ThreadSafetyDocs, EveryPublicClassStatesIt) {
  const std::vector<std::filesystem::path> headers = confvis::test::publicHeaders();
  ASSERT_GT(headers.size(), 50u);
  std::string missing;
  for (const std::filesystem::path& header : headers)
    for (const std::string& type : undocumentedTypes(header)) missing += "\n  " + type;
  EXPECT_TRUE(missing.empty()) << "no \"// Thread-safety:\" line above:" << missing;
}

}  // namespace
