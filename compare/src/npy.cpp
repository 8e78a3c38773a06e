#include "compare/npy.h"

#include <fstream>

namespace springcheck {

bool writeNpy(const std::string& path, const std::vector<long>& shape,
              const std::vector<double>& data) {
  return writeNpy(path, shape, [&](std::ostream& out) {
    out.write(reinterpret_cast<const char*>(data.data()),
              static_cast<std::streamsize>(data.size() * sizeof(double)));
  });
}

bool writeNpy(const std::string& path, const std::vector<long>& shape,
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
  std::ofstream out(path, std::ios::binary);
  out.write("\x93NUMPY\x01\x00", 8);
  const unsigned short length = static_cast<unsigned short>(header.size());
  const char len_bytes[2] = {static_cast<char>(length & 0xff), static_cast<char>(length >> 8)};
  out.write(len_bytes, 2);
  out.write(header.data(), static_cast<std::streamsize>(header.size()));
  write_data(out);
  return static_cast<bool>(out);
}

}  // namespace springcheck
