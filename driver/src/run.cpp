#include "ncc/driver/run.h"

#include <fstream>
#include <memory>
#include <sstream>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "ncc/bytecode/format.h"
#include "ncc/bytecode/loader.h"
#include "ncc/bytecode/verifier.h"
#include "ncc/driver/compile.h"
#include "scratch_file.h"

namespace ncc::driver {

bool isBytecodeFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[4] = {};
  if (in.read(magic, 4) && std::string_view(magic, 4) == "NCCB") return true;
  return absl::EndsWithIgnoreCase(path.string(), ".ncb");
}

bool isBytecodeInput(const Session& session) {
  if (const std::string* bytes = session.stdinContents()) return absl::StartsWith(*bytes, "NCCB");
  return isBytecodeFile(session.input());
}

namespace {

std::optional<bytecode::Error> loadBytes(std::string_view bytes, bytecode::Program& program) {
  return bytecode::load(
      std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()), program);
}

// Compiles the session's input into a scratch file and loads it paged.
std::optional<bytecode::Error> compilePaged(Session& session, bytecode::Program& program,
                                            bool& compiled) {
  ScratchFile scratch = makeScratchFile();
  if (!scratch.error.empty()) return bytecode::Error{"NCC0004", scratch.error};
  std::shared_ptr<const bytecode::ProgramFile> file = bytecode::ProgramFile::adopt(scratch.read_fd);
  compiled = emitBytecode(session, scratch.stream);
  if (!compiled) return std::nullopt;  // the compile's own diagnostics say why
  scratch.stream.flush();
  if (!scratch.stream)
    return bytecode::Error{"NCC0004", "cannot write the temporary bytecode file"};
  return bytecode::loadPaged(std::move(file), program);
}

}  // namespace

bool loadProgram(Session& session, bytecode::Program& program, bool check_machine,
                 Residence residence, std::optional<SetupError>* setup_error) {
  std::optional<bytecode::Error> error;
  const bool paged = residence == Residence::Paged;
  if (isBytecodeInput(session)) {
    const std::string* from_stdin = session.stdinContents();
    if (from_stdin) error = loadBytes(*from_stdin, program);
    else if (paged) error = bytecode::loadFilePaged(session.input(), program);
    else error = bytecode::loadFile(session.input(), program);
  } else if (paged) {
    bool compiled = false;
    error = compilePaged(session, program, compiled);
    if (!compiled && !error) return false;
    if (error && error->code == "NCC0004" && setup_error != nullptr) {
      *setup_error = SetupError{error->code, error->message};
      return false;
    }
  } else {
    std::stringstream buffer;
    if (!emitBytecode(session, buffer)) return false;
    const std::string bytes = std::move(buffer).str();  // C++20: moved out, not copied
    error = loadBytes(bytes, program);
  }
  if (!error) {
    bytecode::VerifyOptions options;
    // Without the machine check (disassembly) the file's own axis table is all there is.
    options.machine = check_machine ? &session.machine() : nullptr;
    options.check_config_hash = check_machine;
    error = bytecode::verify(program, options);
  }
  if (error) {
    session.diagnostics().error(error->code, SourceLocation{session.mainFile(), 0, 0},
                                error->code == "NCC0004"  // the scratch file
                                    ? error->message
                                    : absl::StrCat("invalid bytecode: ", error->message));
    return false;
  }
  return true;
}

}  // namespace ncc::driver
