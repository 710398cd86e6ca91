#include "read/json_source.hpp"

#include <algorithm>
#include <unordered_set>

namespace lacrima::shotfile {

namespace {

bool isContinuationByte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

void appendUtf8(std::string& out, uint32_t cp) {
  if (cp < 0x80) {
    out += char(cp);
  } else if (cp < 0x800) {
    out += char(0xC0 | (cp >> 6));
    out += char(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += char(0xE0 | (cp >> 12));
    out += char(0x80 | ((cp >> 6) & 0x3F));
    out += char(0x80 | (cp & 0x3F));
  } else {
    out += char(0xF0 | (cp >> 18));
    out += char(0x80 | ((cp >> 12) & 0x3F));
    out += char(0x80 | ((cp >> 6) & 0x3F));
    out += char(0x80 | (cp & 0x3F));
  }
}

// nlohmann's what(): "[json.exception.parse_error.101] parse error at line 3, column 8: <detail>".
// Keeps <detail>; lacrima prints its own line and column (computed from the byte offset).
std::string parseErrorDetail(const std::string& what) {
  const size_t column = what.find("column ");
  if (column != std::string::npos) {
    const size_t colon = what.find(": ", column);
    if (colon != std::string::npos) return what.substr(colon + 2);
  }
  const size_t bracket = what.find("] ");
  return bracket == std::string::npos ? what : what.substr(bracket + 2);
}

}  // namespace

std::string childPointer(const std::string& parent, const std::string& key) {
  std::string out = parent + "/";
  for (char c : key) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
  return out;
}

std::string childPointer(const std::string& parent, size_t index) { return parent + "/" + std::to_string(index); }

// Walks text that nlohmann has already accepted, recording where values and keys start.
// Defensive against running off the end, since it never sees invalid text in practice.
class Scanner {
 public:
  explicit Scanner(JsonSource& source) : s_(source.text_), source_(source) {}

  void run() {
    if (s_.compare(0, 3, "\xEF\xBB\xBF") == 0) i_ = 3;  // UTF-8 byte order mark, as nlohmann skips it
    value("", std::string::npos);
  }

 private:
  const std::string& s_;
  JsonSource& source_;
  size_t i_ = 0;

  char peek(size_t ahead = 0) const { return i_ + ahead < s_.size() ? s_[i_ + ahead] : '\0'; }

  void skipSpace() {
    while (i_ < s_.size()) {
      const char c = s_[i_];
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
        ++i_;
      } else if (c == '/' && peek(1) == '/') {
        while (i_ < s_.size() && s_[i_] != '\n') ++i_;
      } else if (c == '/' && peek(1) == '*') {
        const size_t end = s_.find("*/", i_ + 2);
        i_ = end == std::string::npos ? s_.size() : end + 2;
      } else {
        return;
      }
    }
  }

  uint32_t hex4() {
    uint32_t v = 0;
    for (int k = 0; k < 4; ++k) {
      const char c = peek();
      ++i_;
      v <<= 4;
      if (c >= '0' && c <= '9')
        v |= uint32_t(c - '0');
      else if (c >= 'a' && c <= 'f')
        v |= uint32_t(c - 'a' + 10);
      else if (c >= 'A' && c <= 'F')
        v |= uint32_t(c - 'A' + 10);
    }
    return v;
  }

  std::string string() {
    std::string out;
    ++i_;  // opening quote
    while (i_ < s_.size() && s_[i_] != '"') {
      const char c = s_[i_++];
      if (c != '\\') {
        out += c;
        continue;
      }
      const char e = peek();
      ++i_;
      switch (e) {
        case 'b':
          out += '\b';
          break;
        case 'f':
          out += '\f';
          break;
        case 'n':
          out += '\n';
          break;
        case 'r':
          out += '\r';
          break;
        case 't':
          out += '\t';
          break;
        case 'u': {
          uint32_t cp = hex4();
          if (cp >= 0xD800 && cp < 0xDC00 && peek() == '\\' && peek(1) == 'u') {
            i_ += 2;
            const uint32_t low = hex4();
            cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
          }
          appendUtf8(out, cp);
          break;
        }
        default:
          out += e;
          break;  // \" \\ \/
      }
    }
    ++i_;  // closing quote
    return out;
  }

  void value(const std::string& pointer, size_t keyOffset) {
    skipSpace();
    auto& entry = source_.entries_[pointer];
    entry.keyOffset = keyOffset;
    entry.valueOffset = i_;
    const char c = peek();
    if (c == '{') {
      object(pointer);
    } else if (c == '[') {
      array(pointer);
    } else if (c == '"') {
      string();
    } else {
      while (i_ < s_.size() && std::string_view(",}] \t\r\n/").find(s_[i_]) == std::string_view::npos) ++i_;
    }
  }

  void object(const std::string& pointer) {
    ++i_;
    std::unordered_map<std::string, size_t> seen;
    skipSpace();
    if (peek() == '}') {
      ++i_;
      return;
    }
    while (i_ < s_.size()) {
      skipSpace();
      const size_t keyOffset = i_;
      const std::string key = string();
      const std::string child = childPointer(pointer, key);
      skipSpace();
      ++i_;  // ':'
      if (auto [it, inserted] = seen.emplace(key, keyOffset); !inserted) {
        source_.duplicates_.push_back({child, it->second, keyOffset});
        // The later value wins in nlohmann; keep positions pointing at it.
      }
      value(child, keyOffset);
      skipSpace();
      if (peek() == ',') {
        ++i_;
        continue;
      }
      ++i_;  // '}'
      return;
    }
  }

  void array(const std::string& pointer) {
    ++i_;
    skipSpace();
    if (peek() == ']') {
      ++i_;
      return;
    }
    for (size_t index = 0; i_ < s_.size(); ++index) {
      value(childPointer(pointer, index), std::string::npos);
      skipSpace();
      if (peek() == ',') {
        ++i_;
        continue;
      }
      ++i_;  // ']'
      return;
    }
  }
};

JsonSource::JsonSource(std::string text) : text_(std::move(text)) {
  lineStarts_.push_back(0);
  for (size_t i = 0; i < text_.size(); ++i)
    if (text_[i] == '\n') lineStarts_.push_back(i + 1);
}

std::optional<Json> JsonSource::parse() {
  try {
    Json json = Json::parse(text_, nullptr, /*allow_exceptions=*/true, /*ignore_comments=*/true);
    scan();
    return json;
  } catch (const Json::parse_error& e) {
    syntaxError_ = parseErrorDetail(e.what());
    // e.byte is the 1-based index of the last character read: the offending one.
    size_t offset = e.byte > 0 ? e.byte - 1 : 0;
    if (offset >= text_.size()) {
      // End of input: point just after the last character of the last non-empty line.
      offset = text_.size();
      while (offset > 0 && (text_[offset - 1] == '\n' || text_[offset - 1] == '\r' || text_[offset - 1] == ' ' ||
                            text_[offset - 1] == '\t'))
        --offset;
    }
    // nlohmann reports an unexpected string after reading all of it: point at its opening quote.
    if (offset < text_.size() && text_[offset] == '"' &&
        syntaxError_.find("unexpected string literal") != std::string::npos) {
      for (size_t i = offset; i-- > 0;) {
        if (text_[i] != '"') continue;
        size_t backslashes = 0;
        while (i > backslashes && text_[i - 1 - backslashes] == '\\') ++backslashes;
        if (backslashes % 2 == 0) {
          offset = i;
          break;
        }
      }
    }
    syntaxErrorOffset_ = offset;
    return std::nullopt;
  } catch (const Json::out_of_range& e) {
    // A number too large for a double ("1e999"), found by tools/hardening.sh: it escaped as an
    // internal error. nlohmann gives no position: point at the first occurrence of the number.
    syntaxError_ = parseErrorDetail(e.what());
    const size_t quote = syntaxError_.find('\'');
    const std::string number =
        quote == std::string::npos ? "" : syntaxError_.substr(quote + 1, syntaxError_.size() - quote - 2);
    const size_t at = number.empty() ? std::string::npos : text_.find(number);
    syntaxErrorOffset_ = at == std::string::npos ? 0 : at;
    return std::nullopt;
  }
}

void JsonSource::scan() {
  entries_.clear();
  duplicates_.clear();
  Scanner(*this).run();
}

TextPosition JsonSource::positionOf(size_t byteOffset) const {
  byteOffset = std::min(byteOffset, text_.size());
  const auto it = std::upper_bound(lineStarts_.begin(), lineStarts_.end(), byteOffset);
  const size_t lineIndex = size_t(it - lineStarts_.begin()) - 1;
  int column = 1;
  for (size_t i = lineStarts_[lineIndex]; i < byteOffset; ++i)
    if (!isContinuationByte(text_[i])) ++column;
  return {int(lineIndex) + 1, column};
}

TextPosition JsonSource::valuePosition(const std::string& pointer) const {
  const auto it = entries_.find(pointer);
  if (it == entries_.end() || it->second.valueOffset == std::string::npos) return {};
  return positionOf(it->second.valueOffset);
}

TextPosition JsonSource::keyPosition(const std::string& pointer) const {
  const auto it = entries_.find(pointer);
  if (it == entries_.end()) return {};
  return positionOf(it->second.keyOffset != std::string::npos ? it->second.keyOffset : it->second.valueOffset);
}

std::string JsonSource::excerpt(TextPosition position) const {
  if (position.line <= 0 || size_t(position.line) > lineStarts_.size()) return "";
  const size_t begin = lineStarts_[size_t(position.line) - 1];
  size_t end = text_.find('\n', begin);
  if (end == std::string::npos) end = text_.size();
  if (end > begin && text_[end - 1] == '\r') --end;

  // Split into code points so that the caret lands under the right character.
  std::vector<std::string> chars;
  for (size_t i = begin; i < end; ++i) {
    if (!isContinuationByte(text_[i]) || chars.empty())
      chars.emplace_back(1, text_[i] == '\t' ? ' ' : text_[i]);
    else
      chars.back() += text_[i];
  }
  const size_t kMaxWidth = 100;
  const size_t caret = size_t(std::max(position.column, 1)) - 1;
  size_t first = 0, last = chars.size();
  if (chars.size() > kMaxWidth) {
    first = caret > kMaxWidth / 2 ? std::min(caret - kMaxWidth / 2, chars.size() - kMaxWidth) : 0;
    last = first + kMaxWidth;
  }
  std::string line = first > 0 ? "..." : "";
  for (size_t i = first; i < last; ++i) line += chars[i];
  if (last < chars.size()) line += "...";
  const size_t caretColumn = caret - first + (first > 0 ? 3 : 0);
  return "    " + line + "\n    " + std::string(caretColumn, ' ') + "^";
}

}  // namespace lacrima::shotfile
