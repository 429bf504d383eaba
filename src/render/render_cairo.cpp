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

/// The floor decoded once (nullptr: none, or not a PNG Cairo reads).
cairo_surface_t* DecodeFloor(const RecordingScene& s) {
  if (s.floor_png.empty()) return nullptr;
  PngReader reader{&s.floor_png};
  cairo_surface_t* floor = cairo_image_surface_create_from_png_stream(ReadPng, &reader);
  if (cairo_surface_status(floor) == CAIRO_STATUS_SUCCESS) return floor;
  cairo_surface_destroy(floor);
  return nullptr;
}

/// The floor stretched over the arena's rectangle (x0, y0 its top-left corner, w × h, in
/// pixels), nearest-pixel (crisp, like the sensors see it).
void DrawFloor(cairo_t* cr, cairo_surface_t* floor, double x0, double y0, double w, double h) {
  if (!floor) return;
  int fw = cairo_image_surface_get_width(floor), fh = cairo_image_surface_get_height(floor);
  cairo_save(cr);
  cairo_translate(cr, x0, y0);
  cairo_scale(cr, w / fw, h / fh);
  cairo_set_source_surface(cr, floor, 0, 0);
  cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);
  cairo_pattern_set_extend(cairo_get_source(cr), CAIRO_EXTEND_PAD);
  cairo_rectangle(cr, 0, 0, fw, fh);
  cairo_fill(cr);
  cairo_restore(cr);
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

void DrawTrails(cairo_t* cr, const std::vector<FrameView>& frames, double px) {
  const FrameView& now = frames.back();
  cairo_set_line_width(cr, 1.5 * px);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (size_t i = 0; i < now.RobotCount(); ++i) {
    RecordedRobot cur = now.Robot(i);
    if (!cur.present) continue;
    cairo_new_path(cr);
    for (const FrameView& f : frames) {
      RecordedRobot r = f.Robot(i);
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

/// The length of the valid UTF-8 sequence starting at text[i], 0 when there is none (an
/// overlong form, a surrogate, past U+10FFFF, a stray or missing continuation byte).
size_t Utf8Length(const std::string& text, size_t i) {
  const auto byte = [&](size_t k) { return static_cast<unsigned char>(text[i + k]); };
  const unsigned char c = byte(0);
  if (c < 0x80) return 1;
  const size_t n = c < 0xC2 || c > 0xF4 ? 0 : c < 0xE0 ? 2 : c < 0xF0 ? 3 : 4;  // 0x80..0xC1: never a lead
  if (n == 0 || i + n > text.size()) return 0;
  for (size_t k = 1; k < n; ++k)
    if ((byte(k) >> 6) != 2) return 0;
  // The second byte's range after the leads that allow fewer (Unicode's table 3-7).
  const unsigned char lo = c == 0xE0 ? 0xA0 : c == 0xF0 ? 0x90 : 0x80;
  const unsigned char hi = c == 0xED ? 0x9F : c == 0xF4 ? 0x8F : 0xBF;
  return byte(1) >= lo && byte(1) <= hi ? n : 0;
}

/// `text` with each byte that is not part of valid UTF-8 replaced by '?': Cairo refuses such
/// text, and a damaged recording's robot ids may hold any bytes.
std::string ValidUtf8(const std::string& text) {
  std::string out;
  for (size_t i = 0; i < text.size();) {
    const size_t n = Utf8Length(text, i);
    out += n ? text.substr(i, n) : "?";
    i += n ? n : 1;
  }
  return out;
}

// Text in pixels, on a pale box so it reads on any floor: the tick in the top-left corner,
// each robot's id to the upper right of its body.
void DrawLabel(cairo_t* cr, const std::string& label, double x, double y) {
  const std::string text = ValidUtf8(label);
  cairo_text_extents_t ext;
  cairo_text_extents(cr, text.c_str(), &ext);
  cairo_set_source_rgba(cr, 1, 1, 1, 0.75);
  cairo_rectangle(cr, x - 1, y + ext.y_bearing - 1, ext.x_advance + 2, ext.height + 2);
  cairo_fill(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, text.c_str());
}

/// Each robot's id to the upper right of its body; the world frame is set on entry, and
/// left for pixels.
void DrawIds(cairo_t* cr, const FrameView& frame, double radius, double font) {
  std::vector<std::pair<double, double>> at(frame.RobotCount());
  std::vector<bool> present(frame.RobotCount());
  for (size_t i = 0; i < frame.RobotCount(); ++i) {  // world to pixels, while the world frame is set
    RecordedRobot r = frame.Robot(i);
    double x = r.x + radius, y = r.y + radius;
    cairo_user_to_device(cr, &x, &y);
    at[i] = {x, y};
    present[i] = r.present;
  }
  cairo_identity_matrix(cr);
  cairo_set_font_size(cr, font);
  for (size_t i = 0; i < frame.RobotCount(); ++i)
    if (present[i]) DrawLabel(cr, frame.scene().robot_ids[i], at[i].first, at[i].second);
}

void DrawTick(cairo_t* cr, const FrameView& frame, double font) {
  const uint64_t tick = frame.Tick();
  char text[64];
  std::snprintf(text, sizeof text, "tick %llu (%.1f s)", static_cast<unsigned long long>(tick),
                static_cast<double>(tick) / frame.scene().ticks_per_second);
  cairo_set_font_size(cr, font);
  DrawLabel(cr, text, font * 0.5, font * 1.3);
}

/// The longest of 1, 2 or 5 times a power of ten (m) that is at most `most`.
double RoundLength(double most) {
  const double decade = std::pow(10.0, std::floor(std::log10(most)));
  for (double k : {5.0, 2.0})
    if (k * decade <= most) return k * decade;
  return decade;
}

/// A bar of a round length, about a fifth of the image's width at most, bottom left, in pixels.
void DrawScaleBar(cairo_t* cr, double px_per_m, int width, int height, double font) {
  const double metres = RoundLength(width / 5.0 / px_per_m), len = metres * px_per_m;
  char text[32];
  if (metres >= 1)
    std::snprintf(text, sizeof text, "%g m", metres);
  else
    std::snprintf(text, sizeof text, "%g cm", metres * 100);
  const double x = font * 0.5, y = height - font * 0.6;  // the bar's left end
  cairo_text_extents_t ext;
  cairo_set_font_size(cr, font);
  cairo_text_extents(cr, text, &ext);
  cairo_set_source_rgba(cr, 1, 1, 1, 0.75);
  cairo_rectangle(cr, x - 4, y - font - 1, len + font * 0.3 + ext.x_advance + 8, font + 5);
  cairo_fill(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 2);
  cairo_move_to(cr, x, y - font * 0.6);  // |_____|
  cairo_line_to(cr, x, y);
  cairo_line_to(cr, x + len, y);
  cairo_line_to(cr, x + len, y - font * 0.6);
  cairo_stroke(cr);
  cairo_move_to(cr, x + len + font * 0.3, y);
  cairo_show_text(cr, text);
}

/// Obstacles with a slot in the frames (movable ones, and any added during the run) are
/// drawn from the frame; the others where the scene has them (DrawStaticObstacles).
std::vector<int> SlotOf(const RecordingScene& s) {
  std::vector<int> slot(s.obstacles.size(), -1);
  for (size_t k = 0; k < s.movable.size(); ++k) slot[s.movable[k]] = static_cast<int>(k);
  return slot;
}

void DrawStaticObstacles(cairo_t* cr, const RecordingScene& s, double px) {
  const std::vector<int> slot = SlotOf(s);
  for (size_t i = 0; i < s.obstacles.size(); ++i)
    if (slot[i] < 0) DrawObstacle(cr, s.obstacles[i], s.obstacles[i].pose, s.obstacles[i].led, px);
}

void DrawMovableObstacles(cairo_t* cr, const FrameView& frame, double px) {
  const RecordingScene& s = frame.scene();
  for (size_t k = 0; k < s.movable.size(); ++k)
    if (frame.MovablePresent(k))  // else removed, or not added yet
      DrawObstacle(cr, s.obstacles[s.movable[k]], frame.Movable(k), frame.MovableLed(k), px);
}

/// The view's world frame: metres, +y up, the view's min corner at the image's bottom-left.
void SetWorldFrame(cairo_t* cr, int height, const Vec2& vmin, double sx, double sy) {
  cairo_translate(cr, 0, height);
  cairo_scale(cr, sx, -sy);
  cairo_translate(cr, -vmin.x(), -vmin.y());
}

void DrawLights(cairo_t* cr, const RecordingScene& s, double px) {
  for (const RecordedLight& l : s.lights) {
    cairo_new_path(cr);
    cairo_arc(cr, l.position.x(), l.position.y(), std::max(0.05, 4 * px), 0, kTwoPi);
    SetColor(cr, l.color);
    cairo_fill_preserve(cr);
    SetRgb(cr, kOutline);
    cairo_set_line_width(cr, px);
    cairo_stroke(cr);
  }
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

// ---- FrameRenderer ----------------------------------------------------------------

struct FrameRenderer::Impl {
  cairo_surface_t* surface = nullptr;
  cairo_surface_t* floor = nullptr;
  /// What does not move (background, floor, static obstacles), kept while the view stays
  /// the same from one frame to the next (not with --follow): a copy instead of drawing.
  cairo_surface_t* still = nullptr;
  Vec2 last_min = Vec2::Constant(NAN), last_size = Vec2::Constant(NAN);
  void DropStill() {
    if (still) cairo_surface_destroy(still);
    still = nullptr;
  }
  ~Impl() {
    DropStill();
    if (floor) cairo_surface_destroy(floor);
    if (surface) cairo_surface_destroy(surface);
  }
  /// Background, floor and static obstacles for the view (vmin, vsize) at (sx, sy) px per m.
  void DrawStill(cairo_t* cr, const RecordingScene& s, const Vec2& vmin, const Vec2& vsize, double sx, double sy,
                 int height) const {
    SetRgb(cr, kBackground);
    cairo_paint(cr);
    DrawFloor(cr, floor, (s.arena_min.x() - vmin.x()) * sx,
              (vmin.y() + vsize.y() - s.arena_min.y() - s.arena_size.y()) * sy, s.arena_size.x() * sx,
              s.arena_size.y() * sy);
    cairo_save(cr);
    SetWorldFrame(cr, height, vmin, sx, sy);
    DrawStaticObstacles(cr, s, 1.0 / sx);
    cairo_restore(cr);
  }
  /// The still part into `cr`: copied from the cache when the view is the last frame's.
  void PaintStill(cairo_t* cr, const RecordingScene& s, const Vec2& vmin, const Vec2& vsize, double sx, double sy,
                  int width, int height) {
    const bool same = vmin == last_min && vsize == last_size;
    last_min = vmin, last_size = vsize;
    if (!same) {
      DropStill();
      return DrawStill(cr, s, vmin, vsize, sx, sy, height);
    }
    if (!still) {
      still = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
      cairo_t* sc = cairo_create(still);
      DrawStill(sc, s, vmin, vsize, sx, sy, height);
      cairo_destroy(sc);
    }
    cairo_set_source_surface(cr, still, 0, 0);
    cairo_paint(cr);
  }
};

FrameRenderer::FrameRenderer(const RecordingScene& scene, int width, int height)
    : impl_(std::make_unique<Impl>()), scene_(scene), width_(width), height_(height) {
  impl_->surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
  impl_->floor = DecodeFloor(scene);
}

FrameRenderer::~FrameRenderer() = default;

bool FrameRenderer::Draw(const std::vector<FrameView>& frames, const DrawOptions& opt, std::string* error) {
  const RecordingScene& s = scene_;
  const FrameView& frame = frames.back();
  const bool whole = opt.view_size.x() <= 0 || opt.view_size.y() <= 0;
  const Vec2 vmin = whole ? s.arena_min : opt.view_min, vsize = whole ? s.arena_size : opt.view_size;
  const double sx = width_ / vsize.x(), sy = height_ / vsize.y();  // px per m
  cairo_t* cr = cairo_create(impl_->surface);
  impl_->PaintStill(cr, s, vmin, vsize, sx, sy, width_, height_);
  const double px = 1.0 / sx;  // one pixel in metres
  SetWorldFrame(cr, height_, vmin, sx, sy);
  DrawMovableObstacles(cr, frame, px);
  DrawLights(cr, s, px);
  if (frames.size() > 1) DrawTrails(cr, frames, px);
  const double radius = std::max(s.robot_radius, 2 * px);
  for (size_t i = 0; i < frame.RobotCount(); ++i) {
    const RecordedRobot r = frame.Robot(i);
    if (r.present) DrawRobot(cr, r, radius, px);  // else added by the loop functions later
  }
  const double font = std::max(10.0, std::min(14.0, height_ / 50.0));
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  if (opt.ids) DrawIds(cr, frame, radius, font);
  cairo_identity_matrix(cr);
  if (opt.tick) DrawTick(cr, frame, font);
  if (opt.scale_bar) DrawScaleBar(cr, sx, width_, height_, font);
  cairo_status_t st = cairo_status(cr);
  cairo_destroy(cr);
  cairo_surface_flush(impl_->surface);
  if (st == CAIRO_STATUS_SUCCESS) st = cairo_surface_status(impl_->surface);
  if (st != CAIRO_STATUS_SUCCESS) {
    *error = std::string("cairo: ") + cairo_status_to_string(st);
    return false;
  }
  return true;
}

const uint8_t* FrameRenderer::Pixels() const { return cairo_image_surface_get_data(impl_->surface); }

int FrameRenderer::Stride() const { return cairo_image_surface_get_stride(impl_->surface); }

bool FrameRenderer::Png(std::string* png, std::string* error) const {
  png->clear();
  cairo_status_t st = cairo_surface_status(impl_->surface);
  if (st == CAIRO_STATUS_SUCCESS) st = cairo_surface_write_to_png_stream(impl_->surface, WritePng, png);
  if (st != CAIRO_STATUS_SUCCESS) {
    *error = std::string("cairo: ") + cairo_status_to_string(st);
    return false;
  }
  return true;
}

bool RenderSnapshotPng(const Recording& rec, size_t frame, const SnapshotOptions& opt, std::string* png,
                       std::string* error) {
  int width = 0, height = 0;
  SnapshotImageSize(rec.scene(), opt.size, &width, &height);
  // The trail runs from the last frame at or before `trail_ticks` ticks ago.
  std::vector<FrameView> frames;
  if (opt.trail_ticks > 0) {
    const uint64_t now = rec.Tick(frame), span = static_cast<uint64_t>(opt.trail_ticks);
    for (size_t k = rec.FrameAtOrBefore(now > span ? now - span : 0); k < frame; ++k) frames.push_back(rec.Frame(k));
  }
  frames.push_back(rec.Frame(frame));
  FrameRenderer renderer(rec.scene(), width, height);
  DrawOptions draw;
  draw.tick = draw.ids = opt.labels;
  return renderer.Draw(frames, draw, error) && renderer.Png(png, error);
}

}  // namespace essaim
