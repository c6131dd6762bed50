#include "ncc/driver/variables_file.h"

#include "ncc/prepare/block_loop.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
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

// A path that names nothing yet: the first run creates the file (a folder on the way that is
// a file counts as missing too, as it always has; the write-back then fails).
bool missing(int error) { return error == ENOENT || error == ENOTDIR; }

const std::string kTooLarge = absl::StrCat("larger than ", kMaxVariablesFileBytes >> 20,
                                           " MiB, more than any controller's variables");

}  // namespace

std::optional<std::string> variablesFileProblem(const std::filesystem::path& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    if (missing(errno)) return std::nullopt;
    return std::string(std::strerror(errno));
  }
  // Not opened before this: opening a FIFO for reading waits for a writer.
  if (!S_ISREG(st.st_mode)) return std::string("not a regular file");
  if (static_cast<uint64_t>(st.st_size) > kMaxVariablesFileBytes) return kTooLarge;
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return std::string(std::strerror(errno));
  ::close(fd);
  return std::nullopt;
}

std::optional<std::map<int64_t, SavedVariable>> readVariablesFile(
    const std::filesystem::path& path, SourceManager& sources, DiagnosticEngine& diags) {
  std::map<int64_t, SavedVariable> out;
  // O_NONBLOCK: a FIFO opens at once (and is refused below) instead of waiting for a writer.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0 && missing(errno)) return out;
  const int open_error = errno;
  const uint32_t file = sources.addFile(path);
  std::string text;
  std::string why;
  struct stat st {};
  if (fd < 0) {
    why = std::strerror(open_error);
  } else if (::fstat(fd, &st) != 0) {
    why = std::strerror(errno);
  } else if (!S_ISREG(st.st_mode)) {
    why = "not a regular file";
  } else {
    // Bounded whatever the size said: a file may grow while it is read.
    char buffer[1 << 16];
    while (why.empty()) {
      const ssize_t n = ::read(fd, buffer, sizeof buffer);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) why = std::strerror(errno);
      if (n <= 0) break;
      text.append(buffer, static_cast<size_t>(n));
      if (text.size() > kMaxVariablesFileBytes) why = kTooLarge;
    }
  }
  if (fd >= 0) ::close(fd);
  if (!why.empty()) {
    diags.error(kBadFile, SourceLocation{file, 0, 0},
                absl::StrCat("cannot read the variables file '", path.string(), "': ", why));
    return std::nullopt;
  }
  toml::table root;
  try {
#if TOML_EXCEPTIONS
    try {
      root = toml::parse(text, path.string());
    } catch (const toml::parse_error& e) {
      diags.error(kBadFile, at(file, e.source()), std::string(e.description()));
      return std::nullopt;
    }
#else
    toml::parse_result parsed = toml::parse(text, path.string());
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
