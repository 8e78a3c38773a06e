#pragma once
#include <cstdint>

namespace viewer {

// A 5 x 7 pixel font (the classic character-LCD shapes) for the on-screen text: the viewer needs
// numbers and short labels, not a font library. Rows top to bottom, bit 4 = leftmost pixel.
// Lower case is drawn as upper case; a character without a glyph is drawn as '?'.
const std::uint8_t* glyph(char c);

}  // namespace viewer
