#pragma once
// Collecting shot-file problems and reading typed values while checking them. Every reader
// reports what it expected and what it found at the value's JSON pointer and text position,
// and returns nullopt on a problem so that checking goes on and every problem is reported.
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "read/json_source.hpp"
#include "lacrima/base/math.hpp"
#include "lacrima/scenes/shot.hpp"

namespace lacrima::shotfile {

// Where a problem is shown in the text: at the member's key, or at its value.
enum class Anchor { Key, Value };

class Checker {
 public:
  Checker(std::filesystem::path file, const JsonSource& source) : file_(std::move(file)), source_(source) {}

  void error(const std::string& pointer, Anchor anchor, const std::string& message);
  // A diagnostic that does not stop the shot: "warning: " + message, without the excerpt.
  Diagnostic warning(const std::string& pointer, Anchor anchor, const std::string& message) const;
  size_t errorCount() const { return diagnostics_.size(); }
  // Sorted by position in the file (problems without a position last), then by discovery.
  std::vector<Diagnostic> diagnostics() const;

  const JsonSource& source() const { return source_; }

 private:
  std::filesystem::path file_;
  const JsonSource& source_;
  std::vector<Diagnostic> diagnostics_;
};

// Sorted by position in the file (problems without a position last), then by discovery: the order
// in which problems and warnings are shown, whichever phase of loadShot found them.
void sortByPosition(std::vector<Diagnostic>& diagnostics);

// A closed, open or half-open interval of accepted numbers.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool loOpen = false;
  bool hiOpen = false;

  bool contains(double x) const;
  // "a number > 0", "an integer in [1, 16384]", "a number in (1, 3]", "a number"
  std::string describe(bool integer = false) const;
  // The bound alone: ">= 0", "in [0, 1]", "" for any number.
  std::string bound() const;

  static Range any() { return {}; }
  static Range atLeast(double lo) { return {lo, std::numeric_limits<double>::infinity(), false, false}; }
  static Range above(double lo) { return {lo, std::numeric_limits<double>::infinity(), true, false}; }
  static Range closed(double lo, double hi) { return {lo, hi, false, false}; }
  static Range open(double lo, double hi) { return {lo, hi, true, true}; }
  static Range openClosed(double lo, double hi) { return {lo, hi, true, false}; }
};

// How a found value is shown in a message: 5, -4, 1.5, "text", true, null, an object, an array of 2 elements.
std::string describeValue(const Json& value);

// Readers of single values (no key involved).
std::optional<double> readNumber(Checker& c, const Json& v, const std::string& pointer, Range range);
std::optional<int64_t> readInteger(Checker& c, const Json& v, const std::string& pointer, Range range);
std::optional<uint64_t> readUnsigned(Checker& c, const Json& v, const std::string& pointer);
std::optional<bool> readBool(Checker& c, const Json& v, const std::string& pointer);
std::optional<std::string> readString(Checker& c, const Json& v, const std::string& pointer);
// [x, y, z]; every component in `component`.
std::optional<Vec3> readVec3(Checker& c, const Json& v, const std::string& pointer, Range component = Range::any(),
                             const char* shape = "[x, y, z]");
std::optional<Color> readColor(Checker& c, const Json& v, const std::string& pointer, Range component);
std::optional<Vec2> readVec2(Checker& c, const Json& v, const std::string& pointer, Range component, const char* shape);

// An object with a fixed set of allowed keys. The constructor reports a value that is not an
// object and every unknown key (with the closest allowed key).
class ObjectReader {
 public:
  ObjectReader(Checker& c, const Json& value, std::string pointer, std::vector<std::string> allowedKeys);

  bool ok() const { return ok_; }
  bool has(const std::string& key) const;
  const Json* find(const std::string& key) const;
  std::string pointer() const { return pointer_; }
  std::string at(const std::string& key) const { return childPointer(pointer_, key); }
  Checker& checker() const { return c_; }

  // Reports "missing required key 'key' (expectation)" at this object, unless an unknown key
  // of this object was already reported as a probable typo of it.
  void missing(const std::string& key, const std::string& expectation);
  // Reports a problem at a member (at its value unless anchor says otherwise).
  void error(const std::string& key, const std::string& message, Anchor anchor = Anchor::Value);

  // Typed members. With required = true a missing member is reported; otherwise nullopt
  // means "absent or invalid" (invalid ones are reported).
  std::optional<double> number(const std::string& key, Range range, bool required = false);
  std::optional<int64_t> integer(const std::string& key, Range range, bool required = false);
  std::optional<uint64_t> unsignedInteger(const std::string& key, bool required = false);
  std::optional<bool> boolean(const std::string& key, bool required = false);
  std::optional<std::string> string(const std::string& key, bool required = false);
  std::optional<Vec3> vec3(const std::string& key, bool required = false, Range component = Range::any());
  std::optional<Color> color(const std::string& key, Range component, bool required = false);

 private:
  Checker& c_;
  const Json* value_;
  std::string pointer_;
  bool ok_ = false;
  std::vector<std::string> suggested_;  // allowed keys suggested for unknown keys (typos)
};

}  // namespace lacrima::shotfile
