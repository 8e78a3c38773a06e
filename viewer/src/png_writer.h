#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace viewer {

// Writes 8-bit RGB pixels (rows top to bottom) as a compressed PNG with libpng (Debian's
// libpng-dev), whole or not at all: a temporary file renamed into place.
[[nodiscard]] bool writePng(const std::string& path, int width, int height,
                            const std::vector<std::uint8_t>& rgb);

}  // namespace viewer
