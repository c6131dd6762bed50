#include "ncc/machine/probe.h"

#include <charconv>
#include <cmath>

#include "absl/strings/str_cat.h"
#include "ncc/machine/bounds.h"
#include "ncc/machine/machine_config.h"

namespace ncc {

std::optional<std::string> setProbeFromOption(ProbeConfig& probe,
                                              const std::vector<AxisConfig>& axes,
                                              std::string_view text) {
  const size_t eq = text.find('=');
  if (eq == std::string_view::npos)
    return absl::StrCat("'", std::string(text), "' is not AXIS=VALUE (for example Z=-42.5)");
  const std::string name(text.substr(0, eq));
  const std::string number(text.substr(eq + 1));
  int axis = -1;
  std::string names;
  for (size_t i = 0; i < axes.size(); ++i) {
    if (axes[i].name == name) axis = static_cast<int>(i);
    absl::StrAppend(&names, i == 0 ? "" : ", ", axes[i].name);
  }
  if (axis < 0 || axis >= kMaxAxes)
    return absl::StrCat("unknown axis '", name, "' in '", std::string(text), "' (the machine's axes are ",
                        names, ")");
  double v = 0.0;
  const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), v);
  if (number.empty() || ec != std::errc() || end != number.data() + number.size() ||
      !std::isfinite(v))
    return absl::StrCat("'", number, "' in '", std::string(text), "' is not a number");
  if (!(std::abs(v) <= bounds::kMaxPosition))
    return absl::StrCat("the trigger ", number, " of ", name, " is beyond +-",
                        bounds::kMaxPosition, ", the bound of every position");
  probe.axes |= static_cast<AxisMask>(1u << axis);
  probe.trigger[axis] = v;
  return std::nullopt;
}

std::optional<ProbeHit> probeStop(const ProbeConfig& probe, const AxisValues& from,
                                  const AxisValues& to, int axis_count) {
  std::optional<ProbeHit> first;
  for (int i = 0; i < axis_count && i < kMaxAxes; ++i) {
    if ((probe.axes & (1u << i)) == 0) continue;
    const double d = to[i] - from[i];
    if (d == 0.0) continue;  // the move does not approach this plane
    // The fraction where axis i reaches the plane; at or below 0: on at the start (the start
    // is at or beyond the plane in the direction of the move).
    const double s = (probe.trigger[i] - from[i]) / d;
    if (s > 1.0) continue;  // the end point stays on the start side
    const double at = s <= 0.0 ? 0.0 : s;
    if (!first || at < first->fraction) first = ProbeHit{at, i};
  }
  return first;
}

AxisValues probeStopPoint(const ProbeConfig& probe, const ProbeHit& hit, const AxisValues& from,
                          const AxisValues& to, int axis_count) {
  if (hit.fraction <= 0.0) return from;  // on at the start: no motion
  AxisValues at = from;
  for (int i = 0; i < axis_count && i < kMaxAxes; ++i)
    at[i] = from[i] + (to[i] - from[i]) * hit.fraction;
  // Exactly on the plane that stopped it, not a rounding error away.
  if (hit.axis >= 0 && hit.axis < kMaxAxes) at[hit.axis] = probe.trigger[hit.axis];
  return at;
}

}  // namespace ncc
