#pragma once
// The one reader of every JSON input springcheck takes: scenes, tolerance files, sweep specs,
// engines files, and what external engines write. Its guarantees hold for all of them:
//  - a path that is not a regular file is refused as such ("is a directory", "no such file");
//  - every error names the source and the dotted field ("a.json: system.rows: expected ...");
//  - a number beyond the double range (1e400) is refused naming its field, never thrown;
//  - a key given twice in one object is refused (a typo must never fall back silently);
//  - nesting deeper than kMaxJsonDepth is refused as it is read, before anything recurses;
//  - values in messages are shown short (type and at most 40 characters).
#include <expected>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "mysim/types.h"

namespace mysim {

// No input of ours nests deeper than 5; 64 leaves room and keeps any recursion over the value
// (printing it, destroying it) shallow.
constexpr int kMaxJsonDepth = 64;

[[nodiscard]] std::expected<nlohmann::json, std::string> parseJson(const std::string& text,
                                                                   const std::string& source);
// `what` names the expected content in messages ("scene file", "tolerances file").
[[nodiscard]] std::expected<nlohmann::json, std::string> readJsonFile(const std::string& path,
                                                                      const std::string& what);

// A field's error, thrown by FieldReader inside a reader and turned into the error value at the
// reader's edge (readFields), so parsing code reads straight through.
struct FieldError {
  std::string field;
  std::string message;
};
[[noreturn]] void failField(const std::string& field, const std::string& expected,
                            const nlohmann::json& got);
// "type value", at most 40 characters of the value.
std::string describeJson(const nlohmann::json& value);

// Reads the fields of one JSON object, checking each, and refuses keys it was never asked for.
// `path` is the object's dotted field ("" at the top).
class FieldReader {
 public:
  FieldReader(const nlohmann::json& object, std::string path);

  std::string field(const std::string& key) const;
  bool has(const std::string& key);
  const nlohmann::json& raw(const std::string& key);  // required

  double number(const std::string& key);  // finite
  double number(const std::string& key, double fallback);
  double positive(const std::string& key);
  double positive(const std::string& key, double fallback);
  double nonNegative(const std::string& key, double fallback);
  double inRange(const std::string& key, double low, double high);
  long integer(const std::string& key, long low, long high);
  long integer(const std::string& key, long low, long high, long fallback);
  bool boolean(const std::string& key, bool fallback);
  std::string text(const std::string& key);
  std::string text(const std::string& key, const std::string& fallback);
  Vec3 vec3(const std::string& key);
  Vec3 vec3(const std::string& key, const Vec3& fallback);
  Vec3 unitVec3(const std::string& key, const Vec3& fallback);
  // Lists: non-empty, every item checked, items named key[k] in messages.
  std::vector<double> positiveList(const std::string& key);
  std::vector<std::string> textList(const std::string& key);
  // A list of objects, each read by `read(reader, index)`.
  template <typename F>
  void objects(const std::string& key, F read) {
    const nlohmann::json& list = raw(key);
    if (!list.is_array() || list.empty()) failField(field(key), "a non-empty list", list);
    for (std::size_t k = 0; k < list.size(); ++k) {
      FieldReader item(list[k], field(key) + "[" + std::to_string(k) + "]");
      read(item, k);
    }
  }
  FieldReader object(const std::string& key);

  // Call last: any key never asked for is an error.
  void refuseUnknown(const std::string& schema) const;

 private:
  const nlohmann::json& object_;
  std::string path_;
  std::set<std::string> seen_{"$comment"};
};

// Runs `read()` (which may throw FieldError) and turns a FieldError into "SOURCE: FIELD: why".
template <typename T, typename F>
std::expected<T, std::string> readFields(const std::string& source, F read) {
  try {
    return read();
  } catch (const FieldError& e) {
    return std::unexpected(source + ": " + (e.field.empty() ? "(top level)" : e.field) + ": " +
                           e.message);
  }
}

}  // namespace mysim
