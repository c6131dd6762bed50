#include "svg_drawing.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <variant>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"

namespace ncc::passes::testing {

namespace {

constexpr double kPi = std::numbers::pi;

struct Pt {
  double x = 0, y = 0;
};

struct Seg {
  uint32_t line = 0;
  bool rapid = false, arc = false, cw = false;
  Pt from, to, c;
};

std::vector<Seg> segments(const std::vector<ir::Block>& blocks) {
  std::vector<Seg> out;
  Pt at;
  bool first = true;
  for (const ir::Block& b : blocks)
    for (const ir::Operation& op : b.ops) {
      Seg s;
      s.line = b.loc.line;
      s.from = at;
      if (const auto* r = std::get_if<ir::Rapid>(&op)) {
        s.rapid = true;
        s.to = {r->to[0], r->to[1]};
      } else if (const auto* l = std::get_if<ir::Linear>(&op)) {
        s.to = {l->to[0], l->to[1]};
      } else if (const auto* a = std::get_if<ir::Arc>(&op)) {
        s.arc = true;
        s.cw = a->clockwise;
        s.to = {a->to[0], a->to[1]};
        s.c = {a->center[0], a->center[1]};
      } else {
        continue;
      }
      at = s.to;
      // The first move's start is unknown (the tool is somewhere): it is drawn as a point.
      if (!first) out.push_back(s);
      first = false;
    }
  return out;
}

// The sweep of an arc, radians, in (0, 2 pi] (a closed arc is a full circle).
double sweepOf(const Seg& s) {
  const double ax = s.from.x - s.c.x, ay = s.from.y - s.c.y;
  const double bx = s.to.x - s.c.x, by = s.to.y - s.c.y;
  double t = std::atan2(ax * by - ay * bx, ax * bx + ay * by);
  if (s.cw) t = -t;
  if (t <= 1e-12) t += 2 * kPi;
  return t;
}

Pt along(const Seg& s, double angle) {
  const double a = s.cw ? -angle : angle;
  const double vx = s.from.x - s.c.x, vy = s.from.y - s.c.y;
  return {s.c.x + vx * std::cos(a) - vy * std::sin(a), s.c.y + vx * std::sin(a) + vy * std::cos(a)};
}

struct Frame {
  double min_x = 1e300, min_y = 1e300, max_x = -1e300, max_y = -1e300;
  double scale = 1, margin = 12, top = 28;
  void add(Pt p, double pad = 0) {
    min_x = std::min(min_x, p.x - pad);
    max_x = std::max(max_x, p.x + pad);
    min_y = std::min(min_y, p.y - pad);
    max_y = std::max(max_y, p.y + pad);
  }
  std::string x(double v) const { return absl::StrFormat("%.2f", margin + (v - min_x) * scale); }
  std::string y(double v) const {
    return absl::StrFormat("%.2f", top + margin + (max_y - v) * scale);
  }
};

std::string pathOf(const std::vector<Seg>& segs, const Frame& f) {
  std::string d;
  Pt at{1e300, 1e300};
  for (const Seg& s : segs) {
    if (std::hypot(s.from.x - at.x, s.from.y - at.y) > 1e-9)
      absl::StrAppend(&d, d.empty() ? "" : " ", "M", f.x(s.from.x), ",", f.y(s.from.y));
    if (!s.arc) {
      absl::StrAppend(&d, " L", f.x(s.to.x), ",", f.y(s.to.y));
    } else {
      const double r = std::hypot(s.from.x - s.c.x, s.from.y - s.c.y) * f.scale;
      const double sweep = sweepOf(s);
      // Y is flipped: a counterclockwise arc has SVG's sweep flag 0. A full circle in halves.
      const int flag = s.cw ? 1 : 0;
      const std::string rr = absl::StrFormat("%.2f", r);
      if (sweep > 2 * kPi - 1e-9) {
        const Pt half = along(s, kPi);
        absl::StrAppend(&d, " A", rr, ",", rr, " 0 0 ", flag, " ", f.x(half.x), ",", f.y(half.y));
      }
      absl::StrAppend(&d, " A", rr, ",", rr, " 0 ", sweep > kPi && sweep < 2 * kPi - 1e-9 ? 1 : 0,
                      " ", flag, " ", f.x(s.to.x), ",", f.y(s.to.y));
    }
    at = s.to;
  }
  return d;
}

std::string xmlEscape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else out += c;
  }
  return out;
}

}  // namespace

std::string drawSvg(const std::string& title, const std::vector<ir::Block>& programmed,
                    const std::vector<ir::Block>& compensated) {
  const std::vector<Seg> prog = segments(programmed), comp = segments(compensated);
  // The tool's radius by source line, where compensation is on (0: off).
  std::map<uint32_t, double> radius_at;
  double tool = 0;
  for (const ir::Block& b : programmed)
    if (b.comp && b.comp->side != ir::CutterComp::Side::Off) {
      radius_at[b.loc.line] = std::fabs(b.comp->radius);
      tool = std::max(tool, std::fabs(b.comp->radius));
    }
  Frame f;
  for (const std::vector<Seg>* list : {&prog, &comp})
    for (const Seg& s : *list) {
      f.add(s.from);
      f.add(s.to);
      if (s.arc)
        for (int k = 1; k < 32; ++k) f.add(along(s, sweepOf(s) * k / 32));
    }
  for (const Seg& s : comp) f.add(s.to, tool);
  if (prog.empty() && comp.empty()) f.add({0, 0});
  const double w = std::max(f.max_x - f.min_x, 1e-6), h = std::max(f.max_y - f.min_y, 1e-6);
  f.scale = std::min(440 / w, 300 / h);
  const double width = w * f.scale + 2 * f.margin, height = h * f.scale + 2 * f.margin + f.top;
  std::string out = absl::StrFormat(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
      "viewBox=\"0 0 %.0f %.0f\" font-family=\"sans-serif\" font-size=\"12\">\n",
      std::ceil(width), std::ceil(height), std::ceil(width), std::ceil(height));
  absl::StrAppend(&out, "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n");
  absl::StrAppend(&out, "<text x=\"", f.margin, "\" y=\"18\">", xmlEscape(title), "</text>\n");
  // The tool at the end of every compensated move.
  for (const Seg& s : comp)
    if (radius_at.count(s.line) && radius_at[s.line] > 0)
      absl::StrAppend(&out, "<circle cx=\"", f.x(s.to.x), "\" cy=\"", f.y(s.to.y), "\" r=\"",
                      absl::StrFormat("%.2f", radius_at[s.line] * f.scale),
                      "\" fill=\"none\" stroke=\"#1f77b4\" stroke-opacity=\"0.15\"/>\n");
  absl::StrAppend(&out, "<path d=\"", pathOf(prog, f),
                  "\" fill=\"none\" stroke=\"#888\" stroke-width=\"1\" "
                  "stroke-dasharray=\"4 3\"/>\n");
  std::vector<Seg> feed, rapid;
  for (const Seg& s : comp) (s.rapid ? rapid : feed).push_back(s);
  if (!rapid.empty())
    absl::StrAppend(&out, "<path d=\"", pathOf(rapid, f),
                    "\" fill=\"none\" stroke=\"#9ecae1\" stroke-width=\"1.5\"/>\n");
  if (!feed.empty())
    absl::StrAppend(&out, "<path d=\"", pathOf(feed, f),
                    "\" fill=\"none\" stroke=\"#1f77b4\" stroke-width=\"2\"/>\n");
  for (const Seg& s : comp)
    absl::StrAppend(&out, "<circle cx=\"", f.x(s.to.x), "\" cy=\"", f.y(s.to.y),
                    "\" r=\"2.5\" fill=\"#d62728\"/>\n");
  absl::StrAppend(&out, "</svg>\n");
  return out;
}

}  // namespace ncc::passes::testing
