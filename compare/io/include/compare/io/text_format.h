#pragma once
// Numbers and lists as springcheck writes and reads them in tables, messages and options: one
// formatter and one splitter for every command and table.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace springcheck {

// `significant` digits, as printf's %g writes them (tables use 10: a value read back and written
// again is the same text; 17 round-trips a double exactly).
std::string formatNumber(double v, int significant = 10);
// The same, or `missing` for no value.
std::string formatNumber(const std::optional<double>& v, int significant,
                         std::string_view missing = "");

// "a,b,,c" -> {"a", "b", "c"}: the comma-separated items of an option, empty ones dropped.
std::vector<std::string> splitList(const std::string& text);

}  // namespace springcheck
