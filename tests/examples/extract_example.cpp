// Build step of the example tests (tests/examples/examples.cmake): copies one marked code example
// out of a Markdown file or a header comment into a file the tests compile, so the examples that
// integrators read are the code the test suite builds and runs, and cannot drift from it.
//
//   extract_example SOURCE NAME OUTPUT
//
// Markdown: the ```cpp block right after a line `<!-- example: NAME -->`.
// Header:   the comment lines right after a line containing `example: NAME`, each `//   code`
//           (the "//" and three blanks removed) or a bare `//` (a blank line), up to the first
//           other line.
// OUTPUT starts with a #line directive, so a compile error points at the README or header line.
// The build runs it when SOURCE changes. Exit 1 with one message naming the file and the
// example when the marker or the code is missing.
#include <cctype>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

struct Example {
  std::size_t firstLine = 0;  // 1-based line of the example's first code line
  std::vector<std::string> lines;
};

// Returns false with `error` set when the example is missing or malformed.
bool extractMarkdown(const std::vector<std::string>& text, const std::string& name, Example& out,
                     std::string& error) {
  const std::string marker = "<!-- example: " + name + " -->";
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (trimmed(text[i]) != marker) continue;
    std::size_t fence = i + 1;
    while (fence < text.size() && trimmed(text[fence]).empty()) ++fence;
    if (fence == text.size() || trimmed(text[fence]) != "```cpp") {
      error = "the line after the marker is not ```cpp";
      return false;
    }
    for (std::size_t j = fence + 1; j < text.size(); ++j) {
      if (trimmed(text[j]) == "```") {
        out.firstLine = fence + 2;
        out.lines.assign(text.begin() + static_cast<std::ptrdiff_t>(fence + 1),
                         text.begin() + static_cast<std::ptrdiff_t>(j));
        return true;
      }
    }
    error = "the ```cpp block is never closed";
    return false;
  }
  error = "no line '" + marker + "'";
  return false;
}

bool extractComment(const std::vector<std::string>& text, const std::string& name, Example& out,
                    std::string& error) {
  const std::string marker = "example: " + name;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto at = text[i].find(marker);
    if (at == std::string::npos || text[i].rfind("//", 0) != 0) continue;
    const auto after = at + marker.size();  // "example: loop" must not match "example: loop2"
    if (after < text[i].size() && (std::isalnum(static_cast<unsigned char>(text[i][after])) ||
                                   text[i][after] == '_'))
      continue;
    out.firstLine = i + 2;
    for (std::size_t j = i + 1; j < text.size(); ++j) {
      const std::string& line = text[j];
      if (line.rfind("//   ", 0) == 0) out.lines.push_back(line.substr(5));
      else if (trimmed(line) == "//") out.lines.emplace_back();
      else break;
    }
    while (!out.lines.empty() && trimmed(out.lines.back()).empty()) out.lines.pop_back();
    if (out.lines.empty()) {
      error = "no '//   code' lines follow the marker";
      return false;
    }
    return true;
  }
  error = "no comment line with '" + marker + "'";
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: extract_example SOURCE NAME OUTPUT\n");
    return 2;
  }
  const std::string source = argv[1], name = argv[2], output = argv[3];
  std::ifstream in(source);
  if (!in) {
    std::fprintf(stderr, "extract_example: cannot read %s\n", source.c_str());
    return 1;
  }
  std::vector<std::string> text;
  for (std::string line; std::getline(in, line);) text.push_back(line);

  Example example;
  std::string error;
  const bool found = endsWith(source, ".md") ? extractMarkdown(text, name, example, error)
                                             : extractComment(text, name, example, error);
  if (!found) {
    std::fprintf(stderr, "extract_example: %s: example '%s': %s\n", source.c_str(), name.c_str(),
                 error.c_str());
    return 1;
  }
  std::ostringstream code;
  code << "#line " << example.firstLine << " \"" << source << "\"\n";
  for (const std::string& line : example.lines) code << line << '\n';

  const std::string temporary = output + ".tmp";
  {
    std::ofstream out(temporary, std::ios::trunc);
    out << code.str();
    if (!out.flush()) {
      std::fprintf(stderr, "extract_example: cannot write %s\n", temporary.c_str());
      return 1;
    }
  }
  if (std::rename(temporary.c_str(), output.c_str()) != 0) {
    std::fprintf(stderr, "extract_example: cannot rename %s to %s\n", temporary.c_str(),
                 output.c_str());
    return 1;
  }
  return 0;
}
