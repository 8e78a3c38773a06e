#pragma once
#include <expected>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace springcheck {

// Writes little-endian float64 data as a NumPy .npy file (format 1.0), which numpy.load reads
// with no extra package, whole or not at all (writeFileAtomically). `shape` is C order; the
// product of its entries must be data.size().
[[nodiscard]] std::expected<void, std::string> writeNpy(const std::string& path,
                                                        const std::vector<long>& shape,
                                                        const std::vector<double>& data);

// The same, with the data streamed by `write_data` (it must write exactly the shape's count of
// float64 values), so a large trajectory is not copied into one buffer first.
[[nodiscard]] std::expected<void, std::string> writeNpy(
    const std::string& path, const std::vector<long>& shape,
    const std::function<void(std::ostream&)>& write_data);

// A float64 array read from a .npy file.
struct NpyArray {
  std::vector<long> shape;
  std::vector<double> data;  // C order
};

// Reads a .npy file of little-endian float64 ('<f8') in C order, format 1.0, 2.0 or 3.0 (what
// numpy.save writes for float64 arrays). Refuses, naming the file, any other type, a Fortran-
// order array, a malformed header, or data shorter or longer than the shape says.
[[nodiscard]] std::expected<NpyArray, std::string> readNpy(const std::string& path);

}  // namespace springcheck
