#include "mysim/model_terms.h"

namespace mysim {
namespace {

using nlohmann::json;

// The object at `key` of `j`, or null when j is not an object or has no such key.
const json& member(const json& j, const char* key) {
  static const json none;
  return j.is_object() && j.contains(key) ? j[key] : none;
}

const json& material(const json& scene) { return member(member(scene, "system"), "material"); }

bool positive(const json& j, const char* key) {
  const json& v = member(j, key);
  return v.is_number() && v.get<double>() > 0.0;
}

}  // namespace

const std::vector<ModelTerm>& modelTerms() {
  static const std::vector<ModelTerm> terms = {
      {"bending", "no bending energy: material.bending {\"model\": \"none\"} (a membrane)",
       [](const json& s) {
         const json& b = member(material(s), "bending");
         // Compared as JSON, never read as a string: the scene is not validated yet.
         return b.is_object() && member(b, "model") != json("none");
       },
       [](json& s) { s["system"]["material"]["bending"] = {{"model", "none"}}; }},
      {"damping", "material.damping_rate 0: no drag settles it",
       [](const json& s) { return positive(material(s), "damping_rate"); },
       [](json& s) { s["system"]["material"].erase("damping_rate"); }},
      {"drag", "forces.drag 0", [](const json& s) { return positive(member(s, "forces"), "drag"); },
       [](json& s) { s["forces"].erase("drag"); }},
      {"wind", "no forces.wind",
       [](const json& s) { return !member(member(s, "forces"), "wind").is_null(); },
       [](json& s) { s["forces"].erase("wind"); }},
      {"pin_motion", "pins held still: no forces.pin_motion",
       [](const json& s) { return !member(member(s, "forces"), "pin_motion").is_null(); },
       [](json& s) { s["forces"].erase("pin_motion"); }},
      {"colliders", "no colliders (and no sphere)",
       [](const json& s) {
         const json& c = member(s, "colliders");
         return (c.is_array() && !c.empty()) || !member(s, "sphere").is_null();
       },
       [](json& s) {
         s.erase("colliders");
         s.erase("sphere");
       }},
  };
  return terms;
}

const ModelTerm* findModelTerm(const std::string& name) {
  for (const ModelTerm& t : modelTerms()) {
    if (t.name == name) return &t;
  }
  return nullptr;
}

std::string modelTermNames() {
  std::string names;
  for (const ModelTerm& t : modelTerms()) names += (names.empty() ? "" : ", ") + t.name;
  return names;
}

}  // namespace mysim
