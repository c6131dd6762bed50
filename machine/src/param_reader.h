#pragma once
// Private to the machine-file reader: converts one `[machine.params]` value to the type its
// registry entry declares, checking choices, ranges, list sizes and axis names.
#include <optional>
#include <string_view>
#include <vector>

#include "ncc/machine/machine_config.h"
#include "ncc/machine/params.h"
#include "toml_context.h"

namespace ncc::machine_file {

// Index of axis `name` in `axes`; otherwise reports NCC0304 at `where` naming `what` (the
// key the axis was found in) and the configured axes, and returns -1.
int requireAxis(const std::vector<AxisConfig>& axes, std::string_view name, SourceLocation where,
                std::string_view what, TomlContext& ctx);

// nullopt after reporting what is wrong with the value.
std::optional<ParamValue> readParam(const ParamSpec& spec, const toml::node& node,
                                    const std::vector<AxisConfig>& axes, TomlContext& ctx);

}  // namespace ncc::machine_file
