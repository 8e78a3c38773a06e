#include "viewer/window.h"

#include <GLFW/glfw3.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "bitmap_font.h"
#include "mysim/cloth_mesh.h"
#include "mysim/particle_system.h"
#include "png_writer.h"

namespace viewer {
namespace {

struct WindowState {
  ViewerSession* session = nullptr;
  bool dragging = false;
  double last_x = 0, last_y = 0;
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
  if (c) ws->session->handleKey(c);
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

void drawSphere(const mysim::Sphere& sphere) {
  const int slices = 32, stacks = 16;
  glColor3f(0.55f, 0.6f, 0.7f);
  for (int i = 0; i < stacks; ++i) {
    const double a0 = M_PI * i / stacks, a1 = M_PI * (i + 1) / stacks;
    glBegin(GL_QUAD_STRIP);
    for (int j = 0; j <= slices; ++j) {
      const double b = 2 * M_PI * j / slices;
      for (double a : {a0, a1}) {
        const Eigen::Vector3d n(std::sin(a) * std::cos(b), std::cos(a), std::sin(a) * std::sin(b));
        glNormal3d(n.x(), n.y(), n.z());
        const Eigen::Vector3d p = sphere.center + sphere.radius * n;
        glVertex3d(p.x(), p.y(), p.z());
      }
    }
    glEnd();
  }
}

void drawEngine(const ViewerSession& session, const EngineView& e) {
  if (!e.system) return;
  const auto rows = e.system->particleRows(e.state);
  const mysim::ParticleSystem* ps = e.system->particles();
  if (!ps) {  // the circle: the exact orbit and the point
    glDisable(GL_LIGHTING);
    glColor3f(0.5f, 0.5f, 0.5f);
    glBegin(GL_LINE_LOOP);
    for (int k = 0; k < 128; ++k)
      glVertex3d(std::cos(2 * M_PI * k / 128), std::sin(2 * M_PI * k / 128), 0);
    glEnd();
    glPointSize(10);
    glColor3f(1.0f, 0.8f, 0.2f);
    glBegin(GL_POINTS);
    glVertex3d(rows(0, 0), rows(0, 1), 0);
    glEnd();
    return;
  }
  const mysim::Model& model = ps->model();
  if (model.sphere) {
    glEnable(GL_LIGHTING);
    drawSphere(*model.sphere);
  }
  if (model.grid && session.shaded()) {
    mysim::Vector x(3 * rows.rows());
    for (int p = 0; p < rows.rows(); ++p) x.segment<3>(3 * p) = rows.row(p).head<3>().transpose();
    const std::vector<mysim::Vec3> normals = mysim::vertexNormals(*model.grid, x);
    glEnable(GL_LIGHTING);
    glColor3f(0.85f, 0.35f, 0.25f);
    glBegin(GL_TRIANGLES);
    for (const Eigen::Vector3i& t : mysim::gridTriangles(*model.grid)) {
      for (int k = 0; k < 3; ++k) {
        glNormal3d(normals[t[k]].x(), normals[t[k]].y(), normals[t[k]].z());
        glVertex3d(rows(t[k], 0), rows(t[k], 1), rows(t[k], 2));
      }
    }
    glEnd();
  } else {
    glDisable(GL_LIGHTING);
    glBegin(GL_LINES);
    for (const mysim::Spring& s : model.springs) {
      switch (s.family) {
        case mysim::SpringFamily::Shear:
          glColor3f(0.4f, 0.7f, 1.0f);
          break;
        case mysim::SpringFamily::Flex:
          glColor3f(0.5f, 0.9f, 0.5f);
          break;
        default:
          glColor3f(0.95f, 0.95f, 0.95f);
      }
      glVertex3d(rows(s.i, 0), rows(s.i, 1), rows(s.i, 2));
      glVertex3d(rows(s.j, 0), rows(s.j, 1), rows(s.j, 2));
    }
    glEnd();
  }
  glDisable(GL_LIGHTING);
  glPointSize(model.grid ? 3 : 7);
  glBegin(GL_POINTS);
  for (int p = 0; p < rows.rows(); ++p) {
    if (model.grid && session.shaded() && !model.pinned[p]) continue;
    if (model.pinned[p]) {
      glColor3f(1.0f, 0.2f, 0.2f);
    } else {
      glColor3f(1.0f, 0.85f, 0.3f);
    }
    glVertex3d(rows(p, 0), rows(p, 1), rows(p, 2));
  }
  glEnd();
}

// Text in window pixels (origin top left), 2 screen pixels per font pixel.
void drawText(double x, double y, const std::string& text, float r = 1, float g = 1, float b = 1) {
  const double scale = 2.0;
  glColor3f(r, g, b);
  glBegin(GL_QUADS);
  for (std::size_t i = 0; i < text.size(); ++i) {
    const std::uint8_t* rows = glyph(text[i]);
    for (int row = 0; row < 7; ++row) {
      for (int col = 0; col < 5; ++col) {
        if (!(rows[row] & (0x10 >> col))) continue;
        const double px = x + (6 * i + col) * scale, py = y + row * scale;
        glVertex2d(px, py);
        glVertex2d(px + scale, py);
        glVertex2d(px + scale, py + scale);
        glVertex2d(px, py + scale);
      }
    }
  }
  glEnd();
}

std::string format(const char* fmt, double v) {
  char text[64];
  std::snprintf(text, sizeof text, fmt, v);
  return text;
}

void render(ViewerSession& session, int width, int height, double fps) {
  glClearColor(0.12f, 0.13f, 0.16f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const auto& engines = session.engines();
  const int count = std::max<int>(1, engines.size());
  const int view_width = width / count;
  const Camera& cam = session.camera();
  const Eigen::Vector3d target(cam.target[0], cam.target[1], cam.target[2]);
  const Eigen::Vector3d eye =
      target + cam.distance * Eigen::Vector3d(std::cos(cam.pitch) * std::sin(cam.yaw),
                                              std::sin(cam.pitch),
                                              std::cos(cam.pitch) * std::cos(cam.yaw));
  for (int i = 0; i < static_cast<int>(engines.size()); ++i) {
    glViewport(i * view_width, 0, view_width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    const double near = 0.01, top = near * std::tan(0.4), aspect = double(view_width) / height;
    glFrustum(-top * aspect, top * aspect, -top, top, near, 100.0);
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
  glColor3f(0.4f, 0.4f, 0.45f);
  glBegin(GL_LINES);
  for (int i = 1; i < count; ++i) {
    glVertex2d(i * view_width, 0);
    glVertex2d(i * view_width, height);
  }
  glEnd();
  std::string top = session.scene().name + "  t " + format("%.2f", session.time()) + " s  " +
                    session.integrator() + "  dt " + format("%.4g", session.dt()) + " s  " +
                    format("%.0f fps", fps);
  if (session.speed() < 0.99) top += "  slow motion x" + format("%.2f", session.speed());
  if (session.paused()) top += "  paused";
  if (session.wind()) top += "  wind";
  if (session.swing()) top += "  swing";
  drawText(10, 10, top);
  std::string metrics;
  if (auto d = session.engineDistance())
    metrics += "engine distance rms " + format("%.3g m", *d) + "  ";
  if (auto p = session.penetration()) metrics += "penetration " + format("%.3g mm", 1e3 * *p);
  drawText(10, 30, metrics, 0.8f, 0.9f, 1.0f);
  for (int i = 0; i < static_cast<int>(engines.size()); ++i) {
    const EngineView& e = engines[i];
    const double x = i * view_width + 10;
    drawText(x, 56, e.engine, 1.0f, 0.85f, 0.4f);
    if (!e.refused.empty()) {
      drawText(x, 74,
               "refused: " + e.refused.substr(e.refused.rfind(": ") + 2).substr(0, view_width / 12),
               1, 0.5f, 0.5f);
      continue;
    }
    if (auto en = session.energy(e)) drawText(x, 74, "E " + format("%.5g J", *en));
    drawText(x, 92, "stepping " + format("%.2f ms a frame", 1e3 * e.step_seconds));
    if (e.blowup_time)
      drawText(x, 110, "blow-up at t " + format("%.3f s", *e.blowup_time) + " " + e.blowup_check, 1,
               0.3f, 0.3f);
  }
  drawText(10, height - 22,
           "t scene d wind s swing w shade/springs r reset i integrator space pause . step, "
           "drag/wheel: camera",
           0.7f, 0.7f, 0.7f);
}

}  // namespace

int runWindow(ViewerSession& session, const WindowOptions& options) {
  if (!glfwInit()) {
    std::cerr << "error: cannot open a window (no display? run under xvfb-run for a headless "
                 "machine)\n";
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
  GLFWwindow* window =
      glfwCreateWindow(options.width, options.height, "springcheck view", nullptr, nullptr);
  if (!window) {
    std::cerr << "error: cannot create an OpenGL 2.1 window\n";
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(options.frames > 0 ? 0 : 1);
  WindowState ws{&session};
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

  using Clock = std::chrono::steady_clock;
  auto last = Clock::now();
  double fps = 0.0;
  int frame = 0;
  while (!glfwWindowShouldClose(window)) {
    const auto now = Clock::now();
    const double elapsed = std::chrono::duration<double>(now - last).count();
    last = now;
    fps = elapsed > 0 ? 0.9 * fps + 0.1 / elapsed : fps;
    // Headless runs advance a fixed 1/60 s a frame, so a screenshot does not depend on the speed
    // of the machine; interactive runs follow the clock.
    session.advance(options.frames > 0 ? 1.0 / 60 : elapsed, options.frames > 0 ? 1e9 : 0.03);
    int width = 0, height = 0;
    glfwGetFramebufferSize(window, &width, &height);
    render(session, width, height, fps);
    ++frame;
    if (options.frames > 0 && frame >= options.frames) {
      if (!options.screenshot.empty()) {
        std::vector<std::uint8_t> pixels(3L * width * height), flipped(pixels.size());
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
        for (int y = 0; y < height; ++y) {
          std::copy_n(pixels.begin() + 3L * width * (height - 1 - y), 3L * width,
                      flipped.begin() + 3L * width * y);
        }
        if (!writePng(options.screenshot, width, height, flipped)) {
          std::cerr << "error: cannot write " << options.screenshot << '\n';
          glfwDestroyWindow(window);
          glfwTerminate();
          return 1;
        }
      }
      std::printf("view: %d frames, %.1f frames/s\n", frame, fps);
      break;
    }
    glfwSwapBuffers(window);
    glfwPollEvents();
  }
  glfwDestroyWindow(window);
  glfwTerminate();
  return 0;
}

}  // namespace viewer
