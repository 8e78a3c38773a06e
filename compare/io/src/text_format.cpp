#include "compare/io/text_format.h"

#include <sstream>

namespace springcheck {

std::string formatNumber(double v, int significant) {
  std::ostringstream out;  // default floating format: what %.{significant}g writes
  out.precision(significant);
  out << v;
  return out.str();
}

std::string formatNumber(const std::optional<double>& v, int significant,
                         std::string_view missing) {
  return v ? formatNumber(*v, significant) : std::string(missing);
}

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    if (!item.empty()) items.push_back(item);
  }
  return items;
}

}  // namespace springcheck
