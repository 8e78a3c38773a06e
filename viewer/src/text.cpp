#include "text.h"

#include <GLFW/glfw3.h>
#include <stb_truetype.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <utility>

namespace viewer {

std::string viewerFontFile() {
  if (const char* env = std::getenv("SPRINGCHECK_VIEWER_FONT"); env && *env) return env;
  return SPRINGCHECK_VIEWER_FONT;
}

bool Text::load(const std::string& font_file, float pixel_height, std::string& error) {
  std::ifstream in(font_file, std::ios::binary);
  const std::vector<unsigned char> font((std::istreambuf_iterator<char>(in)),
                                        std::istreambuf_iterator<char>());
  stbtt_fontinfo info;
  if (font.empty() ||
      !stbtt_InitFont(&info, font.data(), stbtt_GetFontOffsetForIndex(font.data(), 0))) {
    error = font_file +
            ": cannot read a TrueType font (install fonts-dejavu-core, or set "
            "SPRINGCHECK_VIEWER_FONT to a .ttf file)";
    return false;
  }
  std::vector<unsigned char> atlas(kAtlas * kAtlas);
  std::vector<stbtt_bakedchar> baked(kCount);
  if (stbtt_BakeFontBitmap(font.data(), 0, pixel_height, atlas.data(), kAtlas, kAtlas, kFirst,
                           kCount, baked.data()) <= 0) {
    error = font_file + ": the glyphs do not fit the font texture";
    return false;
  }
  int ascent = 0, descent = 0, gap = 0;
  stbtt_GetFontVMetrics(&info, &ascent, &descent, &gap);
  const float scale = stbtt_ScaleForPixelHeight(&info, pixel_height);
  ascent_ = scale * ascent;
  line_height_ = scale * (ascent - descent + gap) + 2;
  glyphs_.clear();
  for (const stbtt_bakedchar& b : baked) {
    glyphs_.push_back(
        {float(b.x0), float(b.y0), float(b.x1), float(b.y1), b.xoff, b.yoff, b.xadvance});
  }
  glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA, kAtlas, kAtlas, 0, GL_ALPHA, GL_UNSIGNED_BYTE,
               atlas.data());
  return true;
}

float Text::width(const std::string& text) const {
  float w = 0;
  for (unsigned char c : text) {
    if (c >= kFirst && c < kFirst + kCount) w += glyphs_[c - kFirst].advance;
  }
  return w;
}

std::vector<std::string> Text::wrap(const std::string& text, float max_width) const {
  std::vector<std::string> lines;
  std::string line;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    std::string word = text.substr(start, end - start);
    // A word wider than a line is cut where it must be (a long path, say).
    while (width(word) > max_width && word.size() > 1) {
      std::size_t fit = word.size() - 1;
      while (fit > 1 && width(word.substr(0, fit)) > max_width) --fit;
      if (!line.empty()) lines.push_back(std::exchange(line, {}));
      lines.push_back(word.substr(0, fit));
      word = word.substr(fit);
    }
    const std::string joined = line.empty() ? word : line + " " + word;
    if (!line.empty() && width(joined) > max_width) {
      lines.push_back(std::exchange(line, word));
    } else {
      line = joined;
    }
    start = end + 1;
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

float Text::draw(float x, float y, const std::string& text, float r, float g, float b) const {
  if (!texture_) return y + line_height_;
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColor3f(r, g, b);
  glBegin(GL_QUADS);
  float pen = x;
  const float baseline = y + ascent_;
  for (unsigned char c : text) {
    if (c < kFirst || c >= kFirst + kCount) continue;
    const Glyph& gl = glyphs_[c - kFirst];
    const float x0 = std::round(pen + gl.xoff), y0 = std::round(baseline + gl.yoff);
    const float x1 = x0 + (gl.x1 - gl.x0), y1 = y0 + (gl.y1 - gl.y0);
    const float s0 = gl.x0 / kAtlas, t0 = gl.y0 / kAtlas, s1 = gl.x1 / kAtlas, t1 = gl.y1 / kAtlas;
    glTexCoord2f(s0, t0);
    glVertex2f(x0, y0);
    glTexCoord2f(s1, t0);
    glVertex2f(x1, y0);
    glTexCoord2f(s1, t1);
    glVertex2f(x1, y1);
    glTexCoord2f(s0, t1);
    glVertex2f(x0, y1);
    pen += gl.advance;
  }
  glEnd();
  glDisable(GL_BLEND);
  glDisable(GL_TEXTURE_2D);
  return y + line_height_;
}

float Text::drawWrapped(float x, float y, const std::string& text, float max_width, float r,
                        float g, float b) const {
  for (const std::string& line : wrap(text, max_width)) y = draw(x, y, line, r, g, b);
  return y;
}

}  // namespace viewer
