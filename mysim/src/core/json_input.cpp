#include "mysim/json_input.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace mysim {
namespace {

using nlohmann::json;

// Builds the value like nlohmann's DOM parser, keeping the dotted path of what it is reading so
// that a duplicate key, a too-deep value or an overflowing number is refused naming its field.
class CheckedSax final : public json::json_sax_t {
 public:
  json result;
  std::string error;  // set on refusal

  bool null() override { return put(json(nullptr)); }
  bool boolean(bool v) override { return put(json(v)); }
  bool number_integer(number_integer_t v) override { return put(json(v)); }
  bool number_unsigned(number_unsigned_t v) override { return put(json(v)); }
  bool number_float(number_float_t v, const string_t&) override { return put(json(v)); }
  bool string(string_t& v) override { return put(json(std::move(v))); }
  bool binary(binary_t&) override { return refuse(path(), "binary data is not JSON"); }
  bool start_object(std::size_t) override { return open(json::object()); }
  bool start_array(std::size_t) override { return open(json::array()); }
  bool key(string_t& k) override {
    json& object = *stack_.back().value;
    if (object.contains(k)) {
      return refuse(path(clip(k)), "given twice in one object (keys must be unique)");
    }
    stack_.back().key = k;
    return true;
  }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t position, const std::string& token,
                   const nlohmann::detail::exception& e) override {
    if (e.id == 406) {  // out_of_range: number overflow
      const std::string field = stack_.empty() ? "(top level)" : path(pendingKey());
      return refuse(field, "expected a number within the double range (about 1.8e308), got " +
                               token.substr(0, 40));
    }
    std::string what = e.what();
    const std::size_t at = what.find("] ");
    if (at != std::string::npos) what = what.substr(at + 2);
    error = "not valid JSON (byte " + std::to_string(position) + "): " + what;
    return false;
  }

 private:
  struct Level {
    json* value;
    std::string key;  // the key being read (objects)
  };

  std::string pendingKey() const { return stack_.empty() ? "" : stack_.back().key; }
  // Dotted path of the current position, optionally with a key appended.
  std::string path(const std::string& last = "") const {
    std::string p;
    for (std::size_t k = 0; k < stack_.size(); ++k) {
      const json& v = *stack_[k].value;
      if (v.is_object()) {
        const std::string& key = k + 1 == stack_.size() && !last.empty() ? last : stack_[k].key;
        if (key.empty()) continue;
        // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on
        // "literal" + std::string temporaries here.
        if (!p.empty()) p += '.';
        p += clip(key, 60);
      } else {
        // The element being read: the last one placed while inside it, else the next.
        p += '[';
        p += std::to_string(k + 1 < stack_.size() ? v.size() - 1 : v.size());
        p += ']';
      }
    }
    return p.empty() ? "(top level)" : p;
  }
  bool refuse(const std::string& field, const std::string& why) {
    error = field + ": " + why;
    return false;
  }
  // Places a finished value into its parent (or as the result).
  json* place(json&& v) {
    if (stack_.empty()) {
      result = std::move(v);
      return &result;
    }
    json& parent = *stack_.back().value;
    if (parent.is_object()) return &(parent[stack_.back().key] = std::move(v));
    parent.push_back(std::move(v));
    return &parent.back();
  }
  bool put(json&& v) {
    place(std::move(v));
    return true;
  }
  bool open(json&& v) {
    if (static_cast<int>(stack_.size()) >= kMaxJsonDepth) {
      return refuse(path(pendingKey()), "nested deeper than " + std::to_string(kMaxJsonDepth) +
                                            " levels (no springcheck input needs more than 5)");
    }
    json* placed = place(std::move(v));
    stack_.push_back({placed, ""});
    return true;
  }
  bool close() {
    stack_.pop_back();
    return true;
  }

  std::vector<Level> stack_;
};

}  // namespace

std::expected<json, std::string> parseJson(const std::string& text, const std::string& source) {
  CheckedSax sax;
  const bool ok = json::sax_parse(text, &sax, json::input_format_t::json, true);  // strict: one value, nothing after it
  if (!ok) return std::unexpected(source + ": " + sax.error);
  return std::move(sax.result);
}

// "a scene file", "an engines file": the article the noun takes.
static std::string withArticle(const std::string& what) {
  const bool vowel = !what.empty() && std::string("aeiou").find(what.front()) != std::string::npos;
  return (vowel ? "an " : "a ") + what;
}

std::expected<json, std::string> readJsonFile(const std::string& path, const std::string& what) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (ec || !fs::exists(status)) {
    return std::unexpected(clip(path, 200) + ": no such file (expected " + withArticle(what) + ")");
  }
  if (fs::is_directory(status)) {
    return std::unexpected(path + ": is a directory (expected " + withArticle(what) + ")");
  }
  if (!fs::is_regular_file(status)) {
    return std::unexpected(path + ": not a regular file (expected " + withArticle(what) + ")");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::unexpected(path + ": cannot open the " + what);
  std::stringstream text;
  text << in.rdbuf();
  return parseJson(text.str(), path);
}

std::string describeJson(const json& value) {
  if (value.is_array()) return "array of " + std::to_string(value.size());
  if (value.is_object()) return "object of " + std::to_string(value.size()) + " keys";
  if (value.is_null()) return "null";
  std::string text = value.dump();
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return std::string(value.type_name()) + " " + text;
}

void failField(const std::string& field, const std::string& expected, const json& got) {
  throw FieldError{field, "expected " + expected + ", got " + describeJson(got)};
}

FieldReader::FieldReader(const json& object, std::string path)
    : object_(object), path_(std::move(path)) {
  if (!object_.is_object()) failField(path_, "an object", object_);
}

std::string FieldReader::field(const std::string& key) const {
  return path_.empty() ? clip(key, 60) : path_ + "." + clip(key, 60);
}

bool FieldReader::has(const std::string& key) {
  seen_.insert(key);
  return object_.contains(key);
}

const json& FieldReader::raw(const std::string& key) {
  if (!has(key)) throw FieldError{field(key), "missing (required)"};
  return object_.at(key);
}

double FieldReader::number(const std::string& key) {
  const json& v = raw(key);
  if (!v.is_number()) failField(field(key), "a number", v);
  const double d = v.get<double>();
  if (!std::isfinite(d)) failField(field(key), "a finite number", v);
  return d;
}
double FieldReader::number(const std::string& key, double fallback) {
  return has(key) ? number(key) : fallback;
}
double FieldReader::positive(const std::string& key) {
  const double d = number(key);
  if (!(d > 0.0)) failField(field(key), "a number > 0", raw(key));
  return d;
}
double FieldReader::positive(const std::string& key, double fallback) {
  return has(key) ? positive(key) : fallback;
}
double FieldReader::nonNegative(const std::string& key, double fallback) {
  if (!has(key)) return fallback;
  const double d = number(key);
  if (d < 0.0) failField(field(key), "a number >= 0", raw(key));
  return d;
}
double FieldReader::inRange(const std::string& key, double low, double high) {
  const double d = number(key);
  if (d < low || d > high) {
    std::ostringstream range;
    range << "a number in [" << low << ", " << high << "]";
    failField(field(key), range.str(), raw(key));
  }
  return d;
}
long FieldReader::integer(const std::string& key, long low, long high) {
  const json& v = raw(key);
  if (!v.is_number_integer() || v.get<long>() < low || v.get<long>() > high ||
      (v.is_number_unsigned() && v.get<unsigned long>() > static_cast<unsigned long>(high))) {
    failField(field(key),
              "an integer in [" + std::to_string(low) + ", " + std::to_string(high) + "]", v);
  }
  return v.get<long>();
}
long FieldReader::integer(const std::string& key, long low, long high, long fallback) {
  return has(key) ? integer(key, low, high) : fallback;
}
bool FieldReader::boolean(const std::string& key, bool fallback) {
  if (!has(key)) return fallback;
  const json& v = raw(key);
  if (!v.is_boolean()) failField(field(key), "true or false", v);
  return v.get<bool>();
}
std::string FieldReader::text(const std::string& key) {
  const json& v = raw(key);
  if (!v.is_string()) failField(field(key), "a string", v);
  return v.get<std::string>();
}
std::string FieldReader::text(const std::string& key, const std::string& fallback) {
  return has(key) ? text(key) : fallback;
}
Vec3 FieldReader::vec3(const std::string& key) {
  const json& v = raw(key);
  if (!v.is_array() || v.size() != 3) failField(field(key), "an array of 3 numbers", v);
  Vec3 out;
  for (int k = 0; k < 3; ++k) {
    if (!v[k].is_number() || !std::isfinite(v[k].get<double>())) {
      failField(field(key) + "[" + std::to_string(k) + "]", "a finite number", v[k]);
    }
    out[k] = v[k].get<double>();
  }
  return out;
}
Vec3 FieldReader::vec3(const std::string& key, const Vec3& fallback) {
  return has(key) ? vec3(key) : fallback;
}
Vec3 FieldReader::unitVec3(const std::string& key, const Vec3& fallback) {
  if (!has(key)) return fallback;
  const Vec3 v = vec3(key);
  if (!(v.norm() >= 1e-12) || !std::isfinite(v.norm())) {
    failField(field(key), "a non-zero, finite direction", raw(key));
  }
  return v.normalized();
}
std::vector<double> FieldReader::positiveList(const std::string& key) {
  const json& list = raw(key);
  if (!list.is_array() || list.empty())
    failField(field(key), "a non-empty list of numbers > 0", list);
  std::vector<double> values;
  for (std::size_t k = 0; k < list.size(); ++k) {
    const json& v = list[k];
    if (!v.is_number() || !std::isfinite(v.get<double>()) || !(v.get<double>() > 0)) {
      failField(field(key) + "[" + std::to_string(k) + "]", "a finite number > 0", v);
    }
    values.push_back(v.get<double>());
  }
  return values;
}
std::vector<std::string> FieldReader::textList(const std::string& key) {
  const json& list = raw(key);
  if (!list.is_array() || list.empty()) failField(field(key), "a non-empty list of names", list);
  std::vector<std::string> values;
  for (std::size_t k = 0; k < list.size(); ++k) {
    if (!list[k].is_string())
      failField(field(key) + "[" + std::to_string(k) + "]", "a name", list[k]);
    values.push_back(list[k].get<std::string>());
  }
  return values;
}
FieldReader FieldReader::object(const std::string& key) {
  return FieldReader(raw(key), field(key));
}

void FieldReader::refuseUnknown(const std::string& schema) const {
  for (auto it = object_.begin(); it != object_.end(); ++it) {
    if (!seen_.count(it.key())) {
      throw FieldError{field(it.key()), "unknown field (see " + schema + " for the schema)"};
    }
  }
}

}  // namespace mysim
