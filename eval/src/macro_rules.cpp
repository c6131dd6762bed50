#include "ncc/eval/macro_rules.h"

#include <algorithm>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/strings/str_replace.h"
#include "macro_rules_tables.h"

namespace ncc::eval {

namespace {

// The fanuc-t and siemens-din tables differ from their milling siblings only in the dialect.
MacroRules withDialect(const MacroRules& rules, Dialect dialect) {
  MacroRules r = rules;
  r.dialect = dialect;
  return r;
}

}  // namespace

const MacroRules& macroRules(Dialect dialect) {
  static const MacroRules fanuc_t = withDialect(tables::kFanucRules, Dialect::FanucT);
  static const MacroRules siemens_din = withDialect(tables::kSiemensIsoRules, Dialect::SiemensDin);
  switch (dialect) {
    case Dialect::FanucM: return tables::kFanucRules;
    case Dialect::FanucT: return fanuc_t;
    case Dialect::MazakM: return tables::kMazakRules;
    case Dialect::SiemensIsoM: return tables::kSiemensIsoRules;
    case Dialect::SiemensDin: return siemens_din;
  }
  return tables::kFanucRules;
}

std::optional<int64_t> MacroRules::userAlarmNumber(int64_t n) const {
  for (const UserAlarmRange& r : user_alarms)
    if (n >= r.first && n <= r.last) return n + r.offset;
  return std::nullopt;
}

std::vector<std::string> MacroRules::programFileCandidates(int64_t number) const {
  std::vector<std::string> names;
  if (number < 0) return names;
  const std::string plain = absl::StrCat(number);
  const std::string padded = absl::StrFormat("%04d", number);
  for (std::string_view pattern : program_file_names) {
    std::string name = absl::StrReplaceAll(std::string(pattern),
                                           {{"{:04}", padded}, {"{}", plain}});
    if (std::find(names.begin(), names.end(), name) == names.end())
      names.push_back(std::move(name));
  }
  return names;
}

const MacroRules::CommonSet* MacroRules::commonSet(std::string_view name) const {
  for (const CommonSet& s : common_sets)
    if (s.name == name) return &s;
  return nullptr;
}

}  // namespace ncc::eval
