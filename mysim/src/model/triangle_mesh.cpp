#include "mysim/triangle_mesh.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <numbers>
#include <optional>
#include <sstream>

namespace mysim {

TriangleMesh discMesh(double radius, int rings) {
  TriangleMesh mesh;
  mesh.vertices.push_back(Vec3::Zero());
  std::vector<int> previous{0};  // the ring inside, in angle order
  for (int k = 1; k <= rings; ++k) {
    const int count = 6 * k;
    const double r = radius * k / rings;
    std::vector<int> ring;
    for (int j = 0; j < count; ++j) {
      const double angle = 2.0 * std::numbers::pi * j / count;
      ring.push_back(static_cast<int>(mesh.vertices.size()));
      // x = r cos, z = -r sin: counter-clockwise seen from +y.
      mesh.vertices.emplace_back(r * std::cos(angle), 0.0, -r * std::sin(angle));
    }
    if (k == 1) {
      for (int j = 0; j < count; ++j) mesh.triangles.emplace_back(0, ring[j], ring[(j + 1) % count]);
    } else {
      // Zip the two rings: advance along whichever ring's next vertex comes first in angle.
      const int inner = static_cast<int>(previous.size());
      int a = 0, b = 0;  // steps taken on the inner and the outer ring
      while (a < inner || b < count) {
        const double next_inner = (a + 1.0) / inner, next_outer = (b + 1.0) / count;
        if (b < count && (a == inner || next_outer <= next_inner)) {
          mesh.triangles.emplace_back(previous[a % inner], ring[b], ring[(b + 1) % count]);
          ++b;
        } else {
          mesh.triangles.emplace_back(previous[a % inner], ring[b % count], previous[(a + 1) % inner]);
          ++a;
        }
      }
    }
    previous = ring;
  }
  return mesh;
}

std::string TriangleMesh::where(int t) const {
  if (source.empty() || t < 0 || t >= static_cast<int>(lines.size())) return "";
  return source + ":" + std::to_string(lines[t]) + ": ";
}

std::string TriangleMesh::vertexName(int v) const {
  return std::to_string(source.empty() ? v : v + 1);
}

namespace {

// OBJ statements that carry nothing a cloth uses: skipped without a word.
bool ignoredObjStatement(const std::string& tag) {
  static const std::set<std::string> ignored{"vt", "vn", "vp", "o", "g", "s", "mtllib", "usemtl"};
  return tag[0] == '#' || ignored.contains(tag);
}

std::string lineList(const std::vector<int>& lines) {
  std::string text;
  for (std::size_t k = 0; k < lines.size() && k < 10; ++k) {
    text += (k ? ", " : "") + std::to_string(lines[k]);
  }
  if (lines.size() > 10) text += " and " + std::to_string(lines.size() - 10) + " more";
  return text;
}

// One 'f' line: its corners' vertex indices (1-based, or negative: relative to the vertices read
// so far), fanned into triangles. What is wrong with it, if anything.
std::optional<std::string> readFace(std::istringstream& words, int number, TriangleMesh& mesh) {
  std::vector<int> face;
  for (std::string corner; words >> corner;) {
    long index = 0;
    try {
      index = std::stol(corner.substr(0, corner.find('/')));
    } catch (...) {
      return "expected a vertex index in face corner '" + corner + "'";
    }
    const long count = static_cast<long>(mesh.vertices.size());
    if (index < 0) index += count + 1;  // relative to the vertices read so far
    if (index < 1 || index > count) {
      return "face index " + corner + " names no vertex read so far (1.." + std::to_string(count) +
             ")";
    }
    face.push_back(static_cast<int>(index - 1));
  }
  if (face.size() < 3) return "expected a face of three or more vertices";
  for (std::size_t k = 1; k + 1 < face.size(); ++k) {
    mesh.triangles.emplace_back(face[0], face[k], face[k + 1]);
    mesh.lines.push_back(number);
  }
  return std::nullopt;
}

}  // namespace

std::expected<TriangleMesh, std::string> readObjMesh(const std::string& path) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (std::filesystem::is_directory(status)) {
    return std::unexpected(path + ": is a directory, expected an OBJ mesh file");
  }
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    return std::unexpected(path + ": not a regular file (a FIFO or device), expected an OBJ mesh file");
  }
  std::ifstream in(path);
  if (!in) return std::unexpected(path + ": cannot read (the mesh file)");
  TriangleMesh mesh;
  mesh.source = path;
  std::string line;
  int number = 0;
  std::map<std::string, std::vector<int>> unknown;  // statement -> its lines
  auto fail = [&](const std::string& what) {
    return std::unexpected(path + ":" + std::to_string(number) + ": " + what);
  };
  while (std::getline(in, line)) {
    ++number;
    if (number == 1 && line.starts_with("\xEF\xBB\xBF")) line.erase(0, 3);  // UTF-8 BOM
    std::istringstream words(line);
    std::string tag;
    if (!(words >> tag)) continue;
    if (tag == "v") {
      Vec3 v;
      if (!(words >> v.x() >> v.y() >> v.z()) || !v.allFinite()) {
        return fail("expected a vertex, three finite numbers after 'v'");
      }
      mesh.vertices.push_back(v);
    } else if (tag == "f") {
      if (auto wrong = readFace(words, number, mesh)) return fail(*wrong);
    } else if (!ignoredObjStatement(tag)) {
      unknown[clip(tag, 20)].push_back(number);
    }
  }
  if (mesh.triangles.empty()) return std::unexpected(path + ": no faces (f lines): not a mesh");
  for (const auto& [tag, lines] : unknown) {
    mesh.warnings.push_back(path + ": line" + (lines.size() > 1 ? "s " : " ") + lineList(lines) +
                            ": unknown OBJ statement '" + tag + "' skipped");
  }
  return mesh;
}

}  // namespace mysim
