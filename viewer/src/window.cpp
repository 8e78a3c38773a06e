#include "viewer/window.h"

#include <GLFW/glfw3.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <thread>

#include "frame_drawing.h"
#include "mysim/cloth_surface.h"
#include "mysim/particle_system.h"
#include "png_writer.h"
#include "text.h"

namespace viewer {
namespace {

struct WindowState {
  ViewerSession* session = nullptr;
  bool dragging = false;
  double last_x = 0, last_y = 0;
  bool screenshot_requested = false;  // p: saved after the next frame is drawn
};

void keyCallback(GLFWwindow* window, int key, int, int action, int) {
  if (action != GLFW_PRESS) return;
  auto* ws = static_cast<WindowState*>(glfwGetWindowUserPointer(window));
  if (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_Q) {
    glfwSetWindowShouldClose(window, GLFW_TRUE);
    return;
  }
  char c = 0;
  if (key >= GLFW_KEY_A && key <= GLFW_KEY_Z) c = static_cast<char>('a' + (key - GLFW_KEY_A));
  if (key == GLFW_KEY_SPACE) c = ' ';
  if (key == GLFW_KEY_PERIOD) c = '.';
  if (c == 'p') {
    ws->screenshot_requested = true;
    return;
  }
  // Every key that means something says what it did on the terminal (and the tests read it).
  if (c && ws->session->handleKey(c)) {
    const std::string name = c == ' ' ? "space" : std::string(1, c);
    std::printf("view: key %s: %s%s\n", name.c_str(), ws->session->summary().c_str(),
                ws->session->notice().empty() ? "" : ("; " + ws->session->notice()).c_str());
    std::fflush(stdout);
  }
}

void mouseButtonCallback(GLFWwindow* window, int button, int action, int) {
  auto* ws = static_cast<WindowState*>(glfwGetWindowUserPointer(window));
  if (button == GLFW_MOUSE_BUTTON_LEFT) {
    ws->dragging = action == GLFW_PRESS;
    glfwGetCursorPos(window, &ws->last_x, &ws->last_y);
  }
}

void cursorCallback(GLFWwindow* window, double x, double y) {
  auto* ws = static_cast<WindowState*>(glfwGetWindowUserPointer(window));
  if (!ws->dragging) return;
  Camera& cam = ws->session->camera();
  cam.yaw -= 0.01 * (x - ws->last_x);
  cam.pitch = std::clamp(cam.pitch + 0.01 * (y - ws->last_y), -1.5, 1.5);
  ws->last_x = x;
  ws->last_y = y;
}

void scrollCallback(GLFWwindow* window, double, double dy) {
  auto* ws = static_cast<WindowState*>(glfwGetWindowUserPointer(window));
  ws->session->camera().distance *= std::pow(0.9, dy);
}

// The window's pixels as a PNG (rows flipped: OpenGL reads bottom up).
bool saveScreenshot(const std::string& path, int width, int height) {
  std::vector<std::uint8_t> pixels(3L * width * height), flipped(pixels.size());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
  for (int y = 0; y < height; ++y) {
    std::copy_n(pixels.begin() + 3L * width * (height - 1 - y), 3L * width,
                flipped.begin() + 3L * width * y);
  }
  return writePng(path, width, height, flipped);
}

// p's screenshots: DIR/springcheck-view-NNN.png, the first number not taken.
std::string nextScreenshotPath(const std::string& dir) {
  for (int n = 1;; ++n) {
    char name[64];
    std::snprintf(name, sizeof name, "springcheck-view-%03d.png", n);
    const std::filesystem::path path = std::filesystem::path(dir.empty() ? "." : dir) / name;
    if (!std::filesystem::exists(path)) return path.string();
  }
}

// Input callbacks on the session, and the fixed light of every frame.
void setUpWindow(GLFWwindow* window, WindowState& ws) {
  glfwSetWindowUserPointer(window, &ws);
  glfwSetKeyCallback(window, keyCallback);
  glfwSetMouseButtonCallback(window, mouseButtonCallback);
  glfwSetCursorPosCallback(window, cursorCallback);
  glfwSetScrollCallback(window, scrollCallback);
  glEnable(GL_LIGHT0);
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);  // cloth has two sides
  const float ambient[4] = {0.3f, 0.3f, 0.3f, 1.0f};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glShadeModel(GL_SMOOTH);
  glEnable(GL_NORMALIZE);
}

// p: the next free screenshot name in the folder; says where it went, or that it could not.
void saveRequestedScreenshot(const std::string& dir, int width, int height) {
  const std::string path = nextScreenshotPath(dir);
  if (saveScreenshot(path, width, height)) {
    std::printf("view: saved %s\n", path.c_str());
  } else {
    std::fprintf(stderr, "error: cannot write %s\n", path.c_str());
  }
  std::fflush(stdout);
}

// An OpenGL 2.1 window with its context current, or null (after saying why).
GLFWwindow* openWindow(const WindowOptions& options) {
  if (!glfwInit()) {
    std::cerr << "error: cannot open a window (no display? run under xvfb-run for a headless "
                 "machine)\n";
    return nullptr;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
  GLFWwindow* window =
      glfwCreateWindow(options.width, options.height, "springcheck view", nullptr, nullptr);
  if (!window) {
    std::cerr << "error: cannot create an OpenGL 2.1 window\n";
    glfwTerminate();
    return nullptr;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(options.frames > 0 ? 0 : 1);
  return window;
}

// The status band's rate: frames drawn of those asked for (headless), or frames a second.
std::string rateText(const WindowOptions& options, int frame, double fps) {
  if (options.frames <= 0) return formatValue("%.0f frames/s", fps);
  return "frame " + std::to_string(frame) + " of " + std::to_string(options.frames) +
         " (1/60 s of simulated time each)";
}

}  // namespace

int runWindow(ViewerSession& session, const WindowOptions& options) {
  GLFWwindow* window = openWindow(options);
  if (!window) return 1;
  auto close = [&](int code) {
    glfwDestroyWindow(window);
    glfwTerminate();
    return code;
  };
  Text text;
  if (std::string error; !text.load(viewerFontFile(), 15.0f, error)) {
    std::cerr << "error: " << error << '\n';
    return close(1);
  }
  WindowState ws{&session};
  setUpWindow(window, ws);
  std::printf("view: %s\n", session.summary().c_str());
  std::fflush(stdout);

  using Clock = std::chrono::steady_clock;
  // At most 60 frames a second: a display without vsync (Xvfb, some drivers) would otherwise
  // draw hundreds, spending the cores the engines need.
  const auto frame_period = std::chrono::microseconds(1000000 / 60);
  const auto started = Clock::now();
  auto last = started;
  double fps = 0.0;
  int frame = 0;
  while (!glfwWindowShouldClose(window)) {
    if (options.frames == 0) std::this_thread::sleep_until(last + frame_period);
    const auto now = Clock::now();
    const double elapsed = std::chrono::duration<double>(now - last).count();
    last = now;
    fps = elapsed > 0 ? (fps > 0 ? 0.9 * fps + 0.1 / elapsed : 1.0 / elapsed) : fps;
    // Headless runs advance a fixed 1/60 s a frame, so a screenshot does not depend on the speed
    // of the machine; interactive runs follow the clock.
    session.advance(options.frames > 0 ? 1.0 / 60 : elapsed, options.frames > 0 ? 1e9 : 0.03);
    int width = 0, height = 0;
    glfwGetFramebufferSize(window, &width, &height);
    ++frame;
    render(session, text, width, height, rateText(options, frame, fps));
    if (ws.screenshot_requested) {
      ws.screenshot_requested = false;
      saveRequestedScreenshot(options.screenshot_dir, width, height);
    }
    if (options.frames > 0 && frame >= options.frames) {
      if (!options.screenshot.empty() && !saveScreenshot(options.screenshot, width, height)) {
        std::cerr << "error: cannot write " << options.screenshot << '\n';
        return close(1);
      }
      std::printf("view: %d frames drawn in %.2f s\n", frame,
                  std::chrono::duration<double>(Clock::now() - started).count());
      break;
    }
    glfwSwapBuffers(window);
    glfwPollEvents();
  }
  return close(0);
}

}  // namespace viewer
