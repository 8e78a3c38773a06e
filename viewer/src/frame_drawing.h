#pragma once
// One frame of the viewer's window (frame_drawing.cpp).
#include <string>

#include "text.h"
#include "viewer/viewer_session.h"

namespace viewer {

// printf-style formatting of one number, for the window's text.
std::string formatValue(const char* fmt, double v);

// Draws the session's engines side by side, the status band above them and the keys below, into
// the current OpenGL context's width x height framebuffer.
void render(ViewerSession& session, const Text& text, int width, int height,
            const std::string& rate);

}  // namespace viewer
