#pragma once
// The interface input signals the simulated machine presents to a program: the variables
// #1000-#1035 of FANUC and Mazak macros (Mazak §13-9-4 3. "Signaux d'entrée d'interface": #1000 to
// #1031 one contact each, 1 closed or 0 open; #1032 all of #1000-#1031 at once as a 32-bit
// word; #1033-#1035 the next registers, 32 bits each). Read from [machine.signals] or
// `ncc run --signal N=V`. A run-time property, like the probe: not part of the configuration
// hash, and known only when the program runs (the VM prepares the blocks that read one,
// docs/runtime.md). An input never set reads 0 (contact open).
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace ncc {

inline constexpr int kFirstInputSignal = 1000;
inline constexpr int kLastInputBit = 1031;   // #1000-#1031: one contact each
inline constexpr int kInputWord = 1032;      // the bits #1000-#1031 as one word (read only)
inline constexpr int kLastInputSignal = 1035;

struct InputSignals {
  std::map<int, double> values;  // #n -> 0/1 (bits) or 0..2^32-1 (#1033-#1035)
  friend bool operator==(const InputSignals&, const InputSignals&) = default;
};

// Why #`number` cannot be set to `value`, or nullopt: a number outside #1000-#1035 or the
// word #1032 (it is the bits'), a bit not 0 or 1, a word not an integer in 0..2^32-1.
std::optional<std::string> checkInputSignal(int64_t number, double value);
// `N=V` or `#N=V` (`1005=1`): sets that input. The reason when the text is not that, or the
// value is refused (checkInputSignal).
std::optional<std::string> setSignalFromOption(InputSignals& signals, std::string_view text);
// The value a program reads from #`number` (#1000-#1035).
double inputSignalValue(const InputSignals& signals, int64_t number);

}  // namespace ncc
