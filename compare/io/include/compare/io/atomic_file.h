#pragma once
#include <expected>
#include <functional>
#include <ostream>
#include <string>

namespace springcheck {

// Writes `path` whole or not at all: `body` writes into a temporary file beside it (same folder,
// so the rename cannot cross file systems), the stream is checked after closing, and only then
// is it renamed over `path`. An interrupted run leaves the previous file or the new one, never a
// part; a failed write says which file and why, and leaves no temporary behind.
[[nodiscard]] std::expected<void, std::string> writeFileAtomically(
    const std::string& path, const std::function<void(std::ostream&)>& body);

}  // namespace springcheck
