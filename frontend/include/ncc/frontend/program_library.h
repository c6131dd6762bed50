#pragma once
// Finds the program a call names (M98 P, G65 P, an M99 return elsewhere) as a control's
// program memory would, in this order:
//  1. the calling file: a block starting with O n (or :n) in it;
//  2. the program folder by file name: each name pattern in the order given, `{}` standing for
//     the number and `{:04}` for it zero-padded to 4 digits (any width 1..20: `{:08}`), e.g.
//     "O{:04}.nc", "{}.nc", "{:04}.spf"; an exact name first, else the lexicographically first
//     file of the folder whose name matches ignoring ASCII case;
//  3. any file of the folder whose extension is one of the patterns' (ignoring case) and whose
//     first program block is O n, the lexicographically first name winning.
// Files found are registered with SourceManager::addFile(folder / name). A folder that cannot
// be listed and files that cannot be read are skipped, never thrown on. An empty folder path
// (a program read from stdin) searches the calling file only.
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ncc/frontend/program_index.h"

namespace ncc::frontend {

class ProgramLibrary {
 public:
  ProgramLibrary(SourceManager& sources, std::filesystem::path folder,
                 std::vector<std::string> name_patterns, ReaderOptions options);

  struct Found {
    uint32_t file;
    // The O block, or the file's start ({0, 1, 1}) when found by name without an O n block.
    BlockPosition start;
  };
  // nullopt when no program n exists (or n is negative).
  std::optional<Found> find(int64_t number, uint32_t calling_file);

  // Steps 2 and 3 only: the program folder, whatever the calling file holds.
  std::optional<Found> findInFolder(int64_t number);

  // One index per file, created on first use.
  ProgramIndex& index(uint32_t file);

  // A pattern with the number put in: formatName("O{:04}.nc", 12) == "O0012.nc". Text that is
  // not `{}` or `{:0w}` is kept as written.
  static std::string formatName(const std::string& pattern, int64_t number);

 private:
  // The regular files of the folder, sorted by name; listed once.
  const std::vector<std::string>& folderFiles();
  std::optional<Found> findByName(int64_t number);
  std::optional<Found> findByFirstProgram(int64_t number);

  SourceManager& sources_;
  std::filesystem::path folder_;
  std::vector<std::string> patterns_;
  ReaderOptions options_;
  std::map<uint32_t, std::unique_ptr<ProgramIndex>> indexes_;

  bool listed_ = false;
  std::vector<std::string> files_;
  // First program number of each folder file with a pattern's extension (step 3), read once
  // per file; nullopt when it has none or cannot be read.
  std::optional<std::map<std::string, std::optional<int64_t>>> first_numbers_;
};

}  // namespace ncc::frontend
