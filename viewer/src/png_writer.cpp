#include "png_writer.h"

#include <png.h>

#include <cstdio>
#include <filesystem>

namespace viewer {

bool writePng(const std::string& path, int width, int height,
              const std::vector<std::uint8_t>& rgb) {
  if (width <= 0 || height <= 0 || rgb.size() != static_cast<std::size_t>(width) * height * 3) {
    return false;
  }
  const std::string part = path + ".part";
  std::FILE* file = std::fopen(part.c_str(), "wb");
  if (!file) return false;
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(width);
  image.height = static_cast<png_uint_32>(height);
  image.format = PNG_FORMAT_RGB;
  // libpng's simplified API: compressed, filtered, no setjmp needed; a failure is reported.
  const bool written =
      png_image_write_to_stdio(&image, file, 0, rgb.data(), width * 3, nullptr) != 0;
  const bool closed = std::fclose(file) == 0;
  std::error_code error;
  if (!written || !closed) {
    std::filesystem::remove(part, error);
    return false;
  }
  std::filesystem::rename(part, path, error);
  return !error;
}

}  // namespace viewer
