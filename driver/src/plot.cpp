#include "ncc/driver/plot.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "ncc/machine/travel.h"

namespace ncc::driver {

void PlotRecorder::onEvent(const vm::Event& e) {
  if (e.kind == vm::Event::Kind::Machine) {
    if (e.machine.kind == vm::MachineEvent::Kind::ToolSelect) selected_ = e.machine.code;
    if (e.machine.kind == vm::MachineEvent::Kind::ToolChange) {
      loaded_ = selected_;
      changed_ = true;
    }
    return;
  }
  if (e.motion.kind == vm::MotionPrimitive::Kind::Dwell) return;
  moves_.push_back({e.motion, selected_, loaded_});
}

std::vector<PlotMove> PlotRecorder::finish() {
  std::vector<PlotMove> out;
  out.reserve(moves_.size());
  for (const Recorded& r : moves_) out.push_back({r.motion, changed_ ? r.loaded : r.selected});
  moves_.clear();
  return out;
}

const char* plotViewName(PlotView view) {
  switch (view) {
    case PlotView::Top: return "top";
    case PlotView::Front: return "front";
    case PlotView::Side: return "side";
    case PlotView::Iso: return "iso";
  }
  return "top";
}

namespace {

using Kind = vm::MotionPrimitive::Kind;

// A fixed palette (Tableau 10): the tools in the order they first appear.
constexpr const char* kPalette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#9467bd", "#8c564b",
                                    "#e377c2", "#7f7f7f", "#bcbd22", "#17becf", "#d62728"};

// The programmed path under cutter compensation: thin, dashed, a colour no tool has.
constexpr const char* kProgrammedStyle =
    "stroke=\"#ff00ff\" stroke-width=\"0.9\" stroke-dasharray=\"4 2\"";

struct Point2 {
  double u = 0.0, v = 0.0;
};
struct Point3 {
  double x = 0.0, y = 0.0, z = 0.0;
};

// Text for XML character data and attribute values: markup characters as entities, control
// characters and bytes that are not valid UTF-8 as U+FFFD (XML 1.0 allows neither).
std::string xml(std::string_view text) {
  std::string out;
  for (size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else if (c < 0x20 || c == 0x7F) out += "\xEF\xBF\xBD";
    else if (c < 0x80) out += static_cast<char>(c);
    if (c < 0x80) {
      ++i;
      continue;
    }
    // UTF-8 (RFC 3629): lead byte range, then the allowed range of the second byte.
    size_t n = 0;
    unsigned char lo = 0x80, hi = 0xBF;
    if (c >= 0xC2 && c <= 0xDF) n = 2;
    else if (c >= 0xE0 && c <= 0xEF) n = 3, lo = c == 0xE0 ? 0xA0 : 0x80, hi = c == 0xED ? 0x9F : 0xBF;
    else if (c >= 0xF0 && c <= 0xF4) n = 4, lo = c == 0xF0 ? 0x90 : 0x80, hi = c == 0xF4 ? 0x8F : 0xBF;
    bool ok = n > 0 && i + n <= text.size();
    for (size_t k = 1; ok && k < n; ++k) {
      const unsigned char b = static_cast<unsigned char>(text[i + k]);
      ok = k == 1 ? (b >= lo && b <= hi) : (b >= 0x80 && b <= 0xBF);
    }
    if (ok) {
      out.append(text.substr(i, n));
      i += n;
    } else {
      out += "\xEF\xBF\xBD";
      ++i;
    }
  }
  return out;
}

// A coordinate in the titles and labels: 3 decimals, -0 as 0.
std::string mm(double value) {
  std::string text = absl::StrFormat("%.3f", value);
  if (text == "-0.000") text = "0.000";
  return text;
}

// A pixel coordinate: 2 decimals.
std::string px(double value) { return absl::StrFormat("%.2f", value); }

// The projection of one view: machine (x, y, z) to the view's (u right, v up).
Point2 project(PlotView view, const Point3& p) {
  switch (view) {
    case PlotView::Top: return {p.x, p.y};
    case PlotView::Front: return {p.x, p.z};  // seen from -Y
    case PlotView::Side: return {p.y, p.z};   // seen from +X (right side)
    case PlotView::Iso:                       // seen from (+1, -1, +1)
      return {(p.x + p.y) / std::numbers::sqrt2,
              (-p.x + p.y + 2.0 * p.z) / (std::numbers::sqrt2 * std::numbers::sqrt3)};
  }
  return {p.x, p.y};
}

const char* viewLabel(PlotView view) {
  switch (view) {
    case PlotView::Top: return "Top (X right, Y up)";
    case PlotView::Front: return "Front (X right, Z up)";
    case PlotView::Side: return "Side (Y right, Z up)";
    case PlotView::Iso: return "Isometric";
  }
  return "";
}

class Writer {
 public:
  Writer(std::ostream& out, const std::vector<PlotMove>& moves, const PlotOptions& o)
      : out_(out), moves_(moves), o_(o) {}

  void write();

 private:
  Point3 point(const AxisValues& a) const {
    const auto at = [&](int i) { return i >= 0 && i < kMaxAxes ? a[i] : 0.0; };
    return {at(o_.x_axis), at(o_.y_axis), at(o_.z_axis)};
  }
  static ArcMove arcOf(const vm::MotionPrimitive& m) {
    return {m.from, m.to, m.axis1, m.axis2, m.center[m.axis1], m.center[m.axis2], m.cw,
            m.extra_turns};
  }
  // The arc at fraction t of its sweep: the radius linear in the angle, other axes linear.
  static AxisValues arcAt(const vm::MotionPrimitive& m, double sweep, double t) {
    const double c1 = m.center[m.axis1], c2 = m.center[m.axis2];
    const double r0 = std::hypot(m.from[m.axis1] - c1, m.from[m.axis2] - c2);
    const double r1 = std::hypot(m.to[m.axis1] - c1, m.to[m.axis2] - c2);
    const double a = std::atan2(m.from[m.axis2] - c2, m.from[m.axis1] - c1) + t * sweep;
    const double r = r0 + t * (r1 - r0);
    if (t >= 1.0) return m.to;  // exactly, whatever the rounding of the angle
    AxisValues p{};
    for (int i = 0; i < kMaxAxes; ++i) p[i] = m.from[i] + t * (m.to[i] - m.from[i]);
    p[m.axis1] = c1 + r * std::cos(a);
    p[m.axis2] = c2 + r * std::sin(a);
    return p;
  }
  // The number of chords for a polyline of the arc: each within 0.01 mm of the arc, between
  // 0.5 and 2 degrees of it (at most 100,000 chords: 999 extra turns of a large helix).
  static int chords(const vm::MotionPrimitive& m, double sweep) {
    const double c1 = m.center[m.axis1], c2 = m.center[m.axis2];
    const double r = std::max(std::hypot(m.from[m.axis1] - c1, m.from[m.axis2] - c2),
                              std::hypot(m.to[m.axis1] - c1, m.to[m.axis2] - c2));
    constexpr double kDeg = std::numbers::pi / 180.0;
    double step = r > 0.005 ? 2.0 * std::acos(1.0 - 0.01 / r) : 2.0 * kDeg;
    step = std::clamp(step, 0.5 * kDeg, 2.0 * kDeg);
    return std::clamp(static_cast<int>(std::ceil(std::abs(sweep) / step)), 1, 100'000);
  }
  // True when the view sees the arc's plane face-on; `same` then says whether the plane's
  // (axis1, axis2) is the view's (u, v) or its mirror (v, u).
  bool faceOn(PlotView view, const vm::MotionPrimitive& m, bool& same) const {
    int u = -1, v = -1;
    if (view == PlotView::Top) u = o_.x_axis, v = o_.y_axis;
    else if (view == PlotView::Front) u = o_.x_axis, v = o_.z_axis;
    else if (view == PlotView::Side) u = o_.y_axis, v = o_.z_axis;
    else return false;
    if (u < 0 || v < 0) return false;
    same = m.axis1 == u && m.axis2 == v;
    return same || (m.axis1 == v && m.axis2 == u);
  }

  // Screen coordinates of a machine position in the current view.
  Point2 screen(const AxisValues& a) const { return screen(point(a)); }
  Point2 screen(const Point3& p) const {
    const Point2 q = project(view_, p);
    return {ox_ + (q.u - u0_) * scale_, oy_ - (q.v - v0_) * scale_};
  }
  // " X1.000 Y2.000 Z3.000": the drawn axes the machine has.
  std::string axesText(const AxisValues& a) const;
  std::string moveTitle(const PlotMove& m) const;
  std::string pathData(const vm::MotionPrimitive& m) const;
  void fit(double left, double top, double width, double height);
  void writeView(PlotView view, double left, double top, double width, double height);
  void writeLegend(double top);
  void findExtents();
  void writeExtentsBox();

  std::ostream& out_;
  const std::vector<PlotMove>& moves_;
  const PlotOptions& o_;
  std::map<int64_t, const char*> colours_;  // tool -> colour
  std::vector<int64_t> tool_order_;
  bool any_feed_ = false;  // the feed moves' extents lo_..hi_ are known
  Point3 lo_, hi_;
  // The current view and its transform: screen = (ox + (u - u0) s, oy - (v - v0) s).
  PlotView view_ = PlotView::Top;
  double ox_ = 0.0, oy_ = 0.0, u0_ = 0.0, v0_ = 0.0, scale_ = 1.0;
};

std::string Writer::axesText(const AxisValues& a) const {
  const Point3 p = point(a);
  std::string text;
  if (o_.x_axis >= 0) absl::StrAppend(&text, " X", mm(p.x));
  if (o_.y_axis >= 0) absl::StrAppend(&text, " Y", mm(p.y));
  if (o_.z_axis >= 0) absl::StrAppend(&text, " Z", mm(p.z));
  return text;
}

std::string Writer::moveTitle(const PlotMove& pm) const {
  const vm::MotionPrimitive& m = pm.motion;
  const char* code = m.kind == Kind::Rapid ? "G00"
                     : m.kind == Kind::Line ? "G01"
                     : m.cw                 ? "G02"
                                            : "G03";
  std::string text = absl::StrCat(o_.file_name ? o_.file_name(m.where.file) : std::string(), ":",
                                  m.where.line, ": ", code, axesText(m.to), " (T", pm.tool, ")");
  return text;
}

std::string Writer::pathData(const vm::MotionPrimitive& m) const {
  const Point2 a = screen(m.from);
  std::string d = absl::StrCat("M", px(a.u), " ", px(a.v));
  const double sweep = m.kind == Kind::Arc ? arcSweep(arcOf(m)) : 0.0;
  if (sweep == 0.0 || !std::isfinite(sweep)) {  // a line (a degenerate arc runs as one)
    const Point2 b = screen(m.to);
    absl::StrAppend(&d, " L", px(b.u), " ", px(b.v));
    return d;
  }
  const double c1 = m.center[m.axis1], c2 = m.center[m.axis2];
  const double r0 = std::hypot(m.from[m.axis1] - c1, m.from[m.axis2] - c2);
  const double r1 = std::hypot(m.to[m.axis1] - c1, m.to[m.axis2] - c2);
  bool same = true;
  if (faceOn(view_, m, same) && std::abs(r1 - r0) <= 1e-9 * std::max(1.0, r0)) {
    // SVG arcs of at most 120 degrees each (an SVG arc cannot be a full turn). The view's v
    // axis points up, the screen's down: counter-clockwise in (u, v) is clockwise on the
    // screen, SVG's negative angle direction, sweep-flag 0.
    const int pieces = static_cast<int>(std::ceil(std::abs(sweep) / (2.0 * std::numbers::pi / 3.0)));
    const bool ccw = (sweep > 0.0) == same;
    const std::string r = px(r0 * scale_);
    for (int k = 1; k <= pieces; ++k) {
      const Point2 b = screen(arcAt(m, sweep, static_cast<double>(k) / pieces));
      absl::StrAppend(&d, " A", r, " ", r, " 0 0 ", ccw ? 0 : 1, " ", px(b.u), " ", px(b.v));
    }
    return d;
  }
  const int n = chords(m, sweep);
  for (int k = 1; k <= n; ++k) {
    const Point2 b = screen(arcAt(m, sweep, static_cast<double>(k) / n));
    absl::StrAppend(&d, " L", px(b.u), " ", px(b.v));
  }
  return d;
}

// Chooses the transform that fits every drawn move and the work zero into the panel.
void Writer::fit(double left, double top, double width, double height) {
  double ulo = std::numeric_limits<double>::infinity(), uhi = -ulo, vlo = ulo, vhi = -ulo;
  const auto add = [&](const Point3& p) {
    const Point2 q = project(view_, p);
    ulo = std::min(ulo, q.u), uhi = std::max(uhi, q.u);
    vlo = std::min(vlo, q.v), vhi = std::max(vhi, q.v);
  };
  add(point(o_.work_zero));
  const auto add_moves = [&](const std::vector<PlotMove>& moves) {
    for (const PlotMove& pm : moves) {
      const vm::MotionPrimitive& m = pm.motion;
      if (m.kind != Kind::Arc) {
        add(point(m.from));
        add(point(m.to));
        continue;
      }
      // The arc's box (every corner, so the isometric view's fits too).
      const AxisBox box = arcExtent(arcOf(m), kMaxAxes);
      const Point3 lo = point(box.low), hi = point(box.high);
      for (int c = 0; c < 8; ++c)
        add({c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z});
    }
  };
  add_moves(moves_);
  if (o_.programmed) add_moves(*o_.programmed);
  if (o_.alarm_at) add(point(*o_.alarm_at));
  constexpr double kMargin = 36.0;  // px, room for the label and the work zero's
  const double w = std::max(width - 2 * kMargin, 1.0), h = std::max(height - 2 * kMargin, 1.0);
  const double du = uhi - ulo, dv = vhi - vlo;
  scale_ = 1.0;
  if (du > 1e-9 || dv > 1e-9)
    scale_ = std::min(du > 1e-9 ? w / du : std::numeric_limits<double>::infinity(),
                      dv > 1e-9 ? h / dv : std::numeric_limits<double>::infinity());
  u0_ = (ulo + uhi) / 2.0, v0_ = (vlo + vhi) / 2.0;
  ox_ = left + width / 2.0, oy_ = top + height / 2.0 + 8.0;  // below the view's label
}

void Writer::writeView(PlotView view, double left, double top, double width, double height) {
  view_ = view;
  fit(left, top + 16.0, width, height - 16.0);
  const char* name = plotViewName(view);
  out_ << "<g id=\"view-" << name << "\" class=\"view\">\n";
  out_ << "<rect x=\"" << px(left + 2) << "\" y=\"" << px(top + 2) << "\" width=\""
       << px(width - 4) << "\" height=\"" << px(height - 4)
       << "\" fill=\"none\" stroke=\"#cccccc\"/>\n";
  out_ << "<text class=\"view-label\" x=\"" << px(left + 10) << "\" y=\"" << px(top + 20)
       << "\" font-size=\"14\" font-weight=\"bold\">" << viewLabel(view) << "</text>\n";
  // The work zero: a cross with its label.
  const Point2 z = screen(o_.work_zero);
  out_ << "<g class=\"work-zero\"><title>" << xml(o_.work_zero_label) << " work zero:"
       << axesText(o_.work_zero) << " (machine)</title>"
       << "<path d=\"M" << px(z.u - 8) << " " << px(z.v) << " L" << px(z.u + 8) << " " << px(z.v)
       << " M" << px(z.u) << " " << px(z.v - 8) << " L" << px(z.u) << " " << px(z.v + 8)
       << "\" stroke=\"#000000\" stroke-width=\"1.5\"/>"
       << "<circle cx=\"" << px(z.u) << "\" cy=\"" << px(z.v)
       << "\" r=\"4\" fill=\"none\" stroke=\"#000000\"/>"
       << "<text x=\"" << px(z.u + 6) << "\" y=\"" << px(z.v + 16) << "\" font-size=\"11\">"
       << xml(o_.work_zero_label) << " zero</text></g>\n";
  writeExtentsBox();
  if (o_.programmed) {
    // Under the tool centre's path, which stays readable where the two coincide.
    out_ << "<g class=\"programmed-path\" fill=\"none\" stroke-linecap=\"round\" "
         << kProgrammedStyle << ">\n";
    for (const PlotMove& pm : *o_.programmed)
      out_ << "<path class=\"programmed\" d=\"" << pathData(pm.motion) << "\" data-line=\""
           << pm.motion.where.line << "\"><title>programmed: " << xml(moveTitle(pm))
           << "</title></path>\n";
    out_ << "</g>\n";
  }
  // What every move shares is said once, by the group (SVG inheritance).
  out_ << "<g class=\"moves\" fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
  for (const PlotMove& pm : moves_) {
    const vm::MotionPrimitive& m = pm.motion;
    const bool rapid = m.kind == Kind::Rapid;
    out_ << "<path class=\"" << (rapid ? "rapid" : "feed") << "\" d=\"" << pathData(m)
         << "\" stroke=\"" << colours_.at(pm.tool) << "\""
         << (rapid ? " stroke-width=\"1\" stroke-dasharray=\"5 4\"" : " stroke-width=\"1.6\"")
         << " data-tool=\"" << pm.tool << "\" data-line=\"" << m.where.line << "\"><title>"
         << xml(moveTitle(pm)) << "</title></path>\n";
  }
  out_ << "</g>\n";
  if (o_.alarm) {
    const Point2 a = screen(o_.alarm_at       ? *o_.alarm_at
                            : moves_.empty() ? o_.start
                                             : moves_.back().motion.to);
    std::string where = absl::StrCat(
        o_.file_name ? o_.file_name(o_.alarm->where.file) : std::string(), ":", o_.alarm->where.line);
    out_ << "<g class=\"alarm\"><title>" << xml(absl::StrCat("alarm ", o_.alarm->code, " at ", where,
                                                             ": ", o_.alarm->message))
         << "</title><circle cx=\"" << px(a.u) << "\" cy=\"" << px(a.v)
         << "\" r=\"7\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"2.5\"/>"
         << "<text x=\"" << px(a.u + 10) << "\" y=\"" << px(a.v - 8)
         << "\" font-size=\"12\" fill=\"#d62728\">alarm " << xml(o_.alarm->code) << "</text></g>\n";
  }
  out_ << "</g>\n";
}

void Writer::findExtents() {
  // Stopped by a compensation alarm, the programmed path is all there is.
  const std::vector<PlotMove>& moves =
      moves_.empty() && o_.programmed ? *o_.programmed : moves_;
  for (const PlotMove& pm : moves) {
    const vm::MotionPrimitive& m = pm.motion;
    Point3 a, b;
    if (m.kind == Kind::Line) {
      a = point(m.from), b = point(m.to);
    } else if (m.kind == Kind::Arc) {
      const AxisBox box = arcExtent(arcOf(m), kMaxAxes);
      a = point(box.low), b = point(box.high);
    } else {
      continue;
    }
    const Point3 lo{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
    const Point3 hi{std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
    if (!any_feed_) lo_ = lo, hi_ = hi, any_feed_ = true;
    lo_ = {std::min(lo_.x, lo.x), std::min(lo_.y, lo.y), std::min(lo_.z, lo.z)};
    hi_ = {std::max(hi_.x, hi.x), std::max(hi_.y, hi.y), std::max(hi_.z, hi.z)};
  }
}

// The feed extents in an orthographic view: a dashed box with its two sizes written along it.
void Writer::writeExtentsBox() {
  if (!any_feed_ || view_ == PlotView::Iso) return;
  const Point2 a = screen(lo_), b = screen(hi_);
  const double left = std::min(a.u, b.u), right = std::max(a.u, b.u);
  const double top = std::min(a.v, b.v), bottom = std::max(a.v, b.v);
  const Point2 q0 = project(view_, lo_), q1 = project(view_, hi_);
  const char* u_name = view_ == PlotView::Side ? "Y" : "X";
  const char* v_name = view_ == PlotView::Top ? "Y" : "Z";
  out_ << "<g class=\"extents-box\"><title>feed extents: " << u_name << " " << mm(q0.u) << " to "
       << mm(q1.u) << ", " << v_name << " " << mm(q0.v) << " to " << mm(q1.v) << "</title>"
       << "<rect x=\"" << px(left) << "\" y=\"" << px(top) << "\" width=\"" << px(right - left)
       << "\" height=\"" << px(bottom - top)
       << "\" fill=\"none\" stroke=\"#999999\" stroke-width=\"0.8\" stroke-dasharray=\"2 3\"/>"
       << "<text class=\"dimension\" data-axis=\"" << u_name << "\" x=\"" << px((left + right) / 2)
       << "\" y=\"" << px(bottom + 14) << "\" font-size=\"11\" fill=\"#555555\" "
       << "text-anchor=\"middle\">" << u_name << " " << mm(q1.u - q0.u) << "</text>"
       << "<text class=\"dimension\" data-axis=\"" << v_name << "\" x=\"" << px(right + 4)
       << "\" y=\"" << px((top + bottom) / 2) << "\" font-size=\"11\" fill=\"#555555\">" << v_name
       << " " << mm(q1.v - q0.v) << "</text></g>\n";
}

void Writer::writeLegend(double top) {
  // The feed moves' extents: what the part occupies, per axis.
  const bool any = any_feed_;
  const Point3 lo = lo_, hi = hi_;
  out_ << "<g id=\"extents\">\n";
  double x = 12.0;
  if (!any) {
    out_ << "<text x=\"" << px(x) << "\" y=\"" << px(top + 14)
         << "\" font-size=\"12\">no feed moves</text>\n";
  } else {
    out_ << "<text x=\"" << px(x) << "\" y=\"" << px(top + 14)
         << "\" font-size=\"12\" font-weight=\"bold\">Feed extents (machine):</text>\n";
    x += 190.0;
    const struct {
      const char* name;
      int axis;
      double lo, hi;
    } axes[] = {{"X", o_.x_axis, lo.x, hi.x}, {"Y", o_.y_axis, lo.y, hi.y}, {"Z", o_.z_axis, lo.z, hi.z}};
    for (const auto& a : axes) {
      if (a.axis < 0) continue;
      out_ << "<text class=\"extent\" data-axis=\"" << a.name << "\" data-min=\"" << mm(a.lo)
           << "\" data-max=\"" << mm(a.hi) << "\" x=\"" << px(x) << "\" y=\"" << px(top + 14)
           << "\" font-size=\"12\">" << a.name << " " << mm(a.lo) << " to " << mm(a.hi) << " ("
           << mm(a.hi - a.lo) << ")</text>\n";
      x += 230.0;
    }
  }
  out_ << "</g>\n<g id=\"legend\">\n";
  x = 12.0;
  const double y = top + 34.0;
  out_ << "<path d=\"M" << px(x) << " " << px(y - 4) << " L" << px(x + 24) << " " << px(y - 4)
       << "\" stroke=\"#000000\" stroke-dasharray=\"5 4\"/><text x=\"" << px(x + 30) << "\" y=\""
       << px(y) << "\" font-size=\"12\">rapid</text>\n";
  x += 80.0;
  out_ << "<path d=\"M" << px(x) << " " << px(y - 4) << " L" << px(x + 24) << " " << px(y - 4)
       << "\" stroke=\"#000000\" stroke-width=\"1.6\"/><text x=\"" << px(x + 30) << "\" y=\""
       << px(y) << "\" font-size=\"12\">feed</text>\n";
  x += 80.0;
  if (o_.programmed) {
    if (!o_.alarm_at) {
      out_ << "<g class=\"legend-path\" data-path=\"tool-centre\"><path d=\"M" << px(x) << " "
           << px(y - 4) << " L" << px(x + 24) << " " << px(y - 4)
           << "\" stroke=\"#000000\" stroke-width=\"1.6\"/><text x=\"" << px(x + 30)
           << "\" y=\"" << px(y) << "\" font-size=\"12\">tool centre (G41/G42)</text></g>\n";
      x += 170.0;
    }
    out_ << "<g class=\"legend-path\" data-path=\"programmed\"><path d=\"M" << px(x) << " "
         << px(y - 4) << " L" << px(x + 24) << " " << px(y - 4) << "\" " << kProgrammedStyle
         << "/><text x=\"" << px(x + 30) << "\" y=\"" << px(y)
         << "\" font-size=\"12\">programmed path</text></g>\n";
    x += 160.0;
  }
  for (int64_t tool : tool_order_) {
    out_ << "<g class=\"legend-tool\" data-tool=\"" << tool << "\"><rect x=\"" << px(x)
         << "\" y=\"" << px(y - 10) << "\" width=\"12\" height=\"12\" fill=\"" << colours_.at(tool)
         << "\"/><text x=\"" << px(x + 16) << "\" y=\"" << px(y) << "\" font-size=\"12\">T"
         << tool << "</text></g>\n";
    x += 64.0;
  }
  out_ << "</g>\n";
}

void Writer::write() {
  findExtents();
  for (const PlotMove& pm : moves_) {
    if (colours_.count(pm.tool)) continue;
    colours_[pm.tool] = kPalette[tool_order_.size() % std::size(kPalette)];
    tool_order_.push_back(pm.tool);
  }
  const double width = o_.width, height = o_.height;
  out_ << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
       << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << o_.width << "\" height=\""
       << o_.height << "\" viewBox=\"0 0 " << o_.width << " " << o_.height
       << "\" font-family=\"sans-serif\">\n"
       << "<title>" << xml(o_.title) << "</title>\n"
       << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n"
       << "<text id=\"heading\" x=\"12\" y=\"20\" font-size=\"15\" font-weight=\"bold\">"
       << xml(o_.title) << " (" << moves_.size() << " moves"
       << (o_.programmed ? absl::StrCat("; programmed path: ", o_.programmed->size(), " moves")
                         : std::string())
       << ")</text>\n";
  constexpr double kHeader = 28.0, kFooter = 48.0;
  const double body = std::max(height - kHeader - kFooter, 40.0);
  const std::vector<PlotView>& views = o_.views;
  if (views.size() == 1) {
    writeView(views[0], 0.0, kHeader, width, body);
  } else {
    // 2 x 2: top above front, the side view right of the front, the isometric top right.
    const double w = width / 2.0, h = body / 2.0;
    for (PlotView v : views) {
      const double left = v == PlotView::Top || v == PlotView::Front ? 0.0 : w;
      const double top = kHeader + (v == PlotView::Top || v == PlotView::Iso ? 0.0 : h);
      writeView(v, left, top, w, h);
    }
  }
  writeLegend(kHeader + body);
  out_ << "</svg>\n";
}

}  // namespace

void writePlotSvg(std::ostream& out, const std::vector<PlotMove>& moves, const PlotOptions& options) {
  Writer(out, moves, options).write();
}

}  // namespace ncc::driver
