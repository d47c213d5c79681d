#include "frame_record_spool.hpp"

#include "confvis/base/error.hpp"

namespace confvis::cli {

FrameRecordSpool::FrameRecordSpool() : file_(std::tmpfile()) {
  if (!file_) throw Error(ErrorCode::IoFailure, "cannot create a temporary file for the frame records");
}

void FrameRecordSpool::add(const nlohmann::json& record) {
  const std::string line = record.dump() + "\n";
  if (std::fwrite(line.data(), 1, line.size(), file_.get()) != line.size())
    throw Error(ErrorCode::IoFailure, "cannot write the frame records' temporary file (disk full?)");
  ++count_;
}

std::string FrameRecordSpool::spliceInto(const std::string& text) {
  const std::string quoted = std::string("\"") + kPlaceholder + "\"";
  const std::size_t at = text.find(quoted);
  if (at == std::string::npos) throw Error(ErrorCode::Internal, "report without frame records");
  std::string array;
  if (count_ == 0) {
    array = "[]";
  } else {
    if (std::fflush(file_.get()) != 0 || std::fseek(file_.get(), 0, SEEK_SET) != 0)
      throw Error(ErrorCode::IoFailure, "cannot read back the frame records' temporary file");
    array = "[\n";
    std::string line;
    bool first = true;
    for (int c; (c = std::fgetc(file_.get())) != EOF;) {
      if (c != '\n') {
        line.push_back(static_cast<char>(c));
        continue;
      }
      // An element of an array at depth 1 is printed at an indent of 4.
      const std::string element = nlohmann::json::parse(line).dump(2);
      array += first ? "    " : ",\n    ";
      first = false;
      for (char ch : element) {
        array.push_back(ch);
        if (ch == '\n') array += "    ";
      }
      line.clear();
    }
    array += "\n  ]";
  }
  return text.substr(0, at) + array + text.substr(at + quoted.size());
}

}  // namespace confvis::cli
