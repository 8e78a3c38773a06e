#include "viewer/window.h"

#include <GLFW/glfw3.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <thread>

#include "engine_drawing.h"
#include "mysim/cloth_mesh.h"
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

// Column-major view matrix looking from `eye` at `target`, y up (what gluLookAt builds).
void lookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target) {
  const Eigen::Vector3d f = (target - eye).normalized();
  const Eigen::Vector3d s = f.cross(Eigen::Vector3d::UnitY()).normalized();
  const Eigen::Vector3d u = s.cross(f);
  const double m[16] = {s.x(), u.x(), -f.x(), 0, s.y(), u.y(), -f.y(), 0,
                        s.z(), u.z(), -f.z(), 0, 0,     0,     0,      1};
  glMultMatrixd(m);
  glTranslated(-eye.x(), -eye.y(), -eye.z());
}

std::string format(const char* fmt, double v) {
  char text[64];
  std::snprintf(text, sizeof text, fmt, v);
  return text;
}

// Where each engine's viewport goes: one row for up to three engines, two rows beyond, between
// the status band at the top and the key band at the bottom.
struct Layout {
  int top_band = 0, bottom_band = 0, cols = 1, rows = 1, view_width = 0, view_height = 0;
};

Layout layout(int count, int width, int height, const Text& text) {
  Layout l;
  l.top_band = static_cast<int>(2 * text.lineHeight() + 10);
  l.bottom_band = static_cast<int>(text.lineHeight() + 10);
  l.rows = count > 3 ? 2 : 1;
  l.cols = (count + l.rows - 1) / l.rows;
  l.view_width = width / l.cols;
  l.view_height = std::max(1, (height - l.top_band - l.bottom_band) / l.rows);
  return l;
}

// Frames the camera's view so the scene fits a viewport of any shape: the vertical field of view
// holds for wide viewports, the horizontal one for tall ones.
void projection(double aspect) {
  const double near = 0.01, half = near * std::tan(0.4);
  if (aspect >= 1) {
    glFrustum(-half * aspect, half * aspect, -half, half, near, 100.0);
  } else {
    glFrustum(-half, half, -half / aspect, half / aspect, near, 100.0);
  }
}

void band(double x0, double y0, double x1, double y1) {
  glColor3f(0.08f, 0.085f, 0.1f);
  glBegin(GL_QUADS);
  glVertex2d(x0, y0);
  glVertex2d(x1, y0);
  glVertex2d(x1, y1);
  glVertex2d(x0, y1);
  glEnd();
}

void render(ViewerSession& session, const Text& text, int width, int height,
            const std::string& rate) {
  glClearColor(0.12f, 0.13f, 0.16f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const auto& engines = session.engines();
  const int count = std::max<int>(1, engines.size());
  const Layout l = layout(count, width, height, text);
  const Camera& cam = session.camera();
  const Eigen::Vector3d target(cam.target[0], cam.target[1], cam.target[2]);
  const Eigen::Vector3d eye =
      target + cam.distance * Eigen::Vector3d(std::cos(cam.pitch) * std::sin(cam.yaw),
                                              std::sin(cam.pitch),
                                              std::cos(cam.pitch) * std::cos(cam.yaw));
  auto origin = [&](int i) {  // top left of viewport i, window pixels from the top
    return std::pair{(i % l.cols) * l.view_width, l.top_band + (i / l.cols) * l.view_height};
  };
  for (int i = 0; i < static_cast<int>(engines.size()); ++i) {
    const auto [x, y] = origin(i);
    glViewport(x, height - y - l.view_height, l.view_width, l.view_height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    projection(double(l.view_width) / l.view_height);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    // A headlight: set in eye coordinates, from over the viewer's shoulder, so whatever faces the
    // camera is lit.
    const float light[4] = {0.3f, 0.6f, 1.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    lookAt(eye, target);
    glEnable(GL_DEPTH_TEST);
    drawEngine(session, engines[i]);
  }
  // Overlay in window pixels.
  glViewport(0, 0, width, height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, width, height, 0, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_LIGHTING);
  band(0, 0, width, l.top_band);
  band(0, height - l.bottom_band, width, height);
  // Dividers between viewports only, never across the bands' text.
  glColor3f(0.4f, 0.4f, 0.45f);
  glBegin(GL_LINES);
  for (int i = 0; i < count; ++i) {
    const auto [x, y] = origin(i);
    if (x > 0) {
      glVertex2d(x, y);
      glVertex2d(x, y + l.view_height);
    }
    if (y > l.top_band) {
      glVertex2d(x, y);
      glVertex2d(x + l.view_width, y);
    }
  }
  glEnd();

  std::string top = session.config().scene_name + "    t " + format("%.2f s", session.time()) +
                    "    dt " + format("%.4g s", session.dt()) + "    " + rate;
  if (session.speed() < 0.99) top += "    slow motion x" + format("%.2f", session.speed());
  if (session.paused()) top += "    paused";
  if (session.togglesApply()) {
    top += std::string("    wind ") + (session.wind() ? "on" : "off") + "    swing " +
           (session.swing() ? "on" : "off");
  }
  text.draw(10, 4, top);
  std::string metrics;
  if (auto d = session.engineDistance()) {
    metrics += "RMS distance between the first two engines " + format("%.3g m", *d) + "    ";
  }
  if (auto p = session.penetration()) {
    metrics += "deepest node inside a collider " + format("%.3g mm", 1e3 * *p);
  }
  if (!session.notice().empty()) metrics = session.notice();
  text.draw(10, 4 + text.lineHeight(), metrics, 0.75f, 0.87f, 1.0f);

  for (int i = 0; i < static_cast<int>(engines.size()); ++i) {
    const EngineView& e = engines[i];
    const auto [vx, vy] = origin(i);
    const float x = vx + 10, max_width = l.view_width - 20;
    float y = vy + 6;
    std::string stepped = e.integrator;
    if (e.engine == "mysim" && session.activeIntegrator() != session.integrator()) {
      stepped += " (" + session.integrator() + " needs particles)";
    }
    y = text.drawWrapped(x, y, e.engine + (stepped.empty() ? "" : ": " + stepped), max_width, 1.0f,
                         0.85f, 0.4f);
    if (!e.refused.empty()) {
      text.drawWrapped(x, y, "refused: " + e.refused, max_width, 1.0f, 0.55f, 0.55f);
      continue;
    }
    if (auto en = session.energy(e)) y = text.draw(x, y, "total energy " + format("%.5g J", *en));
    y = text.draw(x, y, "stepping " + format("%.2f ms per frame", 1e3 * e.step_seconds));
    if (e.blowup_time) {
      text.drawWrapped(x, y,
                       "blew up at t " + format("%.3f s", *e.blowup_time) + ": " + e.blowup_check,
                       max_width, 1.0f, 0.35f, 0.35f);
    }
  }
  text.drawWrapped(10, height - l.bottom_band + 5,
                   "t scene   d wind   s swing   w shaded / springs   r reset   i integrator   "
                   "space pause   . step   p screenshot   drag: orbit   wheel: zoom   q quit",
                   width - 20, 0.7f, 0.7f, 0.7f);
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
    const std::string rate = options.frames > 0 ? "frame " + std::to_string(frame) + " of " +
                                                      std::to_string(options.frames) +
                                                      " (1/60 s of simulated time each)"
                                                : format("%.0f frames/s", fps);
    render(session, text, width, height, rate);
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
