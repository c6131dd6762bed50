#include "ncc/driver/variables_file.h"

#include "ncc/prepare/block_loop.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <toml++/toml.h>

#include "absl/strings/str_cat.h"
#include "ncc/eval/macro_rules.h"
#include "ncc/eval/variables.h"

namespace ncc::driver {

namespace {

constexpr const char* kBadFile = "NCC0017";

std::optional<int64_t> variableNumber(std::string_view key) {
  if (key.size() < 2 || key[0] != '#') return std::nullopt;
  int64_t n = 0;
  auto [end, ec] = std::from_chars(key.data() + 1, key.data() + key.size(), n);
  if (ec != std::errc() || end != key.data() + key.size() || n <= 0) return std::nullopt;
  return n;
}

SourceLocation at(uint32_t file, const toml::source_region& region) {
  return SourceLocation{file, region.begin.line, region.begin.column};
}

}  // namespace

std::optional<std::map<int64_t, SavedVariable>> readVariablesFile(
    const std::filesystem::path& path, SourceManager& sources, DiagnosticEngine& diags) {
  std::map<int64_t, SavedVariable> out;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return out;
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  if (in) text << in.rdbuf();
  const uint32_t file = sources.addFile(path);
  if (!in) {
    diags.error(kBadFile, SourceLocation{file, 0, 0},
                absl::StrCat("cannot read the variables file '", path.string(), "'"));
    return std::nullopt;
  }
  toml::table root;
  try {
#if TOML_EXCEPTIONS
    try {
      root = toml::parse(text.str(), path.string());
    } catch (const toml::parse_error& e) {
      diags.error(kBadFile, at(file, e.source()), std::string(e.description()));
      return std::nullopt;
    }
#else
    toml::parse_result parsed = toml::parse(text.str(), path.string());
    if (!parsed) {
      diags.error(kBadFile, at(file, parsed.error().source()),
                  std::string(parsed.error().description()));
      return std::nullopt;
    }
    root = std::move(parsed).table();
#endif
  } catch (const std::exception& e) {
    diags.error(kBadFile, SourceLocation{file, 0, 0},
                absl::StrCat("cannot read the variables file: ", e.what()));
    return std::nullopt;
  }
  bool ok = true;
  for (const auto& [key, node] : root) {
    std::optional<int64_t> n = variableNumber(key.str());
    const std::optional<double> v = node.value<double>();
    if (!n) {
      diags.error(kBadFile, at(file, key.source()),
                  absl::StrCat("'", std::string(key.str()), "' is not a variable: keys are \"#n\""));
      ok = false;
    } else if (!v || !std::isfinite(*v)) {
      diags.error(kBadFile, at(file, node.source()),
                  absl::StrCat("#", *n, ": the value must be a finite number"));
      ok = false;
    } else {
      out[*n] = SavedVariable{*v, at(file, key.source())};
    }
  }
  if (!ok) return std::nullopt;
  return out;
}

void writeVariablesFile(std::ostream& out, const std::map<int64_t, double>& values) {
  out << "# ncc variables file (--vars): common variables kept from one run to the next\n";
  for (const auto& [n, v] : values) {
    char buffer[64];
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
    std::string text(buffer, end);
    // TOML floats need a point or an exponent.
    if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
    out << "\"#" << n << "\" = " << text << '\n';
  }
}

std::map<int64_t, double> persistentVariables(
    const Session& session, const std::vector<std::pair<std::string, double>>& variables) {
  const eval::MacroRules& rules = eval::macroRules(session.dialect());
  eval::Variables kept(rules, prepare::commonVariables(rules, session.machine()), nullptr);
  std::map<int64_t, double> out;
  for (const auto& [name, value] : variables)
    if (std::optional<int64_t> n = variableNumber(name); n && kept.isPersistent(*n))
      out[*n] = value;
  return out;
}

}  // namespace ncc::driver
