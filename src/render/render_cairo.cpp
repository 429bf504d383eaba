#include "render/render_cairo.h"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

namespace essaim {

namespace {

// The replay page's palette (src/app/replay_template.html), so both views agree.
constexpr double kBackground[3] = {0xf4 / 255.0, 0xf4 / 255.0, 0xf0 / 255.0};
constexpr double kStatic[3] = {0x4d / 255.0, 0x4d / 255.0, 0x4d / 255.0};
constexpr double kMovable[3] = {0xa0 / 255.0, 0x52 / 255.0, 0x2d / 255.0};
constexpr double kBody[3] = {0xc8 / 255.0, 0xd0 / 255.0, 0xd8 / 255.0};  // robot with no LED lit
constexpr double kDead[3] = {0x6e / 255.0, 0x6e / 255.0, 0x6e / 255.0};
constexpr double kOutline[3] = {0x20 / 255.0, 0x20 / 255.0, 0x20 / 255.0};
constexpr double kTrailUnlit[3] = {0x3a / 255.0, 0x6e / 255.0, 0xb4 / 255.0};

void SetRgb(cairo_t* cr, const double* c, double alpha = 1) { cairo_set_source_rgba(cr, c[0], c[1], c[2], alpha); }
void SetColor(cairo_t* cr, Color c, double alpha = 1) {
  cairo_set_source_rgba(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0, alpha);
}

struct PngReader {
  const std::string* data;
  size_t pos = 0;
};
cairo_status_t ReadPng(void* closure, unsigned char* out, unsigned int length) {
  auto* r = static_cast<PngReader*>(closure);
  if (r->pos + length > r->data->size()) return CAIRO_STATUS_READ_ERROR;
  std::memcpy(out, r->data->data() + r->pos, length);
  r->pos += length;
  return CAIRO_STATUS_SUCCESS;
}
cairo_status_t WritePng(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

/// The floor PNG stretched over the arena, nearest-pixel (crisp, like the sensors see it).
void DrawFloor(cairo_t* cr, const RecordingScene& s, int width, int height) {
  if (s.floor_png.empty()) return;
  PngReader reader{&s.floor_png};
  cairo_surface_t* floor = cairo_image_surface_create_from_png_stream(ReadPng, &reader);
  if (cairo_surface_status(floor) == CAIRO_STATUS_SUCCESS) {
    int fw = cairo_image_surface_get_width(floor), fh = cairo_image_surface_get_height(floor);
    cairo_save(cr);
    cairo_scale(cr, static_cast<double>(width) / fw, static_cast<double>(height) / fh);
    cairo_set_source_surface(cr, floor, 0, 0);
    cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);
    cairo_pattern_set_extend(cairo_get_source(cr), CAIRO_EXTEND_PAD);
    cairo_paint(cr);
    cairo_restore(cr);
  }
  cairo_surface_destroy(floor);
}

void DrawObstacle(cairo_t* cr, const RecordedObstacle& o, const Pose2& pose, Color led, double px) {
  cairo_save(cr);
  cairo_translate(cr, pose.x, pose.y);
  cairo_rotate(cr, pose.yaw);
  if (o.cylinder)
    cairo_arc(cr, 0, 0, o.radius, 0, kTwoPi);
  else
    cairo_rectangle(cr, -o.size_x / 2, -o.size_y / 2, o.size_x, o.size_y);
  SetRgb(cr, o.movable ? kMovable : kStatic);
  cairo_fill_preserve(cr);
  SetRgb(cr, kOutline, 0.6);
  cairo_set_line_width(cr, px);
  cairo_stroke(cr);
  if (!led.IsBlack()) {  // its LED colour as an inner disc (loop functions recolour them)
    const double r = 0.6 * (o.cylinder ? o.radius : std::min(o.size_x, o.size_y) / 2);
    cairo_arc(cr, 0, 0, std::max(r, 2 * px), 0, kTwoPi);
    SetColor(cr, led);
    cairo_fill(cr);
  }
  cairo_restore(cr);
}

void DrawTrails(cairo_t* cr, const Recording& rec, size_t frame, int trail_ticks, double px) {
  uint64_t now = rec.Tick(frame);
  uint64_t from_tick = now > static_cast<uint64_t>(trail_ticks) ? now - trail_ticks : 0;
  size_t first = rec.FrameAtOrBefore(from_tick);
  if (first >= frame) return;
  cairo_set_line_width(cr, 1.5 * px);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (size_t i = 0; i < rec.RobotCount(); ++i) {
    RecordedRobot cur = rec.Robot(frame, i);
    if (!cur.present) continue;
    cairo_new_path(cr);
    for (size_t k = first; k <= frame; ++k) {
      RecordedRobot r = rec.Robot(k, i);
      if (r.present) cairo_line_to(cr, r.x, r.y);  // the first present point starts the path
    }
    if (!cur.alive)
      SetRgb(cr, kDead, 0.5);
    else if (cur.color.IsBlack())
      SetRgb(cr, kTrailUnlit, 0.55);
    else
      SetColor(cr, cur.color, 0.7);
    cairo_stroke(cr);
  }
}

void DrawRobot(cairo_t* cr, const RecordedRobot& r, double radius, double px) {
  cairo_new_path(cr);
  cairo_arc(cr, r.x, r.y, radius, 0, kTwoPi);
  if (!r.alive)
    SetRgb(cr, kDead, 0.75);
  else if (r.color.IsBlack())
    SetRgb(cr, kBody);
  else
    SetColor(cr, r.color);
  cairo_fill_preserve(cr);
  SetRgb(cr, kOutline);
  cairo_set_line_width(cr, std::max(px, radius * 0.08));
  cairo_stroke(cr);
  cairo_move_to(cr, r.x, r.y);
  cairo_line_to(cr, r.x + std::cos(r.yaw) * radius, r.y + std::sin(r.yaw) * radius);
  cairo_set_line_width(cr, std::max(px, radius * 0.15));
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  cairo_stroke(cr);
}

// Text in pixels, on a pale box so it reads on any floor: the tick in the top-left corner,
// each robot's id to the upper right of its body.
void DrawLabel(cairo_t* cr, const std::string& text, double x, double y) {
  cairo_text_extents_t ext;
  cairo_text_extents(cr, text.c_str(), &ext);
  cairo_set_source_rgba(cr, 1, 1, 1, 0.75);
  cairo_rectangle(cr, x - 1, y + ext.y_bearing - 1, ext.x_advance + 2, ext.height + 2);
  cairo_fill(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, text.c_str());
}

void DrawLabels(cairo_t* cr, const Recording& rec, size_t frame, double radius, int height) {
  const double font = std::max(10.0, std::min(14.0, height / 50.0));
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  std::vector<std::pair<double, double>> at(rec.RobotCount());
  std::vector<bool> present(rec.RobotCount());
  for (size_t i = 0; i < rec.RobotCount(); ++i) {  // world to pixels, while the world frame is set
    RecordedRobot r = rec.Robot(frame, i);
    double x = r.x + radius, y = r.y + radius;
    cairo_user_to_device(cr, &x, &y);
    at[i] = {x, y};
    present[i] = r.present;
  }
  cairo_identity_matrix(cr);
  cairo_set_font_size(cr, font);
  for (size_t i = 0; i < rec.RobotCount(); ++i)
    if (present[i]) DrawLabel(cr, rec.scene().robot_ids[i], at[i].first, at[i].second);
  const uint64_t tick = rec.Tick(frame);
  char text[64];
  std::snprintf(text, sizeof text, "tick %llu (%.1f s)", static_cast<unsigned long long>(tick),
                static_cast<double>(tick) / rec.scene().ticks_per_second);
  DrawLabel(cr, text, font * 0.5, font * 1.3);
}
}  // namespace

void SnapshotImageSize(const RecordingScene& s, int size, int* width, int* height) {
  double sx = s.arena_size.x(), sy = s.arena_size.y();
  if (sx >= sy) {
    *width = size;
    *height = std::max(1, static_cast<int>(std::lround(size * sy / sx)));
  } else {
    *height = size;
    *width = std::max(1, static_cast<int>(std::lround(size * sx / sy)));
  }
}

bool RenderSnapshotPng(const Recording& rec, size_t frame, const SnapshotOptions& opt, std::string* png,
                       std::string* error) {
  const RecordingScene& s = rec.scene();
  int width = 0, height = 0;
  SnapshotImageSize(s, opt.size, &width, &height);
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
  cairo_t* cr = cairo_create(surface);

  SetRgb(cr, kBackground);
  cairo_paint(cr);
  DrawFloor(cr, s, width, height);

  // World frame: metres, +y up, the arena's min corner at the bottom-left.
  const double scale = width / s.arena_size.x();
  const double px = 1.0 / scale;  // one pixel in metres
  cairo_translate(cr, 0, height);
  cairo_scale(cr, scale, -static_cast<double>(height) / s.arena_size.y());
  cairo_translate(cr, -s.arena_min.x(), -s.arena_min.y());

  // Obstacles with a slot in the frames (movable ones, and any added during the run) are
  // drawn from the frame; the others where the scene has them.
  std::vector<int> slot(s.obstacles.size(), -1);
  for (size_t k = 0; k < s.movable.size(); ++k) slot[s.movable[k]] = static_cast<int>(k);
  for (size_t i = 0; i < s.obstacles.size(); ++i) {
    const RecordedObstacle& o = s.obstacles[i];
    if (slot[i] < 0) {
      DrawObstacle(cr, o, o.pose, o.led, px);
    } else if (rec.MovablePresent(frame, slot[i])) {  // else removed, or not added yet
      DrawObstacle(cr, o, rec.Movable(frame, slot[i]), rec.MovableLed(frame, slot[i]), px);
    }
  }
  for (const RecordedLight& l : s.lights) {
    cairo_new_path(cr);
    cairo_arc(cr, l.position.x(), l.position.y(), std::max(0.05, 4 * px), 0, kTwoPi);
    SetColor(cr, l.color);
    cairo_fill_preserve(cr);
    SetRgb(cr, kOutline);
    cairo_set_line_width(cr, px);
    cairo_stroke(cr);
  }
  if (opt.trail_ticks > 0) DrawTrails(cr, rec, frame, opt.trail_ticks, px);
  const double radius = std::max(s.robot_radius, 2 * px);
  for (size_t i = 0; i < rec.RobotCount(); ++i) {
    const RecordedRobot r = rec.Robot(frame, i);
    if (r.present) DrawRobot(cr, r, radius, px);  // else added by the loop functions later
  }
  if (opt.labels) DrawLabels(cr, rec, frame, radius, height);

  cairo_destroy(cr);
  cairo_surface_flush(surface);
  png->clear();
  cairo_status_t st = cairo_surface_status(surface);
  if (st == CAIRO_STATUS_SUCCESS) st = cairo_surface_write_to_png_stream(surface, WritePng, png);
  cairo_surface_destroy(surface);
  if (st != CAIRO_STATUS_SUCCESS) {
    *error = std::string("cairo: ") + cairo_status_to_string(st);
    return false;
  }
  return true;
}

}  // namespace essaim
