// ProgramLibrary: where a called program is found (the calling file, then the folder by name,
// then by first program number), with the caller's name patterns, in a scratch folder.
#include <gtest/gtest.h>

#include "ncc/frontend/program_library.h"
#include "temp_dir.h"

namespace ncc::frontend {
namespace {

using testing::TempDir;

std::string blockAt(const SourceManager& sm, ProgramLibrary::Found found) {
  DiagnosticEngine diags(&sm);
  BlockReader reader(sm, found.file, diags);
  reader.seek(found.start);
  auto b = reader.next();
  return b ? printBlock(*b) : "<none>";
}

TEST(ProgramLibrary, FormatName) {
  EXPECT_EQ(ProgramLibrary::formatName("O{:04}.nc", 12), "O0012.nc");
  EXPECT_EQ(ProgramLibrary::formatName("O{:04}.nc", 123456), "O123456.nc");
  EXPECT_EQ(ProgramLibrary::formatName("{}.nc", 12), "12.nc");
  EXPECT_EQ(ProgramLibrary::formatName("L{:08}.SPF", 7), "L00000007.SPF");
  EXPECT_EQ(ProgramLibrary::formatName("{}-{}", 5), "5-5");
  EXPECT_EQ(ProgramLibrary::formatName("{x}{:4}{", 5), "{x}{:4}{");  // kept as written
}

TEST(ProgramLibrary, CallingFileFirstThenNameThenFirstProgramNumber) {
  TempDir dir;
  dir.write("main.nc", "O1\nM98 P10\nM98 P20\nM30\nO10 (IN MAIN)\nM99\n");
  dir.write("O0010.nc", "O10 (BY NAME)\nM99\n");
  dir.write("O0020.nc", "(no O block)\nG0 X20\nM99\n");
  dir.write("O0030.nc", "G0 X1\nO30 (SECOND PROGRAM OF THE FILE)\nM99\n");
  dir.write("b.nc", "O40 (B)\nM99\n");
  dir.write("a.NC", "%\n(header)\nO40 (A)\nM99\n%\n");
  dir.write("c.txt", "O50 (not a program file)\nM99\n");
  dir.write("d.nc", "G0 X1\nO50 (not the first program)\nM99\n");
  SourceManager sm;
  const uint32_t main = sm.addFile(dir.path() / "main.nc");
  ProgramLibrary library(sm, dir.path(), {"O{:04}.nc", "{}.nc"}, {});

  auto found = library.find(10, main);  // in the calling file, before O0010.nc
  ASSERT_TRUE(found);
  EXPECT_EQ(found->file, main);
  EXPECT_EQ(blockAt(sm, *found), "O10 (IN MAIN)");

  found = library.find(20, main);  // by name, no O block: the file's start
  ASSERT_TRUE(found);
  EXPECT_EQ(found->file, sm.addFile(dir.path() / "O0020.nc"));
  EXPECT_EQ(found->start, BlockPosition{});
  EXPECT_EQ(blockAt(sm, *found), "(no O block)");

  found = library.find(30, main);  // by name, its O block
  ASSERT_TRUE(found);
  EXPECT_EQ(blockAt(sm, *found), "O30 (SECOND PROGRAM OF THE FILE)");

  found = library.find(40, main);  // by first program number: a.NC before b.nc
  ASSERT_TRUE(found);
  EXPECT_EQ(found->file, sm.addFile(dir.path() / "a.NC"));
  EXPECT_EQ(blockAt(sm, *found), "O40 (A)");

  EXPECT_FALSE(library.find(50, main));  // .txt is not an extension of the patterns; d.nc's
                                         // first program is not O50
  EXPECT_FALSE(library.find(60, main));
  EXPECT_FALSE(library.find(-1, main));
  // The same file twice is the same id and the same index.
  EXPECT_EQ(&library.index(found->file), &library.index(sm.addFile(dir.path() / "a.NC")));
}

TEST(ProgramLibrary, PatternsInOrderAndNamesIgnoringCase) {
  TempDir dir;
  dir.write("main.nc", "M98 P7\nM30\n");
  dir.write("7.nc", "(seven by {})\nM99\n");
  dir.write("O0007.NC", "(seven by O{:04}.nc, other case)\nM99\n");
  SourceManager sm;
  const uint32_t main = sm.addFile(dir.path() / "main.nc");
  {
    ProgramLibrary library(sm, dir.path(), {"{}.nc", "O{:04}.nc"}, {});
    auto found = library.find(7, main);
    ASSERT_TRUE(found);
    EXPECT_EQ(sm.path(found->file).filename(), "7.nc");
  }
  {
    ProgramLibrary library(sm, dir.path(), {"O{:04}.nc", "{}.nc"}, {});
    auto found = library.find(7, main);
    ASSERT_TRUE(found);
    EXPECT_EQ(sm.path(found->file).filename(), "O0007.NC");
  }
  {
    ProgramLibrary library(sm, dir.path(), {"{:04}.spf"}, {});
    EXPECT_FALSE(library.find(7, main));
  }
}

TEST(ProgramLibrary, UnreadableFolderAndFilesAreSkipped) {
  SourceManager sm;
  const uint32_t main = sm.addBuffer("stdin", "M98 P1\nM30\nO2\nM99\n");
  ProgramLibrary no_folder(sm, {}, {"O{:04}.nc"}, {});  // a program from stdin
  EXPECT_FALSE(no_folder.find(1, main));
  EXPECT_TRUE(no_folder.find(2, main));  // the buffer itself is searched
  ProgramLibrary missing(sm, "/nonexistent/ncc/folder", {"O{:04}.nc"}, {});
  EXPECT_FALSE(missing.find(1, main));

  // A name that is a folder, and a link to nothing: not readable files, skipped.
  TempDir dir;
  std::filesystem::create_directory(dir.path() / "O0001.nc");
  std::filesystem::create_symlink(dir.path() / "nothing.nc", dir.path() / "O0002.nc");
  dir.write("x.nc", "O1 (readable, found by first program number)\nM99\n");
  dir.write("y.nc", "O2 (readable, found by first program number)\nM99\n");
  ProgramLibrary library(sm, dir.path(), {"O{:04}.nc"}, {});
  auto found = library.find(1, main);
  ASSERT_TRUE(found);
  EXPECT_EQ(sm.path(found->file).filename(), "x.nc");
  found = library.find(3, main);
  EXPECT_FALSE(found);
  const uint32_t other = sm.addBuffer("other", "M98 P2\n");
  found = library.find(2, other);
  ASSERT_TRUE(found);
  EXPECT_EQ(sm.path(found->file).filename(), "y.nc");
}

}  // namespace
}  // namespace ncc::frontend
