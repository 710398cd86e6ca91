#pragma once
#include <string>

namespace lacrima::shotfile {

// True when the pattern has a frame field: a run of '#', "%d" or "%0<width>d".
bool hasFrameField(const std::string& pattern);

}  // namespace lacrima::shotfile
