#pragma once
// Per-frame report records kept on disk while a long run goes on, so a 10 000-frame walk holds
// no growing list in memory (tools/soak: the in-memory list was ~1.8 KB a frame, most of the
// walk's growth). The records come back, in order, as the pretty-printed JSON array the report
// would have held.
#include <cstdio>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

namespace confvis::cli {

class FrameRecordSpool {
 public:
  FrameRecordSpool();  // an anonymous temporary file; throws Error(Io) when none can be made

  void add(const nlohmann::json& record);
  std::size_t size() const { return count_; }

  // `text`, a report dumped with indent 2, has `placeholder` (a JSON string value at depth 1)
  // replaced by the records' array, exactly as nlohmann::json::dump(2) would print it there.
  static constexpr const char* kPlaceholder = "@@confvis-frame-records@@";
  std::string spliceInto(const std::string& text);

 private:
  struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
  };
  std::unique_ptr<std::FILE, FileCloser> file_;
  std::size_t count_ = 0;
};

}  // namespace confvis::cli
