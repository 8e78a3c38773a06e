#pragma once
#include <string>

#include "viewer/viewer_session.h"

namespace viewer {

struct WindowOptions {
  int width = 1280;
  int height = 640;
  int frames = 0;          // > 0: run this many frames (1/60 s of simulated time each) and close
  std::string screenshot;  // with frames: save the last frame here as PNG
  std::string screenshot_dir;  // where p saves springcheck-view-NNN.png (default: here)
};

// Opens a window (GLFW, OpenGL 2.1 fixed pipeline, so Mesa's software renderer under Xvfb runs
// it), one viewport per engine with a shared orbit camera, and runs the session: keys go to
// ViewerSession::handleKey, left-drag orbits, the wheel zooms. Returns a process exit code.
int runWindow(ViewerSession& session, const WindowOptions& options);

}  // namespace viewer
