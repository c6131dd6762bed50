#pragma once
// Machines and hand-assembled programs shared by the controller tests.
#include <cstdint>
#include <cstring>
#include <memory>

#include "gtest/gtest.h"
#include "ncc/bytecode/assembler.h"
#include "ncc/machine/machine_config.h"
#include "ncc/vm/controller.h"

namespace ncc::controller_test {

inline AxisValues xyz(double x, double y, double z) {
  AxisValues v{};
  v[0] = x;
  v[1] = y;
  v[2] = z;
  return v;
}

// The default 3-axis mill with every axis' servo set to `servo`.
inline MachineConfig machineWith(const ServoConfig& servo) {
  MachineConfig m = defaultMachine();
  for (AxisConfig& a : m.axes) a.servo = servo;
  return m;
}

// Kv in 1/s from the machine-data unit (m/min)/mm.
inline double kvPerSecond(double kv) { return kv * 1000.0 / 60.0; }

// An assembler whose header matches `machine` (axes and configuration hash).
inline bytecode::Assembler assemblerFor(const MachineConfig& machine) {
  bytecode::Header header;
  for (const AxisConfig& a : machine.axes) header.axes.push_back({a.name, a.kind});
  header.config_hash = machine.configHash();
  return bytecode::Assembler(header);
}

inline std::unique_ptr<vm::Controller> make(bytecode::Program program,
                                            const MachineConfig& machine,
                                            const vm::ControllerOptions& options = {}) {
  bytecode::Error error;
  std::unique_ptr<vm::Controller> ctl =
      vm::Controller::create(std::move(program), machine, error, options);
  EXPECT_TRUE(ctl) << error.code << ": " << error.message;
  return ctl;
}

// FNV-1a 64 over the bytes of the commanded and actual positions of every tick.
class TraceHash {
 public:
  void add(const vm::TickOutput& out, int axes) {
    bytes(out.commanded.data(), sizeof(double) * static_cast<std::size_t>(axes));
    bytes(out.actual.data(), sizeof(double) * static_cast<std::size_t>(axes));
  }
  uint64_t value() const { return h_; }

 private:
  void bytes(const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) {
      h_ ^= b[i];
      h_ *= 0x100000001b3ULL;
    }
  }
  uint64_t h_ = 0xcbf29ce484222325ULL;
};

}  // namespace ncc::controller_test
