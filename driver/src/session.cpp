#include "ncc/driver/session.h"

#include <system_error>

#include "absl/strings/str_cat.h"
#include "ncc/machine/machine_file.h"

namespace ncc::driver {

bool dialectSupported(Dialect d) {
  return d == Dialect::FanucM || d == Dialect::MazakM || d == Dialect::SiemensIsoM;
}

std::optional<SetupError> Session::open(const std::filesystem::path& input,
                                        const SessionOptions& options) {
  std::error_code ec;
  if (!std::filesystem::exists(input, ec))
    return SetupError{absl::StrCat("cannot read '", input.string(), "': no such file")};
  if (!std::filesystem::is_regular_file(input, ec))
    return SetupError{absl::StrCat("cannot read '", input.string(), "': not a regular file")};
  input_ = input;
  // --dialect, else the machine file's [machine] dialect, else from the file name.
  const Dialect by_name = dialectFromFileName(input.filename().string());
  if (options.machine_file) {
    MachineFileOptions file_options;
    file_options.dialect = options.dialect;
    file_options.default_dialect = by_name;
    std::optional<MachineConfig> loaded =
        loadMachineFile(*options.machine_file, sources_, diags_, file_options);
    if (!loaded) return SetupError{absl::StrCat("invalid machine file '", options.machine_file->string(), "'")};
    machine_ = std::move(*loaded);
  } else {
    machine_ = defaultMachine();
  }
  dialect_ = options.dialect.value_or(machine_.dialect.value_or(by_name));
  if (!dialectSupported(dialect_)) {
    return SetupError{absl::StrCat("dialect '", std::string(dialectName(dialect_)),
                                   "' is not supported yet (supported: fanuc-m, mazak-m, "
                                   "siemens-iso-m)")};
  }
  program_dir_ = options.program_dir.value_or(input.has_parent_path() ? input.parent_path()
                                                                      : std::filesystem::path("."));
  main_file_ = sources_.addFile(input);
  return std::nullopt;
}

}  // namespace ncc::driver
