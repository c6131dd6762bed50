// MachineConfig queries, its stable hash, and the built-in default machine.
#include "ncc/machine/machine_config.h"

#include <bit>
#include <type_traits>

namespace ncc {

int MachineConfig::axisIndex(std::string_view name) const {
  for (size_t i = 0; i < axes.size(); ++i)
    if (axes[i].name == name) return static_cast<int>(i);
  return -1;
}

namespace {

// FNV-1a 64 over a canonical byte stream. Every field is written with a fixed width in
// little-endian order (not the host's), strings with their length first, and maps in key
// order (std::map): the result depends only on the configuration's values.
class CanonicalHasher {
 public:
  void byte(uint8_t b) {
    hash_ ^= b;
    hash_ *= 0x100000001b3ULL;
  }
  void u64(uint64_t v) {
    for (int i = 0; i < 8; ++i) byte(static_cast<uint8_t>(v >> (8 * i)));
  }
  void i64(int64_t v) { u64(static_cast<uint64_t>(v)); }
  // -0.0 and 0.0 are the same setting; the reader rejects NaN and infinities.
  void f64(double v) { u64(std::bit_cast<uint64_t>(v == 0.0 ? 0.0 : v)); }
  void str(std::string_view s) {
    u64(s.size());
    for (char c : s) byte(static_cast<uint8_t>(c));
  }
  void tag(char t) { byte(static_cast<uint8_t>(t)); }
  uint64_t value() const { return hash_; }

 private:
  uint64_t hash_ = 0xcbf29ce484222325ULL;
};

void hashLathe(CanonicalHasher& h, char tag, const std::map<int, LatheOffset>& regs) {
  h.tag(tag);
  h.u64(regs.size());
  for (const auto& [n, o] : regs) {
    h.i64(n);
    h.f64(o.x);
    h.f64(o.z);
    h.f64(o.radius);
    h.i64(o.tip);
  }
}

void hashParam(CanonicalHasher& h, const ParamValue& value) {
  h.u64(value.index());
  std::visit(
      [&h](const auto& v) {
        using V = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<V, bool>) {
          h.byte(v ? 1 : 0);
        } else if constexpr (std::is_same_v<V, double>) {
          h.f64(v);
        } else if constexpr (std::is_same_v<V, std::string>) {
          h.str(v);
        } else if constexpr (std::is_same_v<V, ParamAxisTable>) {
          h.u64(v.by_axis.size());
          for (const auto& [k, x] : v.by_axis) h.str(k), h.f64(x);
        } else if constexpr (std::is_same_v<V, std::vector<double>>) {
          h.u64(v.size());
          for (double x : v) h.f64(x);
        } else if constexpr (std::is_same_v<V, std::vector<std::string>>) {
          h.u64(v.size());
          for (const auto& s : v) h.str(s);
        } else if constexpr (std::is_same_v<V, ParamStringTable>) {
          h.u64(v.by_key.size());
          for (const auto& [k, s] : v.by_key) h.str(k), h.str(s);
        } else if constexpr (std::is_same_v<V, ParamAxisRanges>) {
          h.u64(v.by_axis.size());
          for (const auto& [k, r] : v.by_axis) h.str(k), h.f64(r.first), h.f64(r.second);
        }
      },
      value);
}

}  // namespace

uint64_t MachineConfig::configHash() const {
  CanonicalHasher h;
  h.str("ncc-machine-1");  // format version of this serialisation
  h.tag('A');
  h.u64(axes.size());
  for (const AxisConfig& a : axes) {
    h.str(a.name);
    h.byte(static_cast<uint8_t>(a.kind));
    h.byte(a.diameter ? 1 : 0);
    h.f64(a.min_travel);
    h.f64(a.max_travel);
  }
  h.tag('H');
  h.u64(tool_offsets.length.size());
  for (const auto& [n, v] : tool_offsets.length) h.i64(n), h.f64(v);
  h.tag('D');
  h.u64(tool_offsets.radius.size());
  for (const auto& [n, v] : tool_offsets.radius) h.i64(n), h.f64(v);
  hashLathe(h, 'T', lathe_offsets.combined);
  hashLathe(h, 'G', lathe_offsets.geometry);
  hashLathe(h, 'W', lathe_offsets.wear);
  hashLathe(h, 'S', lathe_offsets.second_geometry);
  hashLathe(h, 'E', lathe_offsets.edge);
  // Only the configured axes' slots: the unused tail of AxisValues is not part of the machine.
  const size_t n_axes = axes.size() < kMaxAxes ? axes.size() : kMaxAxes;
  h.tag('O');
  h.u64(work_offsets.size());
  for (const auto& [name, values] : work_offsets) {
    h.str(name);
    for (size_t i = 0; i < n_axes; ++i) h.f64(values[i]);
  }
  h.tag('P');
  for (size_t i = 0; i < n_axes; ++i) h.f64(start_position[i]);
  h.tag('M');
  h.u64(params.all().size());
  for (const auto& [key, value] : params.all()) {
    h.str(key);
    hashParam(h, value);
  }
  return h.value();
}

MachineConfig defaultMachine() {
  MachineConfig m;
  for (const char* name : {"X", "Y", "Z"}) {
    AxisConfig axis;
    axis.name = name;
    m.axes.push_back(axis);
  }
  for (const char* name : {"G54", "G55", "G56", "G57", "G58", "G59"})
    m.work_offsets[name] = zeroAxes();
  return m;
}

}  // namespace ncc
