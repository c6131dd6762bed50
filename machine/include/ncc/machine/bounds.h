#pragma once
// The sane ranges of a machine's numbers: what the machine file accepts (NCC0306 outside) and
// what the VM's machine check asks of a configuration built in code (NCC7115). Beyond them a
// value is a typo or a hostile file, not a machine: an IPO cycle or a jerk of 1e-300 would make
// the simulation of one move take longer than the universe. Each bound leaves room for every
// real machine (docs/machine-file.md, "Bounds").
namespace ncc::bounds {

// Interpolation cycle, s: 100 us (a fast current controller runs 125 us) to 100 ms.
inline constexpr double kMinIpoCycle = 1e-4;
inline constexpr double kMaxIpoCycle = 0.1;
// Chord tolerance, mm: 1 nm to 1 mm.
inline constexpr double kMinChordTolerance = 1e-6;
inline constexpr double kMaxChordTolerance = 1.0;
// Corner tolerance, mm: 0 (corners stop) or 1 nm to 10 mm.
inline constexpr double kMinCornerTolerance = 1e-6;
inline constexpr double kMaxCornerTolerance = 10.0;
// Axis speeds (rapid_velocity, max_velocity), mm/min (deg/min): 1 to 1,000,000 (Sinumerik's
// largest path speed is 1000 m/min).
inline constexpr double kMinVelocity = 1.0;
inline constexpr double kMaxVelocity = 1e6;
// Axis acceleration, mm/s^2: 1 to 1,000,000 (100 g).
inline constexpr double kMinAcceleration = 1.0;
inline constexpr double kMaxAcceleration = 1e6;
// Axis jerk, mm/s^3: 1 to 1e9.
inline constexpr double kMinJerk = 1.0;
inline constexpr double kMaxJerk = 1e9;
// Travel limits, mm or deg: within +-1e9, the default travel range ("unlimited").
inline constexpr double kMaxCoordinate = 1e9;
// A position the machine stands at or offsets by (start position, work offsets, reference
// points), mm or deg: within +-1e6, the bytecode's bound on any coordinate (docs/bytecode.md).
// A start at 1e8 mm would make the first rapid a simulation of days.
inline constexpr double kMaxPosition = 1e6;

}  // namespace ncc::bounds
