#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace viewer {

// Writes 8-bit RGB pixels (rows top to bottom) as a PNG: zlib "stored" (uncompressed) blocks,
// which every PNG reader accepts, so no image library is needed for a screenshot.
[[nodiscard]] bool writePng(const std::string& path, int width, int height,
                            const std::vector<std::uint8_t>& rgb);

}  // namespace viewer
