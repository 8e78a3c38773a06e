#pragma once
#include <string>
#include <vector>

namespace viewer {

// Text on screen in a real typeface (DejaVu Sans from Debian's fonts-dejavu-core, rasterised by
// stb_truetype from libstb-dev into one texture at start-up), upper and lower case, so units read
// as written ("ms", "m", "mJ"). Drawn in window pixels, origin top left, in the current OpenGL
// 2.1 context.
class Text {
 public:
  // Reads the font and makes its texture; the message names the file on failure.
  [[nodiscard]] bool load(const std::string& font_file, float pixel_height, std::string& error);
  // Pixels from the top of one line to the top of the next.
  float lineHeight() const { return line_height_; }
  float width(const std::string& text) const;
  // Splits at spaces (and inside a word longer than the width) so no line is wider than
  // `max_width`; a message is shown whole, over as many lines as it needs.
  std::vector<std::string> wrap(const std::string& text, float max_width) const;
  // Draws `text` with its top left at (x, y); returns the y of the next line.
  float draw(float x, float y, const std::string& text, float r = 1, float g = 1,
             float b = 1) const;
  // draw() of every line of wrap(); returns the y below the last.
  float drawWrapped(float x, float y, const std::string& text, float max_width, float r = 1,
                    float g = 1, float b = 1) const;

 private:
  static constexpr int kFirst = 32, kCount = 95, kAtlas = 512;
  struct Glyph {
    float x0, y0, x1, y1;  // in the atlas, pixels
    float xoff, yoff, advance;
  };
  std::vector<Glyph> glyphs_;
  unsigned texture_ = 0;
  float line_height_ = 0, ascent_ = 0;
};

// The font the viewer uses: SPRINGCHECK_VIEWER_FONT if set, else the DejaVu Sans CMake found.
std::string viewerFontFile();

}  // namespace viewer
