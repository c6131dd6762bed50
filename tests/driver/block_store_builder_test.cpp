// The compiler side of the block store: which files the builder keeps, that a parsed program
// round-trips through the encoding, and that StoredProgramStore over the stored blocks answers
// every ProgramStore question as SourceProgramStore does over the source files.
#include "block_store_builder.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "../eval/block_store_compare.h"
#include "gtest/gtest.h"
#include "ncc/eval/evaluator.h"
#include "ncc/eval/variables.h"

namespace ncc::driver {
namespace {

namespace fs = std::filesystem;
using eval::ProgramPoint;
using eval::SequenceSearch;

const std::vector<std::string> kPatterns = {"O{:04}.nc", "O{}.nc", "{:04}.nc", "{}.nc"};

class TempFolder {
 public:
  TempFolder() {
    path_ = fs::temp_directory_path() /
            ("ncc_block_store_" + std::to_string(::getpid()) + "_" + std::to_string(counter_++));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempFolder() { fs::remove_all(path_); }
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(path_ / name, std::ios::binary) << text;
    return path_ / name;
  }
  const fs::path& path() const { return path_; }

 private:
  static inline int counter_ = 0;
  fs::path path_;
};

// A main program with a local subprogram after M30, every kind of statement, labels that are
// and are not a block's first word, two blocks on one line, and text after the closing '%'.
const char* kMain =
    "%\n"
    "O0001 (MAIN)\n"
    "N1 G90 G0 X0 Y0 ; N2 G17\n"
    "/2 N3 M98 P12\n"
    "G65 P34 A1. B-2.5\n"
    "#1 = 0\n"
    "N20 #1 = #1 + 1 (COUNT)\n"
    "IF [#1 LT 3] GOTO 20\n"
    "IF [#1 EQ 3] THEN #2 = SIN[30.] * [#1 + 2]\n"
    "WHILE [#2 GT 0] DO 1\n"
    "#2 = #2 - 1\n"
    "END 1\n"
    "G1 N20 X1. ,C2.\n"
    "M98 P100\n"
    "N40 M30\n"
    "O100 (LOCAL)\n"
    "N10 G1 X1. F100\n"
    "N30 G1 X2.\n"
    "N10 G1 X3.\n"
    "M99\n"
    "%\n"
    "this is not a program ((\n";

void writeFolder(const TempFolder& t) {
  t.write("main.nc", kMain);
  t.write("O0012.nc", "O12 (SUB)\nN5 M98 P56\nN6 G1 Y1.\nM99\n");
  t.write("34.nc", "(MACRO WITHOUT O)\n#100 = #1 + #2\nN7 M99\n");
  t.write("probe.nc", "%\n(HEADER)\nO56\nN1 G31 Z-10. F50\nM99\n%\n");
  t.write("O0077.nc", "O77\nM99\n");  // called by nobody
}

struct Fixture {
  Fixture() : diags(&sources) {
    writeFolder(folder);
    main = sources.addFile(folder.path() / "main.nc");
  }
  TempFolder folder;
  SourceManager sources;
  DiagnosticEngine diags;
  uint32_t main = 0;
};

std::set<std::string> names(const eval::BlockStore& s) {
  std::set<std::string> out;
  for (const eval::StoredFile& f : s.files) out.insert(f.name);
  return out;
}

std::string diagnosticsText(const DiagnosticEngine& diags) {
  std::string out;
  for (const Diagnostic& d : diags.diagnostics()) out += diags.format(d) + "\n";
  return out;
}

TEST(BlockStoreBuilder, KeepsTheFilesLiteralCallsReach) {
  Fixture fx;
  SourceProgramStore store(fx.sources, fx.diags, fx.folder.path(), kPatterns, {});
  const eval::BlockStore s = buildBlockStore(store, fx.main, {}, fx.diags);
  EXPECT_FALSE(fx.diags.hasErrors()) << diagnosticsText(fx.diags);
  // M98 P12 -> O0012.nc, G65 P34 -> 34.nc (by name), O12's M98 P56 -> probe.nc (first O
  // number); M98 P100 stays in main.nc; O0077.nc is not called.
  EXPECT_EQ(names(s), (std::set<std::string>{"main.nc", "O0012.nc", "34.nc", "probe.nc"}));
  EXPECT_EQ(s.main_file, fx.main);
  EXPECT_EQ(s.files.front().id, fx.main);
  ASSERT_EQ(s.folder_programs.size(), 3u);
  EXPECT_EQ(s.folder_programs.at(34).position, frontend::BlockPosition{});  // no O block
  EXPECT_EQ(s.folder_programs.at(56).position.line, 3u);
  EXPECT_FALSE(s.folder_programs.count(100));
  // The main file stops at its closing '%': the text after it is not read (nor reported).
  const eval::StoredFile& main = s.files.front();
  EXPECT_TRUE(main.blocks.back().block.percent);
  EXPECT_EQ(main.record_end, main.blocks.back().position);
  EXPECT_EQ(main.blocks.back().position.line, 21u);
  // Labels as the text scan reads them: `G1 N20` is not one.
  int labelled_20 = 0;
  for (const eval::StoredBlock& b : main.blocks)
    labelled_20 += b.start == eval::StoredBlock::Start::Sequence && b.block.sequence == 20;
  EXPECT_EQ(labelled_20, 1);
}

TEST(BlockStoreBuilder, KeepsWhatTheCompileAskedForAndTheCodeMacros) {
  Fixture fx;
  fx.folder.write("TOOL_CHANGE.nc", "G91 G28 Z0\nM99\n");
  fx.folder.write("O9006.nc", "O9006\nM99\n");
  fx.folder.write("O0123.nc", "O123\nM99\n");
  SourceProgramStore store(fx.sources, fx.diags, fx.folder.path(), kPatterns, {});
  // What the compile asked: O77 (found in the folder), O4242 (found nowhere).
  EXPECT_TRUE(store.findProgram(77, fx.main));
  EXPECT_FALSE(store.findProgram(4242, fx.main));
  EXPECT_TRUE(store.findProgram(100, fx.main));  // local: nothing to record
  EXPECT_EQ(store.folderNumbers(), (std::set<int64_t>{77, 4242}));
  BlockStoreTargets targets;
  targets.code_macros = {{"M6", "TOOL_CHANGE"}, {"M106", "9006"}, {"M107", "NOWHERE"}};
  const eval::BlockStore s = buildBlockStore(store, fx.main, targets, fx.diags);
  EXPECT_FALSE(fx.diags.hasErrors()) << diagnosticsText(fx.diags);
  EXPECT_EQ(names(s), (std::set<std::string>{"main.nc", "O0012.nc", "34.nc", "probe.nc",
                                             "O0077.nc", "TOOL_CHANGE.nc", "O9006.nc"}));
  EXPECT_TRUE(s.folder_programs.count(77));
  EXPECT_TRUE(s.folder_programs.count(9006));
  EXPECT_FALSE(s.folder_programs.count(4242));
  ASSERT_TRUE(s.named_programs.count("TOOL_CHANGE"));
  EXPECT_EQ(s.named_programs.at("TOOL_CHANGE").position, frontend::BlockPosition{});
  EXPECT_FALSE(s.named_programs.count("NOWHERE"));
}

TEST(BlockStoreBuilder, RepeatCountsInPAreReadBothWays) {
  Fixture fx;
  fx.folder.write("O0021.nc", "O21\nM99\n");
  fx.folder.write("O30022.nc", "O30022\nM99\n");
  const fs::path main = fx.folder.write("repeat.nc", "M98 P30021\nM98 P30022\nM98 P50099\nM30\n");
  SourceProgramStore store(fx.sources, fx.diags, fx.folder.path(), kPatterns, {});
  const eval::BlockStore s = buildBlockStore(store, fx.sources.addFile(main), {}, fx.diags);
  EXPECT_FALSE(fx.diags.hasErrors()) << diagnosticsText(fx.diags);
  // P30021: O21 three times (O30021 does not exist); P30022: O30022 (O22 does not exist);
  // P50099: neither exists, so nothing.
  EXPECT_EQ(names(s), (std::set<std::string>{"repeat.nc", "O0021.nc", "O30022.nc"}));
  BlockStoreTargets no_count;
  no_count.program_number_digits = 0;
  SourceProgramStore again(fx.sources, fx.diags, fx.folder.path(), kPatterns, {});
  EXPECT_EQ(names(buildBlockStore(again, fx.sources.addFile(main), no_count, fx.diags)),
            (std::set<std::string>{"repeat.nc", "O30022.nc"}));
}

TEST(BlockStoreBuilder, UnparsableReachableTextIsAnError) {
  Fixture fx;
  fx.folder.write("O0012.nc", "O12\nG1 X[1+\nM99\n");  // the called program does not parse
  SourceProgramStore store(fx.sources, fx.diags, fx.folder.path(), kPatterns, {});
  buildBlockStore(store, fx.main, {}, fx.diags);
  ASSERT_TRUE(fx.diags.hasErrors());
  EXPECT_NE(diagnosticsText(fx.diags).find("O0012.nc:2:"), std::string::npos)
      << diagnosticsText(fx.diags);
}

TEST(BlockStoreBuilder, TextAfterTheMainProgramsEndIsNeverAnError) {
  // docs/cli.md, The end of a program: what follows M30 is not parsed by the compile (a
  // warning at most); the stored program after it is still kept.
  Fixture fx;
  const fs::path main = fx.folder.write(
      "end.nc", "G0 X1.\nM30\nG00 X@@@\nN5 G0 X5.\nO100\nN1 G1 X2. F10.\nM99\n%\nX@@@\n");
  const uint32_t id = fx.sources.addFile(main);
  BlockStoreTargets targets;
  targets.main_end = ProgramPoint{id, {7, 2, 1}};  // M30
  SourceProgramStore store(fx.sources, fx.diags, fx.folder.path(), kPatterns, {});
  const eval::BlockStore s = buildBlockStore(store, id, targets, fx.diags);
  EXPECT_TRUE(fx.diags.diagnostics().empty()) << diagnosticsText(fx.diags);
  ASSERT_EQ(s.files.size(), 1u);
  std::vector<uint32_t> lines;
  for (const eval::StoredBlock& b : s.files[0].blocks) lines.push_back(b.position.line);
  // Line 3 does not parse and is left out; N5 after it parses and is kept; line 9 is after '%'.
  EXPECT_EQ(lines, (std::vector<uint32_t>{1, 2, 4, 5, 6, 7, 8}));
  EXPECT_EQ(s.files[0].blocks[3].start, eval::StoredBlock::Start::Program);
  EXPECT_TRUE(s.files[0].blocks.back().block.percent);
  std::string error;
  ASSERT_TRUE(eval::decodeBlockStore(eval::encodeBlockStore(s), error)) << error;

  // Without the end (the compile stopped before it: the rest is prepared at run time) the
  // builder takes the main program's first M02/M30 block: the same store, no error.
  SourceProgramStore again(fx.sources, fx.diags, fx.folder.path(), kPatterns, {});
  const eval::BlockStore found = buildBlockStore(again, id, {}, fx.diags);
  EXPECT_TRUE(fx.diags.diagnostics().empty()) << diagnosticsText(fx.diags);
  EXPECT_EQ(eval::encodeBlockStore(found), eval::encodeBlockStore(s));
  // Text that does not parse before the M30 is an error (the run may reach it).
  const fs::path bad = fx.folder.write("bad.nc", "G0 X1.\nG00 X@@@\nM30\n");
  const uint32_t bad_id = fx.sources.addFile(bad);
  SourceProgramStore third(fx.sources, fx.diags, fx.folder.path(), kPatterns, {});
  buildBlockStore(third, bad_id, {}, fx.diags);
  EXPECT_NE(diagnosticsText(fx.diags).find("bad.nc:2:"), std::string::npos) << diagnosticsText(fx.diags);
}

TEST(BlockStoreBuilder, ParsedProgramsRoundTrip) {
  Fixture fx;
  SourceProgramStore store(fx.sources, fx.diags, fx.folder.path(), kPatterns, {});
  eval::BlockStore s = buildBlockStore(store, fx.main, {}, fx.diags);
  ASSERT_FALSE(fx.diags.hasErrors()) << diagnosticsText(fx.diags);
  s.saved_variables = {{500, 2.5}};
  s.limits.max_back_jumps = 5;
  s.ahead_blocks = 17;
  // The corpus's FANUC programs too: real CAM and hand-written text.
  size_t corpus_files = 0;
  for (const fs::directory_entry& e :
       fs::directory_iterator(fs::path(NCC_SOURCE_DIR) / "tests/corpus/fanuc-m")) {
    SourceManager sources;
    DiagnosticEngine diags(&sources);
    SourceProgramStore corpus(sources, diags, {}, kPatterns, {});
    eval::BlockStore one = buildBlockStore(corpus, sources.addFile(e.path()), {}, diags);
    if (diags.hasErrors()) continue;  // programs the parser refuses are tested elsewhere
    ++corpus_files;
    std::string error;
    std::optional<eval::BlockStore> decoded = eval::decodeBlockStore(eval::encodeBlockStore(one), error);
    ASSERT_TRUE(decoded) << e.path() << ": " << error;
    EXPECT_EQ(eval::test::diffStore(one, *decoded), "") << e.path();
  }
  EXPECT_GE(corpus_files, 20u);
  std::string error;
  std::optional<eval::BlockStore> decoded = eval::decodeBlockStore(eval::encodeBlockStore(s), error);
  ASSERT_TRUE(decoded) << error;
  EXPECT_EQ(eval::test::diffStore(s, *decoded), "");
}

// Every question of the ProgramStore interface, asked of both stores.
TEST(BlockStoreBuilder, StoredStoreAnswersAsTheSourceStore) {
  Fixture fx;
  SourceProgramStore source(fx.sources, fx.diags, fx.folder.path(), kPatterns, {});
  const eval::BlockStore built = buildBlockStore(source, fx.main, {}, fx.diags);
  ASSERT_FALSE(fx.diags.hasErrors()) << diagnosticsText(fx.diags);
  std::string error;
  const std::optional<eval::BlockStore> decoded =
      eval::decodeBlockStore(eval::encodeBlockStore(built), error);
  ASSERT_TRUE(decoded) << error;
  eval::StoredProgramStore stored(*decoded);

  const std::vector<int64_t> numbers = {1, 2, 3, 5, 6, 7, 10, 12, 20, 30, 34, 40, 56, 100, 999};
  size_t files = 0, sequence_answers = 0;
  for (const eval::StoredFile& f : decoded->files) {
    ++files;
    // The blocks, read straight through, and after seeking to each block and between blocks.
    std::unique_ptr<eval::BlockCursor> a = source.open(f.id);
    std::unique_ptr<eval::BlockCursor> b = stored.open(f.id);
    EXPECT_EQ(a->lastPoint(), b->lastPoint());
    size_t count = 0;
    while (const ast::Block* y = b->next()) {
      const ast::Block* x = a->next();
      ASSERT_TRUE(x) << f.name;
      EXPECT_EQ(eval::test::diffBlock(*x, *y, f.name), "");
      EXPECT_EQ(a->lastPoint(), b->lastPoint()) << f.name;
      ++count;
    }
    EXPECT_EQ(count, f.blocks.size());
    // The points a reader may seek to: a file's start (a program found by name) and blocks.
    std::vector<ProgramPoint> points{{f.id, {}}};
    for (const eval::StoredBlock& block : f.blocks) points.push_back({f.id, block.position});
    for (size_t i = points.size(); i-- > 0;) {  // backwards: every seek goes back
      a->seek(points[i]);
      b->seek(points[i]);
      const ast::Block* y = b->next();
      if (!y) continue;  // after the last stored block (the source would read on past '%')
      const ast::Block* x = a->next();
      ASSERT_TRUE(x);
      EXPECT_EQ(eval::test::diffBlock(*x, *y, f.name), "");
      EXPECT_EQ(a->lastPoint(), b->lastPoint());
    }

    // The numbers the program calls (in the file or the folder) and one that exists nowhere.
    for (int64_t n : {12, 34, 56, 100, 999})
      EXPECT_EQ(source.findProgram(n, f.id), stored.findProgram(n, f.id)) << f.name << " O" << n;
    // Programs never asked for are not kept: main.nc's O1 is found in the folder by its first
    // O number from the source files, not from another stored file.
    if (f.id != fx.main) {
      EXPECT_TRUE(source.findProgram(1, f.id));
      EXPECT_FALSE(stored.findProgram(1, f.id));
    }
    for (const ProgramPoint& p : points)
      EXPECT_EQ(source.programEnd(p), stored.programEnd(p)) << f.name << " @" << p.position.offset;
    // Ranges: the whole record and each program's own text.
    std::vector<std::pair<ProgramPoint, ProgramPoint>> ranges{
        {{f.id, {}}, {f.id, f.record_end}}};
    for (const eval::StoredBlock& block : f.blocks)
      if (block.start == eval::StoredBlock::Start::Program) {
        const ProgramPoint begin{f.id, block.position};
        ranges.push_back({begin, source.programEnd(begin)});
      }
    for (const auto& [begin, end] : ranges)
      for (const ProgramPoint& from : points)
        for (int64_t n : numbers)
          for (SequenceSearch order : {SequenceSearch::ForwardThenFromStart, SequenceSearch::FromStart}) {
            const std::optional<ProgramPoint> x = source.findSequence(n, from, order, begin, end);
            EXPECT_EQ(x, stored.findSequence(n, from, order, begin, end))
                << f.name << " N" << n << " from line " << from.position.line << " in ["
                << begin.position.line << ", " << end.position.line << ")";
            sequence_answers += x.has_value();
          }
  }
  EXPECT_EQ(files, 4u);
  EXPECT_GT(sequence_answers, 100u);  // the comparison is not only of "not found"
  // Names are kept only for the code macros (none here).
  EXPECT_FALSE(stored.findProgramNamed("34"));
}

// The evaluator's output over each store: what reaches lowering. M30 ends the program as
// lowering would say.
std::vector<ast::Block> evaluate(eval::ProgramStore& store, uint32_t main, DiagnosticEngine& diags) {
  const eval::MacroRules& rules = eval::macroRules(Dialect::FanucM);
  eval::Variables variables(rules, {rules.commons.begin(), rules.commons.end()}, nullptr);
  eval::EvaluatorOptions options;
  options.rules = &rules;
  options.repeat = eval::RepeatEncoding::HighDigitsOfP;
  eval::Evaluator evaluator(options, store, store.open(main), variables, diags);
  std::vector<ast::Block> out;
  while (const ast::Block* b = evaluator.next()) {
    out.push_back(*b);
    for (const ast::Word& w : b->words)
      if (w.address == "M" && w.value.number == 30) evaluator.programEndCode();
  }
  EXPECT_EQ(evaluator.end(), eval::ProgramEnd::ProgramEndCode);
  return out;
}

TEST(BlockStoreBuilder, TheEvaluatorReadsTheSameProgramFromBothStores) {
  Fixture fx;
  SourceProgramStore source(fx.sources, fx.diags, fx.folder.path(), kPatterns, {});
  const std::vector<ast::Block> compiled = evaluate(source, fx.main, fx.diags);
  ASSERT_FALSE(fx.diags.hasErrors()) << diagnosticsText(fx.diags);
  const eval::BlockStore built = buildBlockStore(source, fx.main, {}, fx.diags);
  std::string error;
  const std::optional<eval::BlockStore> decoded =
      eval::decodeBlockStore(eval::encodeBlockStore(built), error);
  ASSERT_TRUE(decoded) << error;
  eval::StoredProgramStore stored(*decoded);
  DiagnosticEngine run_diags(&fx.sources);
  const std::vector<ast::Block> run = evaluate(stored, fx.main, run_diags);
  EXPECT_TRUE(run_diags.diagnostics().empty()) << diagnosticsText(run_diags);
  // Blocks for lowering came from all four files (34.nc's is its comment line).
  std::set<uint32_t> files;
  for (const ast::Block& b : run) files.insert(b.loc.file);
  EXPECT_EQ(files.size(), 4u);
  EXPECT_GE(run.size(), 16u);
  ASSERT_EQ(compiled.size(), run.size());
  for (size_t i = 0; i < run.size(); ++i)
    EXPECT_EQ(eval::test::diffBlock(compiled[i], run[i], absl::StrCat("block ", i)), "");
}

}  // namespace
}  // namespace ncc::driver
