#include "mysim/state_hash.h"

#include <cstdio>
#include <cstring>

namespace mysim {

std::string hashRows(const ParticleRows& rows) {
  std::uint64_t h = 1469598103934665603ULL;
  for (int p = 0; p < rows.rows(); ++p) {
    for (int k = 0; k < 6; ++k) {
      const double v = rows(p, k);
      unsigned char bytes[sizeof v];
      std::memcpy(bytes, &v, sizeof v);
      for (unsigned char b : bytes) {
        h ^= b;
        h *= 1099511628211ULL;
      }
    }
  }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

}  // namespace mysim
