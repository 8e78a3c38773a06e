#pragma once
// What `springcheck trade` writes: the table (one row a setup), the answer as JSON, and the
// answer in words on standard output (docs/trade.md).
#include <nlohmann/json.hpp>
#include <string>

#include "compare/studies/ablation.h"
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
// The ablation at `where` (the setup's description): each term's change, and what can go.
void printAblation(const Ablation& a, const std::string& where);
nlohmann::json ablationJson(const Ablation& a);

}  // namespace springcheck
