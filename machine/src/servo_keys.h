#pragma once
// Private to the machine-file reader: the servo keys of [machine.axis.<NAME>]
// (docs/machine-file.md, docs/servo.md).
#include <string>

#include "ncc/machine/machine_config.h"
#include "toml_context.h"

namespace ncc::machine_file {

// Reads `key = node` into axis.servo when `key` is a servo key, reporting bad values itself.
// Returns false (and reports nothing) when `key` is not a servo key.
bool readServoKey(const toml::key& key, const toml::node& node, AxisConfig& axis,
                  TomlContext& ctx);

}  // namespace ncc::machine_file
