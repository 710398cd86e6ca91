#include "read/shot_checker.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <climits>
#include <cmath>

#include "read/suggest.hpp"

namespace lacrima::shotfile {

namespace {

std::string found(const Json& v) { return "found " + describeValue(v); }

bool isIntegral(const Json& v) {
  if (v.is_number_integer()) return true;  // signed or unsigned
  if (!v.is_number_float()) return false;
  const double d = v.get<double>();
  return std::isfinite(d) && d == std::floor(d);
}

}  // namespace

// ---- Checker -------------------------------------------------------------------------------

void Checker::error(const std::string& pointer, Anchor anchor, const std::string& message) {
  const TextPosition p = anchor == Anchor::Key ? source_.keyPosition(pointer) : source_.valuePosition(pointer);
  Diagnostic d;
  d.file = file_;
  d.jsonPath = pointer;
  d.line = p.line;
  d.column = p.column;
  d.message = message;
  const std::string excerpt = source_.excerpt(p);
  if (!excerpt.empty()) d.message += "\n" + excerpt;
  diagnostics_.push_back(std::move(d));
}

Diagnostic Checker::warning(const std::string& pointer, Anchor anchor, const std::string& message) const {
  const TextPosition p = anchor == Anchor::Key ? source_.keyPosition(pointer) : source_.valuePosition(pointer);
  Diagnostic d;
  d.file = file_;
  d.jsonPath = pointer;
  d.line = p.line;
  d.column = p.column;
  d.message = "warning: " + message;
  return d;
}

void sortByPosition(std::vector<Diagnostic>& diagnostics) {
  std::stable_sort(diagnostics.begin(), diagnostics.end(), [](const Diagnostic& a, const Diagnostic& b) {
    const int la = a.line > 0 ? a.line : INT_MAX, lb = b.line > 0 ? b.line : INT_MAX;
    return la != lb ? la < lb : a.column < b.column;
  });
}

std::vector<Diagnostic> Checker::diagnostics() const {
  std::vector<Diagnostic> sorted = diagnostics_;
  sortByPosition(sorted);
  return sorted;
}

// ---- Range ---------------------------------------------------------------------------------

bool Range::contains(double x) const {
  if (!std::isfinite(x)) return false;
  const bool aboveLo = loOpen ? x > lo : x >= lo;
  const bool belowHi = hiOpen ? x < hi : x <= hi;
  return aboveLo && belowHi;
}

std::string Range::bound() const {
  const bool hasLo = std::isfinite(lo), hasHi = std::isfinite(hi);
  if (hasLo && hasHi) return fmt::format("in {}{}, {}{}", loOpen ? "(" : "[", lo, hi, hiOpen ? ")" : "]");
  if (hasLo) return fmt::format("{} {}", loOpen ? ">" : ">=", lo);
  if (hasHi) return fmt::format("{} {}", hiOpen ? "<" : "<=", hi);
  return "";
}

std::string Range::describe(bool integer) const {
  const std::string kind = integer ? "an integer" : "a number";
  const std::string b = bound();
  return b.empty() ? kind : kind + " " + b;
}

std::string describeValue(const Json& v) {
  switch (v.type()) {
    case Json::value_t::object:
      return v.empty() ? "an empty object" : "an object";
    case Json::value_t::array:
      return v.empty() ? "an empty array" : fmt::format("an array of {} element{}", v.size(), v.size() == 1 ? "" : "s");
    case Json::value_t::string: {
      const std::string s = v.get<std::string>();
      if (s.size() > 60) return Json(s.substr(0, 57) + "...").dump();
      return v.dump();
    }
    default:
      return v.dump();  // numbers, true, false, null
  }
}

// ---- single values -------------------------------------------------------------------------

std::optional<double> readNumber(Checker& c, const Json& v, const std::string& pointer, Range range) {
  if (!v.is_number()) {
    c.error(pointer, Anchor::Value, fmt::format("expected {}, {}", range.describe(), found(v)));
    return std::nullopt;
  }
  const double x = v.get<double>();
  if (!range.contains(x)) {
    c.error(pointer, Anchor::Value, fmt::format("expected {}, {}", range.describe(), found(v)));
    return std::nullopt;
  }
  return x;
}

std::optional<int64_t> readInteger(Checker& c, const Json& v, const std::string& pointer, Range range) {
  if (!isIntegral(v) || !range.contains(v.get<double>())) {
    c.error(pointer, Anchor::Value, fmt::format("expected {}, {}", range.describe(true), found(v)));
    return std::nullopt;
  }
  const double x = v.get<double>();
  if (x < double(INT_MIN) || x > double(INT_MAX)) {
    c.error(pointer, Anchor::Value,
            fmt::format("expected {}, {} (outside [{}, {}])", range.describe(true), found(v), INT_MIN, INT_MAX));
    return std::nullopt;
  }
  return int64_t(x);
}

std::optional<uint64_t> readUnsigned(Checker& c, const Json& v, const std::string& pointer) {
  if (v.is_number_unsigned()) return v.get<uint64_t>();
  if (v.is_number_integer() && v.get<int64_t>() >= 0) return uint64_t(v.get<int64_t>());
  if (isIntegral(v) && v.get<double>() >= 0.0 && v.get<double>() <= 9007199254740992.0)
    return uint64_t(v.get<double>());
  c.error(pointer, Anchor::Value, "expected an integer >= 0, " + found(v));
  return std::nullopt;
}

std::optional<bool> readBool(Checker& c, const Json& v, const std::string& pointer) {
  if (!v.is_boolean()) {
    c.error(pointer, Anchor::Value, "expected true or false, " + found(v));
    return std::nullopt;
  }
  return v.get<bool>();
}

std::optional<std::string> readString(Checker& c, const Json& v, const std::string& pointer) {
  if (!v.is_string() || v.get<std::string>().empty()) {
    c.error(pointer, Anchor::Value, "expected a non-empty string, " + found(v));
    return std::nullopt;
  }
  return v.get<std::string>();
}

namespace {

// An array of n numbers, each in `component`; shape names it in messages ("[x, y, z]").
std::optional<std::vector<float>> readNumbers(Checker& c, const Json& v, const std::string& pointer, size_t n,
                                              Range component, const char* shape) {
  const std::string bound = component.bound();
  const std::string expectation =
      fmt::format("{} (an array of {} numbers{})", shape, n, bound.empty() ? "" : ", each " + bound);
  if (!v.is_array() || v.size() != n) {
    c.error(pointer, Anchor::Value, fmt::format("expected {}, {}", expectation, found(v)));
    return std::nullopt;
  }
  std::vector<float> out;
  bool ok = true;
  for (size_t i = 0; i < n; ++i) {
    const auto x = readNumber(c, v[i], childPointer(pointer, i), component);
    if (x)
      out.push_back(float(*x));
    else
      ok = false;
  }
  if (!ok) return std::nullopt;
  return out;
}

}  // namespace

std::optional<Vec3> readVec3(Checker& c, const Json& v, const std::string& pointer, Range component,
                             const char* shape) {
  const auto xs = readNumbers(c, v, pointer, 3, component, shape);
  if (!xs) return std::nullopt;
  return Vec3((*xs)[0], (*xs)[1], (*xs)[2]);
}

std::optional<Color> readColor(Checker& c, const Json& v, const std::string& pointer, Range component) {
  const auto xs = readNumbers(c, v, pointer, 3, component, "[r, g, b]");
  if (!xs) return std::nullopt;
  return Color((*xs)[0], (*xs)[1], (*xs)[2]);
}

std::optional<Vec2> readVec2(Checker& c, const Json& v, const std::string& pointer, Range component,
                             const char* shape) {
  const auto xs = readNumbers(c, v, pointer, 2, component, shape);
  if (!xs) return std::nullopt;
  return Vec2((*xs)[0], (*xs)[1]);
}

// ---- ObjectReader --------------------------------------------------------------------------

ObjectReader::ObjectReader(Checker& c, const Json& value, std::string pointer, std::vector<std::string> allowedKeys)
    : c_(c), value_(&value), pointer_(std::move(pointer)) {
  if (!value.is_object()) {
    c_.error(pointer_, Anchor::Value, "expected an object, " + found(value));
    return;
  }
  ok_ = true;
  for (const auto& item : value.items()) {
    const std::string& key = item.key();
    if (std::find(allowedKeys.begin(), allowedKeys.end(), key) != allowedKeys.end()) continue;
    const std::string closest = closestName(key, allowedKeys);
    const std::string suggestion = didYouMean(key, allowedKeys);
    if (!closest.empty()) suggested_.push_back(closest);
    c_.error(at(key), Anchor::Key,
             suggestion.empty() ? fmt::format("unknown key '{}' (allowed here: {})", key, join(allowedKeys, ", "))
                                : fmt::format("unknown key '{}'{}", key, suggestion));
  }
}

bool ObjectReader::has(const std::string& key) const { return find(key) != nullptr; }

const Json* ObjectReader::find(const std::string& key) const {
  if (!ok_) return nullptr;
  const auto it = value_->find(key);
  return it == value_->end() ? nullptr : &*it;
}

void ObjectReader::missing(const std::string& key, const std::string& expectation) {
  if (std::find(suggested_.begin(), suggested_.end(), key) != suggested_.end()) return;
  c_.error(pointer_, Anchor::Key, fmt::format("missing required key '{}' ({})", key, expectation));
}

void ObjectReader::error(const std::string& key, const std::string& message, Anchor anchor) {
  c_.error(at(key), anchor, message);
}

std::optional<double> ObjectReader::number(const std::string& key, Range range, bool required) {
  const Json* v = find(key);
  if (!v) {
    if (required && ok_) missing(key, range.describe());
    return std::nullopt;
  }
  return readNumber(c_, *v, at(key), range);
}

std::optional<int64_t> ObjectReader::integer(const std::string& key, Range range, bool required) {
  const Json* v = find(key);
  if (!v) {
    if (required && ok_) missing(key, range.describe(true));
    return std::nullopt;
  }
  return readInteger(c_, *v, at(key), range);
}

std::optional<uint64_t> ObjectReader::unsignedInteger(const std::string& key, bool required) {
  const Json* v = find(key);
  if (!v) {
    if (required && ok_) missing(key, "an integer >= 0");
    return std::nullopt;
  }
  return readUnsigned(c_, *v, at(key));
}

std::optional<bool> ObjectReader::boolean(const std::string& key, bool required) {
  const Json* v = find(key);
  if (!v) {
    if (required && ok_) missing(key, "true or false");
    return std::nullopt;
  }
  return readBool(c_, *v, at(key));
}

std::optional<std::string> ObjectReader::string(const std::string& key, bool required) {
  const Json* v = find(key);
  if (!v) {
    if (required && ok_) missing(key, "a non-empty string");
    return std::nullopt;
  }
  return readString(c_, *v, at(key));
}

std::optional<Vec3> ObjectReader::vec3(const std::string& key, bool required, Range component) {
  const Json* v = find(key);
  if (!v) {
    if (required && ok_) missing(key, "[x, y, z]");
    return std::nullopt;
  }
  return readVec3(c_, *v, at(key), component);
}

std::optional<Color> ObjectReader::color(const std::string& key, Range component, bool required) {
  const Json* v = find(key);
  if (!v) {
    if (required && ok_) missing(key, "[r, g, b]");
    return std::nullopt;
  }
  return readColor(c_, *v, at(key), component);
}

}  // namespace lacrima::shotfile
