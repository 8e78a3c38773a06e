#include "compare/io/npy.h"

#include <filesystem>
#include <fstream>
#include <optional>

#include "compare/io/atomic_file.h"

namespace springcheck {

std::expected<void, std::string> writeNpy(const std::string& path, const std::vector<long>& shape,
                                          const std::vector<double>& data) {
  return writeNpy(path, shape, [&](std::ostream& out) {
    out.write(reinterpret_cast<const char*>(data.data()),
              static_cast<std::streamsize>(data.size() * sizeof(double)));
  });
}

std::expected<void, std::string> writeNpy(const std::string& path, const std::vector<long>& shape,
                                          const std::function<void(std::ostream&)>& write_data) {
  std::string dims;
  for (long d : shape) dims += std::to_string(d) + ", ";
  if (shape.size() > 1) dims.resize(dims.size() - 2);  // (n,) for 1-D, (a, b) otherwise
  std::string header = "{'descr': '<f8', 'fortran_order': False, 'shape': (" + dims + "), }";
  // Magic (6) + version (2) + length (2) + header, padded with spaces to a multiple of 64 and
  // ended by a newline, as the format asks.
  const std::size_t total = 10 + header.size() + 1;
  header.append((64 - total % 64) % 64, ' ');
  header += '\n';
  return writeFileAtomically(path, [&](std::ostream& out) {
    out.write("\x93NUMPY\x01\x00", 8);
    const unsigned short length = static_cast<unsigned short>(header.size());
    const char len_bytes[2] = {static_cast<char>(length & 0xff), static_cast<char>(length >> 8)};
    out.write(len_bytes, 2);
    out.write(header.data(), static_cast<std::streamsize>(header.size()));
    write_data(out);
  });
}

namespace {

// The value of 'key' in the header dict, up to the next comma at depth 0 (the shape's tuple has
// commas inside parentheses).
std::string headerValue(const std::string& header, const std::string& key) {
  std::size_t at = header.find("'" + key + "'");
  if (at == std::string::npos) return "";
  at = header.find(':', at);
  if (at == std::string::npos) return "";
  int depth = 0;
  std::size_t end = at + 1;
  for (; end < header.size(); ++end) {
    const char c = header[end];
    if (c == '(') ++depth;
    if (c == ')') --depth;
    if ((c == ',' && depth == 0) || c == '}') break;
  }
  std::string value = header.substr(at + 1, end - at - 1);
  const auto first = value.find_first_not_of(' ');
  const auto last = value.find_last_not_of(' ');
  return first == std::string::npos ? "" : value.substr(first, last - first + 1);
}

// The header's shape tuple "(a, b, ...)": its extents and their product (at most 2^34 values).
// What is wrong with it, if anything.
std::optional<std::string> parseShape(const std::string& shape_text, std::vector<long>& shape,
                                      std::size_t& count) {
  if (shape_text.size() < 2 || shape_text.front() != '(' || shape_text.back() != ')') {
    return "malformed shape " + shape_text;
  }
  std::string inner = shape_text.substr(1, shape_text.size() - 2);
  for (std::size_t start = 0; start < inner.size();) {
    std::size_t comma = inner.find(',', start);
    if (comma == std::string::npos) comma = inner.size();
    std::string item = inner.substr(start, comma - start);
    item.erase(0, item.find_first_not_of(' '));
    item.erase(item.find_last_not_of(' ') + 1);
    start = comma + 1;
    if (item.empty()) continue;
    if (item.find_first_not_of("0123456789") != std::string::npos || item.size() > 12) {
      return "malformed shape " + shape_text;
    }
    shape.push_back(std::stol(item));
    const auto extent = static_cast<std::size_t>(shape.back());
    if (extent != 0 && count > (std::size_t{1} << 34) / extent) return "array too large";
    count *= extent;
  }
  return std::nullopt;
}

}  // namespace

std::expected<NpyArray, std::string> readNpy(const std::string& path) {
  auto bad = [&](const std::string& why) { return std::unexpected(path + ": " + why); };
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {  // a FIFO would block the reader
    return bad("not a regular file (expected a .npy file)");
  }
  const std::uintmax_t file_size = std::filesystem::file_size(path, ec);
  std::ifstream in(path, std::ios::binary);
  if (!in) return bad("cannot open");
  char magic[8];
  if (!in.read(magic, 8) || std::string(magic, 6) != "\x93NUMPY") {
    return bad("not a .npy file (no \\x93NUMPY magic)");
  }
  const int major = static_cast<unsigned char>(magic[6]);
  if (major < 1 || major > 3) return bad("unknown .npy format version " + std::to_string(major));
  unsigned char len_bytes[4] = {0, 0, 0, 0};
  const int len_size = major == 1 ? 2 : 4;
  if (!in.read(reinterpret_cast<char*>(len_bytes), len_size)) return bad("header cut short");
  std::size_t header_length = 0;
  for (int k = len_size - 1; k >= 0; --k) header_length = header_length * 256 + len_bytes[k];
  if (header_length > 65536) return bad("header longer than 64 KiB");
  std::string header(header_length, ' ');
  if (!in.read(header.data(), static_cast<std::streamsize>(header_length))) {
    return bad("header cut short");
  }
  const std::string descr = headerValue(header, "descr");
  if (descr != "'<f8'" && descr != "'<d'") {
    return bad("dtype " + (descr.empty() ? std::string("missing") : descr) +
               ", expected float64 ('<f8')");
  }
  if (headerValue(header, "fortran_order") != "False") {
    return bad("Fortran-order array, expected C order (numpy.save of a C-contiguous array)");
  }
  std::string shape_text = headerValue(header, "shape");
  NpyArray array;
  std::size_t count = 1;
  if (auto why = parseShape(shape_text, array.shape, count)) return bad(*why);
  // The claimed shape against the bytes the file has, before anything is allocated for it.
  const auto data_start = static_cast<std::uintmax_t>(in.tellg());
  if (ec || data_start > file_size || (file_size - data_start) / sizeof(double) < count) {
    return bad("data shorter than its shape " + shape_text + " says (" +
               std::to_string(ec ? 0 : file_size - std::min(file_size, data_start)) +
               " bytes for " + std::to_string(count) + " values)");
  }
  array.data.resize(count);
  if (!in.read(reinterpret_cast<char*>(array.data.data()),
               static_cast<std::streamsize>(count * sizeof(double)))) {
    return bad("data shorter than its shape " + shape_text + " says");
  }
  if (in.peek() != std::char_traits<char>::eof()) {
    return bad("data longer than its shape " + shape_text + " says");
  }
  return array;
}

}  // namespace springcheck
