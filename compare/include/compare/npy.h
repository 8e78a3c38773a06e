#pragma once
#include <string>
#include <vector>

namespace springcheck {

// Writes little-endian float64 data as a NumPy .npy file (format 1.0), which numpy.load reads
// with no extra package. `shape` is C order; the product of its entries must be data.size().
[[nodiscard]] bool writeNpy(const std::string& path, const std::vector<long>& shape,
                            const std::vector<double>& data);

}  // namespace springcheck
