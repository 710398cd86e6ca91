// Keyframed values in shot files; see animation_reader.hpp.
#include "read/animation_reader.hpp"

#include <fmt/format.h>

#include "read/suggest.hpp"

namespace lacrima::shotfile {

namespace {

const std::vector<std::string> kInterpolationNames = {"step", "linear", "smooth", "monotone"};

std::optional<Interpolation> readInterpolation(ObjectReader& o) {
  const Json* v = o.find("interpolation");
  if (!v) return Interpolation::MonotoneCubic;
  const auto name = readString(o.checker(), *v, o.at("interpolation"));
  if (!name) return std::nullopt;
  if (*name == "step") return Interpolation::Step;
  if (*name == "linear") return Interpolation::Linear;
  if (*name == "smooth") return Interpolation::CatmullRom;
  if (*name == "monotone") return Interpolation::MonotoneCubic;
  o.error("interpolation", fmt::format("unknown interpolation '{}'{}", *name,
                                       didYouMean(*name, kInterpolationNames).empty()
                                           ? " (expected 'step', 'linear', 'smooth' or 'monotone')"
                                           : didYouMean(*name, kInterpolationNames)));
  return std::nullopt;
}

// Reads every [frame, value] pair with readValue(json, pointer) -> optional<T>; reports frames
// that do not increase. Returns the keys when all of them are valid.
template <typename Key, typename ReadValue>
std::optional<std::vector<Key>> readKeys(ObjectReader& o, ReadValue&& readValue) {
  Checker& c = o.checker();
  const Json* keys = o.find("keys");
  const std::string pointer = o.at("keys");
  if (!keys->is_array() || keys->empty()) {
    c.error(pointer, Anchor::Value, "expected a non-empty array of [frame, value] keys, found " + describeValue(*keys));
    return std::nullopt;
  }
  std::vector<Key> result;
  bool ok = true;
  for (size_t i = 0; i < keys->size(); ++i) {
    const Json& key = (*keys)[i];
    const std::string keyPointer = childPointer(pointer, i);
    if (!key.is_array() || key.size() != 2) {
      c.error(keyPointer, Anchor::Value, "expected a key [frame, value], found " + describeValue(key));
      ok = false;
      continue;
    }
    const auto frame = readNumber(c, key[0], childPointer(keyPointer, size_t(0)), Range::any());
    const auto value = readValue(key[1], childPointer(keyPointer, size_t(1)));
    if (!frame || !value) {
      ok = false;
      continue;
    }
    if (!result.empty() && !(float(*frame) > result.back().time)) {
      c.error(childPointer(keyPointer, size_t(0)), Anchor::Value,
              fmt::format("key frames must increase: frame {} is not after the previous key's frame {}", *frame,
                          result.back().time));
      ok = false;
      continue;
    }
    result.push_back(Key{float(*frame), *value});
  }
  if (!ok) return std::nullopt;
  return result;
}

const char* kKeyedShape = "{\"keys\": [[frame, value], ...], \"interpolation\": ...}";

}  // namespace

bool isKeyed(const Json& v) { return v.is_object(); }

std::optional<AnimatedFloat> readAnimatedNumber(Checker& c, const Json& v, const std::string& pointer, Range range) {
  if (!isKeyed(v)) {
    if (!v.is_number()) {
      c.error(pointer, Anchor::Value,
              fmt::format("expected {} or keys {}, found {}", range.describe(), kKeyedShape, describeValue(v)));
      return std::nullopt;
    }
    const auto x = readNumber(c, v, pointer, range);
    if (!x) return std::nullopt;
    return AnimatedFloat{float(*x), nullptr};
  }
  ObjectReader o(c, v, pointer, {"keys", "interpolation"});
  if (!o.has("keys")) {
    o.missing("keys", "[[frame, value], ...]");
    return std::nullopt;
  }
  const auto interpolation = readInterpolation(o);
  const auto keys = readKeys<ScalarKey>(o, [&](const Json& value, const std::string& p) -> std::optional<float> {
    const auto x = readNumber(c, value, p, range);
    return x ? std::optional<float>(float(*x)) : std::nullopt;
  });
  if (!keys || !interpolation) return std::nullopt;
  AnimatedFloat result;
  result.constant = keys->front().value;
  result.curve = std::make_shared<const ScalarCurve>(*keys, *interpolation);
  return result;
}

std::optional<AnimatedVec3> readAnimatedVec3(Checker& c, const Json& v, const std::string& pointer) {
  if (!isKeyed(v)) {
    const auto x = readVec3(c, v, pointer);
    if (!x) return std::nullopt;
    return AnimatedVec3{*x, nullptr};
  }
  ObjectReader o(c, v, pointer, {"keys", "interpolation"});
  if (!o.has("keys")) {
    o.missing("keys", "[[frame, [x, y, z]], ...]");
    return std::nullopt;
  }
  const auto interpolation = readInterpolation(o);
  const auto keys = readKeys<Vec3Key>(
      o, [&](const Json& value, const std::string& p) { return readVec3(c, value, p); });
  if (!keys || !interpolation) return std::nullopt;
  AnimatedVec3 result;
  result.constant = keys->front().value;
  result.curve = std::make_shared<const Vec3Curve>(*keys, *interpolation);
  return result;
}

}  // namespace lacrima::shotfile
