#pragma once
// The text of a JSON file with positions: where each value (and each object key) starts, by JSON
// pointer, so that errors found later in the parsed value can name line and column. nlohmann
// 3.11 does not expose positions, so a small scanner walks the text again after a successful
// parse; it also finds duplicate keys, which nlohmann accepts silently.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace lacrima::shotfile {

using Json = nlohmann::ordered_json;

struct TextPosition {
  int line = 0;    // 1-based, 0 unknown
  int column = 0;  // 1-based in code points, 0 unknown
};

struct DuplicateKey {
  std::string pointer;  // JSON pointer of the key
  size_t firstKeyOffset = 0;
  size_t duplicateKeyOffset = 0;
};

class JsonSource {
 public:
  explicit JsonSource(std::string text);

  const std::string& text() const { return text_; }

  // Parses the text (comments allowed). On a syntax error returns nullopt and sets the error
  // message (nlohmann's explanation) and its byte offset.
  std::optional<Json> parse();
  const std::string& syntaxError() const { return syntaxError_; }
  size_t syntaxErrorOffset() const { return syntaxErrorOffset_; }

  // After a successful parse(): where the value at a pointer starts, and where its key starts
  // (for object members; the value position otherwise). {0, 0} when unknown.
  TextPosition valuePosition(const std::string& pointer) const;
  TextPosition keyPosition(const std::string& pointer) const;
  const std::vector<DuplicateKey>& duplicateKeys() const { return duplicates_; }

  TextPosition positionOf(size_t byteOffset) const;
  // The source line of a position and a caret under its column, each line indented by 4 spaces
  // ("" when the position is unknown). Long lines are cut around the column.
  std::string excerpt(TextPosition position) const;

 private:
  struct Entry {
    size_t keyOffset = std::string::npos;
    size_t valueOffset = std::string::npos;
  };
  std::string text_;
  std::vector<size_t> lineStarts_;
  std::unordered_map<std::string, Entry> entries_;
  std::vector<DuplicateKey> duplicates_;
  std::string syntaxError_;
  size_t syntaxErrorOffset_ = 0;

  void scan();
  friend class Scanner;
};

// "/" + key with '~' and '/' escaped as JSON pointers require.
std::string childPointer(const std::string& parent, const std::string& key);
std::string childPointer(const std::string& parent, size_t index);

}  // namespace lacrima::shotfile
