#include "compare/io/progress.h"

namespace springcheck {

Progress::Progress(std::string label, bool terminal)
    : label_(std::move(label)), terminal_(terminal) {}

void Progress::update(int done, int total) {
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double eta = done > 0 ? elapsed * (total - done) / done : 0.0;
  if (terminal_) {
    const int width = 30, filled = total ? width * done / total : width;
    std::fprintf(stderr, "\r%s [%-*s] %d/%d  elapsed %.0f s  ETA %.0f s ", label_.c_str(), width,
                 std::string(filled, '#').c_str(), done, total, elapsed, eta);
    if (done == total) std::fprintf(stderr, "\n");
    return;
  }
  const int decile = total ? 10 * done / total : 10;
  if (decile == last_decile_ && done != total) return;
  last_decile_ = decile;
  std::fprintf(stderr, "%s: %d/%d done, elapsed %.0f s, ETA %.0f s\n", label_.c_str(), done, total,
               elapsed, eta);
}

}  // namespace springcheck
