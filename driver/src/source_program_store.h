#pragma once
// The evaluator's blocks read from source files: cursors are BlockReaders that seek, programs
// and sequence numbers are found through the frontend's program library and indexes
// (docs/middle.md, Block sources).
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "ncc/eval/program_store.h"
#include "ncc/frontend/block_reader.h"
#include "ncc/frontend/program_library.h"
#include "ncc/support/diagnostics.h"
#include "ncc/support/source_manager.h"

namespace ncc::driver {

class SourceProgramStore final : public eval::ProgramStore {
 public:
  SourceProgramStore(SourceManager& sources, DiagnosticEngine& diags,
                     std::filesystem::path program_dir, std::vector<std::string> name_patterns,
                     frontend::ReaderOptions options);

  std::unique_ptr<eval::BlockCursor> open(uint32_t file) override;
  std::optional<eval::ProgramPoint> findProgram(int64_t number, uint32_t calling_file) override;
  std::optional<eval::ProgramPoint> findProgramNamed(std::string_view name) override;
  std::optional<eval::ProgramPoint> findSequence(int64_t n, const eval::ProgramPoint& from,
                                                 eval::SequenceSearch order,
                                                 const eval::ProgramPoint& begin,
                                                 const eval::ProgramPoint& end) override;
  eval::ProgramPoint programEnd(const eval::ProgramPoint& start) override;

  // The reader under a cursor this store opened (for the text after the program's end).
  static frontend::BlockReader& readerOf(eval::BlockCursor& cursor);

 private:
  SourceManager& sources_;
  DiagnosticEngine& diags_;
  frontend::ReaderOptions options_;
  frontend::ProgramLibrary library_;
  std::filesystem::path folder_;
  std::vector<std::string> extensions_;  // of the name patterns: ".nc", ".spf", ...
};

}  // namespace ncc::driver
