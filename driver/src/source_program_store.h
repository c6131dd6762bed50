#pragma once
// The evaluator's blocks read from source files: cursors are BlockReaders that seek, programs
// and sequence numbers are found through the frontend's program library and indexes
// (docs/middle.md, Block sources).
#include <filesystem>
#include <map>
#include <memory>
#include <set>
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
  std::optional<eval::ProgramPoint> findLabel(std::string_view label, const eval::ProgramPoint& from,
                                              eval::SequenceSearch order,
                                              const eval::ProgramPoint& begin,
                                              const eval::ProgramPoint& end) override;
  eval::ProgramPoint programEnd(const eval::ProgramPoint& start) override;

  // The reader under a cursor this store opened (for the text after the program's end).
  static frontend::BlockReader& readerOf(eval::BlockCursor& cursor);

  // What the compile asked of this store, for the block store (block_store_builder.h): the
  // files opened, the program numbers asked that the calling file did not hold (found in the
  // folder or not), and the names found.
  const std::set<uint32_t>& openedFiles() const { return opened_; }
  const std::set<int64_t>& folderNumbers() const { return folder_numbers_; }
  const std::map<std::string, eval::ProgramPoint, std::less<>>& namedPrograms() const {
    return named_;
  }
  // Program n in the program folder only (ProgramLibrary steps 2-3).
  std::optional<eval::ProgramPoint> findInFolder(int64_t number);
  frontend::ProgramIndex& index(uint32_t file) { return library_.index(file); }
  SourceManager& sources() const { return sources_; }
  const frontend::ReaderOptions& readerOptions() const { return options_; }

 private:
  SourceManager& sources_;
  DiagnosticEngine& diags_;
  frontend::ReaderOptions options_;
  frontend::ProgramLibrary library_;
  std::filesystem::path folder_;
  std::vector<std::string> extensions_;  // of the name patterns: ".nc", ".spf", ...
  std::set<uint32_t> opened_;
  std::set<int64_t> folder_numbers_;
  std::map<std::string, eval::ProgramPoint, std::less<>> named_;
};

}  // namespace ncc::driver
