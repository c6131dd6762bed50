#include "ncc/machine/dialect.h"

#include "absl/strings/ascii.h"
#include "absl/strings/match.h"

namespace ncc {

namespace {
struct NamedDialect {
  Dialect dialect;
  std::string_view name;
};
constexpr NamedDialect kDialects[] = {
    {Dialect::FanucM, "fanuc-m"},           {Dialect::FanucT, "fanuc-t"},
    {Dialect::MazakM, "mazak-m"},           {Dialect::SiemensIsoM, "siemens-iso-m"},
    {Dialect::SiemensDin, "siemens-din"},
};
}  // namespace

std::string_view dialectName(Dialect d) {
  for (const auto& n : kDialects)
    if (n.dialect == d) return n.name;
  return "fanuc-m";
}

std::optional<Dialect> parseDialect(std::string_view name) {
  for (const auto& n : kDialects)
    if (n.name == name) return n.dialect;
  return std::nullopt;
}

Dialect dialectFromFileName(std::string_view file_name) {
  std::string lower = absl::AsciiStrToLower(std::string(file_name));
  if (absl::EndsWith(lower, ".mpf") || absl::EndsWith(lower, ".spf")) return Dialect::SiemensDin;
  return Dialect::FanucM;
}

}  // namespace ncc
