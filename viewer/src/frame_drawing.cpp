// One frame of the viewer: every engine in its viewport, the status and key bands, the labels.
#include "frame_drawing.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "engine_drawing.h"

namespace viewer {

std::string formatValue(const char* fmt, double v) {
  char text[64];
  std::snprintf(text, sizeof text, fmt, v);
  return text;
}

namespace {

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

// Top left of viewport i, in window pixels from the top.
std::pair<int, int> viewportOrigin(const Layout& l, int i) {
  return {(i % l.cols) * l.view_width, l.top_band + (i / l.cols) * l.view_height};
}

// Each engine in its viewport, seen from the session's camera.
void drawViewports(ViewerSession& session, const Layout& l, int height) {
  const Camera& cam = session.camera();
  const Eigen::Vector3d target(cam.target[0], cam.target[1], cam.target[2]);
  const Eigen::Vector3d eye =
      target + cam.distance * Eigen::Vector3d(std::cos(cam.pitch) * std::sin(cam.yaw),
                                              std::sin(cam.pitch),
                                              std::cos(cam.pitch) * std::cos(cam.yaw));
  const auto& engines = session.engines();
  for (int i = 0; i < static_cast<int>(engines.size()); ++i) {
    const auto [x, y] = viewportOrigin(l, i);
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
}

// The overlay's frame in window pixels: the top and bottom bands, dividers between viewports
// only (never across the bands' text).
void drawOverlayFrame(const Layout& l, int count, int width, int height) {
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
  glColor3f(0.4f, 0.4f, 0.45f);
  glBegin(GL_LINES);
  for (int i = 0; i < count; ++i) {
    const auto [x, y] = viewportOrigin(l, i);
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
}

// The top band: scene, time, step, rate and toggles; then the engines' distance, the deepest
// penetration, or the session's notice.
void drawStatus(ViewerSession& session, const Text& text, const std::string& rate) {
  std::string top = session.config().scene_name + "    t " + formatValue("%.2f s", session.time()) +
                    "    dt " + formatValue("%.4g s", session.dt()) + "    " + rate;
  if (session.speed() < 0.99) top += "    slow motion x" + formatValue("%.2f", session.speed());
  if (session.paused()) top += "    paused";
  if (session.togglesApply()) {
    top += std::string("    wind ") + (session.wind() ? "on" : "off") + "    swing " +
           (session.swing() ? "on" : "off");
  }
  text.draw(10, 4, top);
  std::string metrics;
  if (auto d = session.engineDistance()) {
    metrics += "RMS distance between the first two engines " + formatValue("%.3g m", *d) + "    ";
  }
  if (auto p = session.penetration()) {
    metrics += "deepest node inside a collider " + formatValue("%.3g mm", 1e3 * *p);
  }
  if (!session.notice().empty()) metrics = session.notice();
  text.draw(10, 4 + text.lineHeight(), metrics, 0.75f, 0.87f, 1.0f);
}

// Each viewport's label: engine and integrator, then refused, or energy, step time and blow-up.
void drawEngineLabels(ViewerSession& session, const Text& text, const Layout& l) {
  const auto& engines = session.engines();
  for (int i = 0; i < static_cast<int>(engines.size()); ++i) {
    const EngineView& e = engines[i];
    const auto [vx, vy] = viewportOrigin(l, i);
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
    if (auto en = session.energy(e)) y = text.draw(x, y, "total energy " + formatValue("%.5g J", *en));
    y = text.draw(x, y, "stepping " + formatValue("%.2f ms per frame", 1e3 * e.step_seconds));
    if (e.blowup_time) {
      text.drawWrapped(x, y,
                       "blew up at t " + formatValue("%.3f s", *e.blowup_time) + ": " + e.blowup_check,
                       max_width, 1.0f, 0.35f, 0.35f);
    }
  }
}

}  // namespace

void render(ViewerSession& session, const Text& text, int width, int height,
            const std::string& rate) {
  glClearColor(0.12f, 0.13f, 0.16f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const int count = std::max<int>(1, session.engines().size());
  const Layout l = layout(count, width, height, text);
  drawViewports(session, l, height);
  drawOverlayFrame(l, count, width, height);
  drawStatus(session, text, rate);
  drawEngineLabels(session, text, l);
  text.drawWrapped(10, height - l.bottom_band + 5,
                   "t scene   d wind   s swing   w shaded / springs   r reset   i integrator   "
                   "space pause   . step   p screenshot   drag: orbit   wheel: zoom   q quit",
                   width - 20, 0.7f, 0.7f, 0.7f);
}


}  // namespace viewer
