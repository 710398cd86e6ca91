#pragma once
// What the flesh's on-disk caches share: raw values in and out of a stream, and files written
// whole or not at all (into a temporary file of this process, renamed into place, so a reader, or
// another farm task writing the same file, never sees half of one).
#include <filesystem>
#include <functional>
#include <istream>
#include <ostream>

namespace lacrima::flesh {

template <typename T>
void put(std::ostream& out, const T& value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof value);
}

template <typename T>
bool get(std::istream& in, T& value) {
  return bool(in.read(reinterpret_cast<char*>(&value), sizeof value));
}

// Writes `file` by `write`; throws std::runtime_error naming the file when it cannot.
void writeFileWhole(const std::filesystem::path& file, const std::function<void(std::ostream&)>& write);

}  // namespace lacrima::flesh
