#pragma once
// The CSV every table of ours is written and read with (RFC 4180 quoting): a field holding a
// comma, a quote or a line break is quoted, quotes doubled; line breaks inside fields become
// spaces so one row stays one line.
#include <optional>
#include <string>
#include <vector>

namespace springcheck {

std::string csvField(const std::string& text);
std::string csvLine(const std::vector<std::string>& fields);  // no line ending
// The fields of one line, or nothing if its quotes do not balance (a row cut short).
std::optional<std::vector<std::string>> parseCsvLine(const std::string& line);

}  // namespace springcheck
