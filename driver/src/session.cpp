#include "ncc/driver/session.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <system_error>

#include "absl/strings/str_cat.h"
#include "ncc/machine/machine_file.h"

namespace ncc::driver {

bool dialectSupported(Dialect d) {
  return d != Dialect::FanucT;
}

namespace {

// Why `input` cannot be read as a program, or nothing. Opening it is the only sure test of
// the permission (a file without read permission used to fail later, as a syntax error).
std::optional<SetupError> unreadable(const std::filesystem::path& input) {
  std::error_code ec;
  auto fail = [&](const std::string& why) {
    return SetupError{"NCC0001", absl::StrCat("cannot read '", input.string(), "': ", why)};
  };
  const std::filesystem::file_status status = std::filesystem::status(input, ec);
  if (!std::filesystem::exists(status)) {
    // A folder on the way that cannot be searched is not "no such file".
    return fail(ec && ec != std::errc::no_such_file_or_directory ? ec.message() : "no such file");
  }
  if (!std::filesystem::is_regular_file(status)) return fail("not a regular file");
  std::ifstream probe(input, std::ios::binary);
  if (!probe) return fail(std::strerror(errno));
  return std::nullopt;
}

}  // namespace

std::optional<SetupError> Session::open(const std::filesystem::path& input,
                                        const SessionOptions& options) {
  const bool from_stdin = input == kStdinName;
  if (!from_stdin) {
    if (std::optional<SetupError> error = unreadable(input)) return error;
  }
  input_ = input;
  // --dialect, else the machine file's [machine] dialect, else from the file name.
  const Dialect by_name = from_stdin ? Dialect::FanucM : dialectFromFileName(input.filename().string());
  loop_limits_ = options.loop_limits;
  bounds_ = options.bounds;
  bound_action_ = options.bound_action;
  variables_file_ = options.variables_file;
  defer_ = options.defer;
  if (options.machine_file) {
    if (std::optional<SetupError> error = unreadable(*options.machine_file)) {
      error->code = "NCC0003";
      return error;
    }
    MachineFileOptions file_options;
    file_options.dialect = options.dialect;
    file_options.default_dialect = by_name;
    std::optional<MachineConfig> loaded =
        loadMachineFile(*options.machine_file, sources_, diags_, file_options);
    if (!loaded)
      return SetupError{"NCC0003", absl::StrCat("invalid machine file '", options.machine_file->string(), "'")};
    machine_ = std::move(*loaded);
    machine_file_ = options.machine_file;
  } else {
    machine_ = defaultMachine();
  }
  dialect_ = options.dialect.value_or(machine_.dialect.value_or(by_name));
  if (!dialectSupported(dialect_)) {
    return SetupError{"NCC0002", absl::StrCat("dialect '", std::string(dialectName(dialect_)),
                                              "' is not supported yet (supported: fanuc-m, "
                                              "mazak-m, siemens-iso-m, siemens-din)")};
  }
  if (from_stdin) {
    program_dir_ = options.program_dir.value_or(std::filesystem::path("."));
    std::string contents((std::istreambuf_iterator<char>(std::cin)), std::istreambuf_iterator<char>());
    if (std::cin.bad()) return SetupError{"NCC0001", "cannot read the standard input"};
    main_file_ = sources_.addBuffer("<stdin>", std::move(contents));
    return std::nullopt;
  }
  program_dir_ = options.program_dir.value_or(input.has_parent_path() ? input.parent_path()
                                                                      : std::filesystem::path("."));
  main_file_ = sources_.addFile(input);
  return std::nullopt;
}

std::vector<InputFile> Session::inputFiles() const {
  std::vector<InputFile> files;
  if (machine_file_) files.push_back({*machine_file_, "the machine file"});
  if (variables_file_) files.push_back({*variables_file_, "the variables file"});
  for (uint32_t id = 1; id <= sources_.fileCount(); ++id) {
    if (sources_.buffer(id)) continue;  // stdin
    const std::filesystem::path& path = sources_.path(id);
    if (id == main_file_) files.push_back({path, "the program"});
    else if ((!machine_file_ || path != *machine_file_) &&
             (!variables_file_ || path != *variables_file_))
      files.push_back({path, "the subprogram"});
  }
  return files;
}

}  // namespace ncc::driver
