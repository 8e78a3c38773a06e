#pragma once
#include <expected>
#include <functional>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

namespace springcheck {

// Writes `path` whole or not at all: `body` writes into a temporary file beside it (same folder,
// so the rename cannot cross file systems; named by process and a counter, so two writers never
// share one), the stream is checked after closing, and only then is it renamed over `path`. An
// interrupted run leaves the previous file or the new one, never a part; a failed write (the
// stream, or `body` throwing) says which file and why, and leaves no temporary behind.
[[nodiscard]] std::expected<void, std::string> writeFileAtomically(
    const std::string& path, const std::function<void(std::ostream&)>& body);

// JSON text as springcheck writes it: indented, and with any invalid UTF-8 (a log line, a file
// name) replaced by U+FFFD instead of throwing.
std::string jsonText(const nlohmann::json& value, int indent);

}  // namespace springcheck
