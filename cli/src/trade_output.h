#pragma once
// What `springcheck trade` writes: the table (one row a setup), the answer as JSON, and the
// answer in words on standard output (docs/trade.md).
#include <nlohmann/json.hpp>
#include <string>

#include "compare/studies/trade.h"

namespace springcheck {

struct TradeReport {
  std::string scene, quantity, unit;
  TradeQuestion question;
  std::string table;  // the path trade.csv is written to
};

std::string tradeTableCsv(const TradeAnswer& a);
nlohmann::json tradeJson(const TradeAnswer& a, const TradeReport& r);
void printTradeAnswer(const TradeAnswer& a, const TradeReport& r);

}  // namespace springcheck
