// The block store without the parser: its encoding round-trips every field of the syntax tree
// bit for bit, the decoder refuses damaged input without crashing, and StoredProgramStore
// answers the program store's questions from the stored blocks. The comparison with the
// compiler's SourceProgramStore on real files is in tests/driver/block_store_builder_test.cpp.
#include "ncc/eval/block_store.h"

#include <cmath>
#include <limits>
#include <random>

#include "block_store_compare.h"
#include "gtest/gtest.h"

namespace ncc::eval {
namespace {

using test::diffStore;
using Kind = ast::Expr::Kind;
using Start = StoredBlock::Start;

// EncodingIsPinned: the size and FNV-1a hash of richStore() in version 3.
constexpr size_t kPinnedSize = 735;
constexpr uint64_t kPinnedHash = 14308647918551686207ull;

ast::Expr num(double v, bool point, SourceLocation loc, uint8_t digits = 0) {
  ast::Expr e = ast::Expr::literal(v, point, loc);
  e.digits = digits;
  return e;
}
// `op` as the table spells it ("" for none).
ast::Expr node(Kind kind, std::string_view op, std::vector<ast::Expr> args, SourceLocation loc) {
  ast::Expr e;
  e.kind = kind;
  e.op = ast::opNamed(op).value_or(ast::Op::None);
  e.args = std::move(args);
  e.loc = loc;
  return e;
}
ast::Expr var(double n, SourceLocation loc) { return node(Kind::Variable, "", {num(n, false, loc, 3)}, loc); }

StoredBlock stored(uint64_t offset, uint32_t line, uint32_t column, ast::Block b,
                   Start start = Start::Other) {
  return StoredBlock{{offset, line, column}, start, std::move(b)};
}

ast::Block plain(uint32_t file, uint32_t line, std::optional<int64_t> n = std::nullopt,
                 std::optional<int64_t> o = std::nullopt) {
  ast::Block b;
  b.loc = {file, line, 1};
  b.sequence = n;
  b.program_number = o;
  return b;
}

// A store with every field of every syntax tree type set, several ways.
BlockStore richStore() {
  BlockStore s;
  s.main_file = 3;
  s.ahead_blocks = 123456789012ull;
  s.limits.max_back_jumps = 77;
  s.limits.max_idle_blocks = 1234;
  s.saved_variables = {{500, 1.5}, {501, -0.0}, {-3, std::numeric_limits<double>::infinity()}};

  StoredFile f;
  f.id = 3;
  f.name = "MAIN.nc";
  ast::Block open_mark = plain(3, 1);
  open_mark.percent = true;
  f.blocks.push_back(stored(0, 1, 1, open_mark));
  f.blocks.push_back(stored(2, 2, 1, plain(3, 2, std::nullopt, 1234), Start::Program));

  // /3 N10 G01 X-0. Y1.5 Z[#1+SIN[30.]] F1e300 ,C#[2] (A) (B)
  ast::Block words = plain(3, 3, 10);
  words.loc.column = 2;
  words.skip_level = 3;
  words.comments = {"A", "", "with ) and \xc3\xa9"};
  const SourceLocation l3{3, 3, 5}, elsewhere{9, 40, 7};
  words.words.push_back({"G", num(1, false, l3, 2), l3});
  words.words.push_back({"X", num(-0.0, true, {3, 3, 9}, 1), {3, 3, 8}});
  words.words.push_back({"Y", num(1.5, true, l3, 2), l3});
  words.words.push_back(
      {"Z",
       node(Kind::Bracket, "",
            {node(Kind::Binary, "+",
                  {var(1, l3), node(Kind::Call, "SIN", {num(30, true, elsewhere, 2)}, l3)}, l3)},
            l3),
       l3});
  words.words.push_back({"F", num(1e300, false, l3, 4), l3});
  words.words.push_back({"Q", num(std::bit_cast<double>(uint64_t{0x7ff8000000000123}), true, l3), l3});
  words.words.push_back({"R", num(-9.0e15, false, l3, 16), l3});
  words.words.push_back({"S", num(static_cast<double>(1ull << 60), false, l3, 19), l3});
  words.words.push_back({",C", node(Kind::Variable, "", {node(Kind::Bracket, "", {num(2, false, l3)}, l3)}, l3), elsewhere});
  words.words.push_back({"U", node(Kind::Unary, "-", {node(Kind::Vacant, "", {}, {})}, l3), l3});
  // Decimals as written (m / 10^k), and values no short decimal gives back (their bits).
  for (double v : {0.1, -0.0015, 123.456789, 1e-7, 0.1 + 0.2, 1.0 / 3.0, 5e-324, 1e15 + 0.5})
    words.words.push_back({"V", num(v, true, l3, 9), l3});
  f.blocks.push_back(stored(10, 3, 1, words, Start::Sequence));

  // Statements: #1 = 2 ; GOTO 10 ; IF [#1 GT 0] GOTO 20 ; IF [..] THEN #2 = 3 ; WHILE DO 1 ; END 1
  ast::Block statements = plain(3, 4);
  ast::Statement assign;
  assign.kind = ast::Statement::Kind::Assign;
  assign.target = var(1, {3, 4, 1});
  assign.value = num(2, false, {3, 4, 5}, 1);
  assign.loc = {3, 4, 1};
  statements.statements.push_back(assign);
  ast::Statement go;
  go.kind = ast::Statement::Kind::Goto;
  go.target = num(10, false, {3, 4, 12});
  statements.statements.push_back(go);
  ast::Statement if_goto;
  if_goto.kind = ast::Statement::Kind::IfGoto;
  if_goto.value = node(Kind::Binary, "GT", {var(1, {3, 4, 20}), num(0, false, {3, 4, 27})}, {3, 4, 20});
  if_goto.target = num(20, false, {3, 4, 35});
  statements.statements.push_back(if_goto);
  ast::Statement if_then;
  if_then.kind = ast::Statement::Kind::IfThen;
  if_then.value = node(Kind::Binary, "EQ", {var(2, {3, 4, 40}), num(-1, false, {3, 4, 45})}, {3, 4, 40});
  if_then.then_assign = assign;
  if_then.then_assign->then_assign = go;  // nested: kept too
  statements.statements.push_back(if_then);
  ast::Statement loop;
  loop.kind = ast::Statement::Kind::While;
  loop.value = var(3, {4, 1, 1});
  loop.loop_id = 1;
  statements.statements.push_back(loop);
  ast::Statement end;
  end.kind = ast::Statement::Kind::End;
  end.loop_id = -2147483647 - 1;
  statements.statements.push_back(end);
  // Two blocks on one line (after a ';'): same offset, a later column.
  f.blocks.push_back(stored(60, 4, 1, statements));
  f.blocks.push_back(stored(60, 4, 30, plain(3, 4, 20), Start::Sequence));
  // A DIN block: a label, DEF of an array, an R parameter, a name with indices, a string and a
  // backward jump.
  ast::Block din = plain(5, 1);
  din.language = frontend::Language::Din;
  ast::Statement label;
  label.kind = ast::Statement::Kind::Label;
  label.target = node(Kind::Name, "", {}, {5, 5, 1});
  label.target.text = std::string("MA1");
  din.statements.push_back(label);
  ast::Statement def;
  def.kind = ast::Statement::Kind::Define;
  def.type = ast::DataType::Int;
  def.target = node(Kind::Name, "", {num(3, false, {5, 5, 20})}, {5, 5, 16});
  def.target.text = std::string("COUNT");
  def.value = node(Kind::Vacant, "", {}, {5, 5, 16});
  din.statements.push_back(def);
  ast::Statement r;
  r.kind = ast::Statement::Kind::Assign;
  r.target = node(Kind::RParam, "", {num(10, false, {5, 5, 31})}, {5, 5, 30});
  ast::Expr text = node(Kind::String, "", {}, {5, 5, 40});
  text.text = std::string("T\xC3\xA9");
  r.value = node(Kind::Binary, "DIV", {node(Kind::Name, "", {num(1, false, {5, 5, 36})}, {5, 5, 34}), text}, {5, 5, 38});
  r.value.args[0].text = std::string("COUNT");
  din.statements.push_back(r);
  ast::Statement back;
  back.kind = ast::Statement::Kind::IfGoto;
  back.jump = ast::Jump::Backward;
  back.value = node(Kind::Unary, "NOT", {num(0, false, {5, 5, 54})}, {5, 5, 50});
  back.target = label.target;
  din.statements.push_back(back);
  f.blocks.push_back(stored(80, 5, 1, din));
  // DIN control structures: a FOR (its counter's assignment nested) and a CASE with a DEFAULT
  // branch (the last statement kind).
  ast::Block for_block = plain(6, 1);
  for_block.language = frontend::Language::Din;
  ast::Statement for_loop;
  for_loop.kind = ast::Statement::Kind::For;
  for_loop.then_assign = r;
  for_loop.value = num(7, false, {6, 6, 20});
  for_block.statements.push_back(for_loop);
  ast::Statement branch;
  branch.kind = ast::Statement::Kind::CaseBranch;
  branch.jump = ast::Jump::Forward;
  branch.value = node(Kind::Vacant, "", {}, {6, 6, 30});
  branch.target = label.target;
  for_block.statements.push_back(branch);
  f.blocks.push_back(stored(120, 6, 1, for_block));
  ast::Block close = plain(3, 9);
  close.percent = true;
  close.sequence = 5;  // `N5 %`: a number that is not a label
  f.blocks.push_back(stored(4000000000ull, 9, 1, close));
  f.record_end = f.blocks.back().position;
  s.files.push_back(f);

  StoredFile sub;
  sub.id = 7;
  sub.name = "O0012.nc";
  sub.blocks.push_back(stored(0, 1, 1, plain(7, 1, std::nullopt, 12), Start::Program));
  sub.record_end = {100, 5, 1};
  s.files.push_back(sub);
  StoredFile empty;
  empty.id = 8;
  empty.name = "";
  s.files.push_back(empty);

  s.folder_programs = {{12, {7, {0, 1, 1}}}, {99999999, {8, {}}}};
  s.named_programs = {{"M6_MAKRO", {7, {0, 1, 1}}}, {"", {8, {}}}};
  return s;
}

TEST(BlockStore, RoundTripKeepsEveryField) {
  const BlockStore original = richStore();
  const std::vector<uint8_t> bytes = encodeBlockStore(original);
  std::string error;
  std::optional<BlockStore> decoded = decodeBlockStore(bytes, error);
  ASSERT_TRUE(decoded) << error;
  EXPECT_EQ(error, "");
  EXPECT_EQ(diffStore(original, *decoded), "");
  EXPECT_EQ(encodeBlockStore(*decoded), bytes);  // one encoding per store
  // The comparison sees what matters: a changed sign of zero is a difference.
  BlockStore changed = original;
  changed.files[0].blocks[2].block.words[1].value.number = 0.0;
  EXPECT_NE(diffStore(original, changed), "");
}

// The bytes of version 7, pinned: a change to a node's schema or to the codec changes them.
// Then raise kVersion (block_store.cpp) and write the new hash here.
TEST(BlockStore, EncodingIsPinned) {
  const std::vector<uint8_t> bytes = encodeBlockStore(richStore());
  uint64_t hash = 0xCBF29CE484222325ull;  // FNV-1a 64
  for (uint8_t b : bytes) hash = (hash ^ b) * 0x100000001B3ull;
  EXPECT_EQ(bytes.size(), kPinnedSize);
  EXPECT_EQ(hash, kPinnedHash) << std::hex << hash;
}

// Random trees (every node kind, operator, number form, location form and optional member)
// come back member for member, and encode to the same bytes again.
class RandomTree {
 public:
  explicit RandomTree(uint32_t seed) : rng_(seed) {}

  ast::Block block(uint32_t file, uint32_t line) {
    ast::Block b;
    b.loc = loc(file, line);
    if (chance(4)) b.skip_level = pick(0, 9);
    if (chance(3)) b.sequence = integer();
    if (chance(6)) b.program_number = integer();
    b.percent = chance(8);
    if (chance(3)) b.language = frontend::Language::Din;
    for (int i = pick(0, 6); i > 0; --i) {
      ast::Word& w = b.words.emplace_back();
      w.address = address();
      w.loc = loc(file, line);
      w.value = expr(file, line, pick(0, 4));
    }
    for (int i = chance(3) ? pick(1, 3) : 0; i > 0; --i)
      b.statements.push_back(statement(file, line, 2));
    for (int i = chance(4) ? pick(1, 2) : 0; i > 0; --i) {
      std::string c;
      for (int n = pick(0, 12); n > 0; --n) c.push_back(static_cast<char>(pick(1, 255)));
      b.comments.push_back(c);
    }
    return b;
  }

 private:
  int pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  bool chance(int one_in) { return pick(1, one_in) == 1; }
  int64_t integer() {
    return chance(2) ? pick(0, 99999) : static_cast<int64_t>(rng_()) << 20 | static_cast<int64_t>(rng_());
  }
  SourceLocation loc(uint32_t file, uint32_t line) {
    switch (pick(0, 4)) {
      case 0: return {};                                                  // none
      case 1: return {file + 1, static_cast<uint32_t>(pick(1, 1 << 30)), 7};  // another file
      default: return {file, line, static_cast<uint32_t>(pick(1, 5000))};
    }
  }
  ast::Address address() {
    switch (pick(0, 5)) {
      case 0: return ast::Address(std::string(",") + static_cast<char>('A' + pick(0, 25)));
      case 1: return ast::Address(std::string(static_cast<size_t>(pick(2, 14)), static_cast<char>('A' + pick(0, 25))));
      case 2: return ast::Address(static_cast<char>('a' + pick(0, 25)));
      default: return ast::Address(static_cast<char>('A' + pick(0, 25)));
    }
  }
  double number() {
    switch (pick(0, 6)) {
      case 0: return 0.0;
      case 1: return -0.0;
      case 2: return std::bit_cast<double>(static_cast<uint64_t>(rng_()) << 32 | rng_());  // any bits
      case 3: return static_cast<double>(pick(-100000, 100000)) / std::pow(10.0, pick(0, 16));
      default: return static_cast<double>(pick(-99999, 99999)) / 1000.0;
    }
  }
  ast::Expr expr(uint32_t file, uint32_t line, int depth) {
    ast::Expr e;
    e.kind = static_cast<Kind>(pick(0, ast::kEnumValues<Kind> - 1));
    e.op = static_cast<ast::Op>(pick(0, ast::kEnumValues<ast::Op> - 1));
    e.number = number();
    e.has_point = chance(2);
    e.digits = static_cast<uint8_t>(pick(0, 255));
    e.loc = loc(file, line);
    for (int i = depth > 0 ? pick(0, 3) : 0; i > 0; --i) e.args.push_back(expr(file, line, depth - 1));
    if (chance(3)) e.text = std::string(static_cast<size_t>(pick(0, 40)), static_cast<char>(pick(32, 126)));
    return e;
  }
  ast::Statement statement(uint32_t file, uint32_t line, int depth) {
    ast::Statement s;
    s.kind = static_cast<ast::Statement::Kind>(pick(0, ast::kEnumValues<ast::Statement::Kind> - 1));
    s.loc = loc(file, line);
    s.target = expr(file, line, 1);
    s.value = expr(file, line, 2);
    s.loop_id = chance(2) ? pick(-3, 3) : static_cast<int>(rng_());
    if (depth > 0 && chance(2)) s.then_assign = statement(file, line, depth - 1);
    s.type = static_cast<ast::DataType>(pick(0, ast::kEnumValues<ast::DataType> - 1));
    s.jump = static_cast<ast::Jump>(pick(0, ast::kEnumValues<ast::Jump> - 1));
    return s;
  }
  std::mt19937 rng_;
};

TEST(BlockStore, RandomTreesRoundTrip) {
  for (uint32_t seed = 1; seed <= 300; ++seed) {
    RandomTree random(seed);
    BlockStore s;
    s.main_file = 2;
    StoredFile f;
    f.id = 2;
    for (uint32_t line = 1; line <= 8; ++line)
      f.blocks.push_back(stored(line * 40, line, 1, random.block(2, line)));
    f.record_end = {1000, 9, 1};
    s.files.push_back(f);
    const std::vector<uint8_t> bytes = encodeBlockStore(s);
    std::string error;
    std::optional<BlockStore> decoded = decodeBlockStore(bytes, error);
    ASSERT_TRUE(decoded) << "seed " << seed << ": " << error;
    ASSERT_EQ(diffStore(s, *decoded), "") << "seed " << seed;
    ASSERT_EQ(encodeBlockStore(*decoded), bytes) << "seed " << seed;
  }
}

TEST(BlockStore, EmptyStoreRoundTrips) {
  std::string error;
  std::optional<BlockStore> decoded = decodeBlockStore(encodeBlockStore(BlockStore{}), error);
  ASSERT_TRUE(decoded) << error;
  EXPECT_EQ(diffStore(BlockStore{}, *decoded), "");
}

TEST(BlockStore, PlainBlocksAreCompact) {
  // N10 G01 X12.5 Y-3. F1000 on every line: about the size of its text (35 bytes a block).
  BlockStore s;
  s.main_file = 1;
  StoredFile f;
  f.id = 1;
  uint64_t offset = 0;
  for (uint32_t line = 1; line <= 1000; ++line) {
    ast::Block b = plain(1, line, line * 10);
    const auto at = [&](uint32_t column) { return SourceLocation{1, line, column}; };
    b.words = {{"G", num(1, false, at(8), 2), at(7)},
               {"X", num(12.5, true, at(11), 3), at(10)},
               {"Y", num(-3, true, at(17), 1), at(16)},
               {"F", num(1000, false, at(21), 4), at(20)}};
    f.blocks.push_back(stored(offset, line, 1, b, Start::Sequence));
    offset += 29;
  }
  f.record_end = {offset, 1001, 1};
  s.files.push_back(f);
  const std::vector<uint8_t> bytes = encodeBlockStore(s);
  EXPECT_LT(bytes.size(), 1000u * 40) << bytes.size();  // the text: 29 bytes a line
  std::string error;
  std::optional<BlockStore> decoded = decodeBlockStore(bytes, error);
  ASSERT_TRUE(decoded) << error;
  EXPECT_EQ(diffStore(s, *decoded), "");
}

TEST(BlockStore, EveryTruncationFailsWithAnError) {
  const std::vector<uint8_t> bytes = encodeBlockStore(richStore());
  for (size_t n = 0; n < bytes.size(); ++n) {
    std::string error;
    EXPECT_FALSE(decodeBlockStore(std::span(bytes.data(), n), error)) << "prefix " << n;
    EXPECT_NE(error, "") << "prefix " << n;
  }
}

// Uses a decoded store as the VM would: every cursor to its end, and the lookups.
void exercise(const BlockStore& s) {
  StoredProgramStore programs(s);
  for (const StoredFile& f : s.files) {
    std::unique_ptr<BlockCursor> c = programs.open(f.id);
    while (c->next()) {
    }
    c->seek({f.id, {}});
    c->next();
    programs.programEnd({f.id, {}});
    programs.findSequence(10, {f.id, {}}, SequenceSearch::ForwardThenFromStart, {f.id, {}},
                          {f.id, f.record_end});
    programs.findProgram(12, f.id);
  }
}

TEST(BlockStore, CorruptedCopiesNeverCrash) {
  const std::vector<uint8_t> bytes = encodeBlockStore(richStore());
  std::mt19937 random(20261127);
  int decoded = 0, refused = 0;
  for (int copy = 0; copy < 4000; ++copy) {
    std::vector<uint8_t> damaged = bytes;
    const int flips = 1 + copy % 4;
    for (int i = 0; i < flips; ++i) {
      const size_t at = random() % damaged.size();
      damaged[at] = copy % 3 == 0 ? static_cast<uint8_t>(random()) : damaged[at] ^ (1u << (random() % 8));
    }
    if (copy % 5 == 0) damaged.resize(random() % damaged.size());
    std::string error;
    std::optional<BlockStore> s = decodeBlockStore(damaged, error);
    if (!s) {
      EXPECT_NE(error, "");
      ++refused;
      continue;
    }
    ++decoded;
    exercise(*s);
    // What decodes encodes back to the same store.
    std::optional<BlockStore> again = decodeBlockStore(encodeBlockStore(*s), error);
    ASSERT_TRUE(again) << error;
    EXPECT_EQ(diffStore(*s, *again), "");
  }
  EXPECT_GT(refused, 1000);
  EXPECT_GT(decoded, 100);  // changed numbers, names, columns: still a store
}

TEST(BlockStore, HugeCountsAreRefusedBeforeAllocating) {
  // "NCBS" v7, main 1, ahead 0, jumps 0, idle blocks 0, no variables, then 2^62 files.
  std::vector<uint8_t> bytes = {'N', 'C', 'B', 'S', 7, 0, 1, 0, 0, 0, 0,
                                0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x40};
  std::string error;
  EXPECT_FALSE(decodeBlockStore(bytes, error));
  EXPECT_NE(error.find("count beyond the remaining bytes"), std::string::npos) << error;
  bytes = {'N', 'C', 'B', 'S', 8, 0};
  EXPECT_FALSE(decodeBlockStore(bytes, error));
  EXPECT_NE(error.find("version 8"), std::string::npos) << error;
  bytes = {'X', 'C', 'B', 'S', 1, 0};
  EXPECT_FALSE(decodeBlockStore(bytes, error));
  EXPECT_NE(error.find("NCBS"), std::string::npos) << error;
}

TEST(BlockStore, NestingIsBounded) {
  const auto nested = [](int depth) {
    ast::Expr e = num(1, false, {1, 1, 1});
    for (int i = 1; i < depth; ++i) e = node(Kind::Unary, "-", {std::move(e)}, {1, 1, 1});
    return e;
  };
  const auto storeWith = [](ast::Expr e) {
    BlockStore s;
    s.main_file = 1;
    StoredFile f;
    f.id = 1;
    ast::Block b = plain(1, 1);
    b.words.push_back({"X", std::move(e), {1, 1, 1}});
    f.blocks.push_back(stored(0, 1, 1, std::move(b)));
    s.files.push_back(std::move(f));
    return s;
  };
  BlockStore deep = storeWith(nested(kMaxStoredNesting));
  EXPECT_EQ(blockNesting(deep.files[0].blocks[0].block), kMaxStoredNesting);
  std::string error;
  EXPECT_TRUE(decodeBlockStore(encodeBlockStore(deep), error)) << error;
  BlockStore deeper = storeWith(nested(kMaxStoredNesting + 1));
  EXPECT_GT(blockNesting(deeper.files[0].blocks[0].block), kMaxStoredNesting);
  EXPECT_FALSE(decodeBlockStore(encodeBlockStore(deeper), error));
  EXPECT_NE(error.find("nested too deep"), std::string::npos) << error;
}

TEST(BlockStore, InconsistentStoresAreRefused) {
  std::string error;
  BlockStore s = richStore();
  std::swap(s.files[0].blocks[1], s.files[0].blocks[2]);
  EXPECT_FALSE(decodeBlockStore(encodeBlockStore(s), error));
  EXPECT_NE(error.find("out of order"), std::string::npos) << error;

  s = richStore();
  s.folder_programs[5] = {42, {}};
  EXPECT_FALSE(decodeBlockStore(encodeBlockStore(s), error));
  EXPECT_NE(error.find("not stored"), std::string::npos) << error;

  s = richStore();
  s.files[0].blocks[3].start = Start::Program;  // no O number in that block
  EXPECT_FALSE(decodeBlockStore(encodeBlockStore(s), error));
  EXPECT_NE(error.find("without its number"), std::string::npos) << error;

  s = richStore();
  s.files[1].id = 3;
  EXPECT_FALSE(decodeBlockStore(encodeBlockStore(s), error));
  EXPECT_NE(error.find("stored twice"), std::string::npos) << error;

  std::vector<uint8_t> bytes = encodeBlockStore(richStore());
  bytes.push_back(0);
  EXPECT_FALSE(decodeBlockStore(bytes, error));
  EXPECT_NE(error.find("after the end"), std::string::npos) << error;
}

// O1 / N10 / G1 N20 / N20 / N10 / M99 / O2 / N10 / M99 / % ; lines 1.., offsets 10 per line.
BlockStore labelledStore() {
  BlockStore s;
  s.main_file = 1;
  StoredFile f;
  f.id = 1;
  f.name = "MAIN.nc";
  const auto add = [&](std::optional<int64_t> n, std::optional<int64_t> o, Start start) {
    const uint32_t line = static_cast<uint32_t>(f.blocks.size() + 1);
    f.blocks.push_back(stored(10 * (line - 1), line, 1, plain(1, line, n, o), start));
  };
  add(std::nullopt, 1, Start::Program);  // 1
  add(10, std::nullopt, Start::Sequence);  // 2
  add(20, std::nullopt, Start::Other);     // 3: `G1 N20`, not a label
  add(20, std::nullopt, Start::Sequence);  // 4
  add(10, std::nullopt, Start::Sequence);  // 5
  add(std::nullopt, std::nullopt, Start::Other);  // 6: M99
  add(std::nullopt, 2, Start::Program);  // 7
  add(10, std::nullopt, Start::Sequence);  // 8
  add(std::nullopt, std::nullopt, Start::Other);  // 9
  ast::Block percent = plain(1, 10);
  percent.percent = true;
  f.blocks.push_back(stored(90, 10, 1, percent));
  f.record_end = {90, 10, 1};
  s.files.push_back(f);
  StoredFile folder;
  folder.id = 2;
  folder.blocks.push_back(stored(0, 1, 1, plain(2, 1, std::nullopt, 5), Start::Program));
  folder.record_end = {10, 2, 1};
  s.files.push_back(folder);
  s.folder_programs = {{5, {2, {0, 1, 1}}}, {1, {2, {0, 1, 1}}}};
  s.named_programs = {{"TOOL_CHANGE", {2, {}}}};
  return s;
}

ProgramPoint lineOf(uint32_t line) { return {1, {10u * (line - 1), line, 1}}; }

TEST(StoredProgramStore, FindsProgramsInTheCallingFileThenTheFolder) {
  const BlockStore s = labelledStore();
  StoredProgramStore programs(s);
  EXPECT_EQ(programs.findProgram(2, 1), lineOf(7));
  EXPECT_EQ(programs.findProgram(1, 1), lineOf(1));  // the calling file's O1 before the folder's
  EXPECT_EQ(programs.findProgram(1, 2), (ProgramPoint{2, {0, 1, 1}}));
  EXPECT_EQ(programs.findProgram(5, 1), (ProgramPoint{2, {0, 1, 1}}));
  EXPECT_FALSE(programs.findProgram(3, 1));
  EXPECT_FALSE(programs.findProgram(-1, 1));
  EXPECT_FALSE(programs.findProgram(3, 99));
  EXPECT_EQ(programs.findProgramNamed("TOOL_CHANGE"), (ProgramPoint{2, {}}));
  EXPECT_FALSE(programs.findProgramNamed("TOOL"));
  EXPECT_EQ(programs.programEnd(lineOf(1)), lineOf(7));
  EXPECT_EQ(programs.programEnd(lineOf(3)), lineOf(7));
  EXPECT_EQ(programs.programEnd(lineOf(7)), lineOf(10));  // the closing '%'
  EXPECT_EQ(programs.programEnd({2, {}}), (ProgramPoint{2, {10, 2, 1}}));  // the end of the file
}

TEST(StoredProgramStore, FindsSequencesInSearchOrderWithinBounds) {
  const BlockStore s = labelledStore();
  StoredProgramStore programs(s);
  const auto find = [&](int64_t n, uint32_t from, SequenceSearch order, uint32_t begin, uint32_t end) {
    std::optional<ProgramPoint> p = programs.findSequence(n, lineOf(from), order, lineOf(begin), lineOf(end));
    return p ? static_cast<int>(p->position.line) : 0;
  };
  const auto forward = SequenceSearch::ForwardThenFromStart;
  const auto start = SequenceSearch::FromStart;
  EXPECT_EQ(find(10, 2, forward, 1, 7), 5);  // after N10 of line 2
  EXPECT_EQ(find(10, 5, forward, 1, 7), 2);  // wraps to the start
  EXPECT_EQ(find(10, 3, start, 1, 7), 2);
  EXPECT_EQ(find(20, 1, forward, 1, 7), 4);  // `G1 N20` on line 3 is not a label
  EXPECT_EQ(find(20, 4, forward, 1, 7), 4);  // the GOTO block itself, last
  EXPECT_EQ(find(10, 7, forward, 7, 10), 8);  // O2's own N10
  EXPECT_EQ(find(10, 8, forward, 7, 10), 8);
  EXPECT_EQ(find(10, 1, forward, 7, 10), 8);  // `from` before the range
  EXPECT_EQ(find(10, 9, start, 7, 10), 8);
  EXPECT_EQ(find(10, 5, forward, 3, 5), 0);  // [3, 5) holds no N10
  EXPECT_EQ(find(10, 4, forward, 4, 7), 5);  // begin == from: the blocks after it first
  EXPECT_EQ(find(30, 1, forward, 1, 10), 0);
  EXPECT_FALSE(programs.findSequence(10, {99, {}}, start, {99, {}}, {99, {}}));
}

TEST(StoredProgramStore, CursorsReadSeekAndShareTheBlocks) {
  const BlockStore s = labelledStore();
  StoredProgramStore programs(s);
  std::unique_ptr<BlockCursor> c = programs.open(1);
  EXPECT_EQ(c->file(), 1u);
  EXPECT_EQ(c->lastPoint(), (ProgramPoint{1, {0, 1, 1}}));  // before the first block
  const ast::Block* b = c->next();
  ASSERT_TRUE(b);
  EXPECT_EQ(b->program_number, 1);
  EXPECT_EQ(c->lastPoint(), lineOf(1));
  c->seek(lineOf(4));
  EXPECT_EQ(c->lastPoint(), lineOf(1));  // seeking does not change the last block
  ASSERT_TRUE((b = c->next()));
  EXPECT_EQ(b->loc.line, 4u);
  EXPECT_EQ(c->lastPoint(), lineOf(4));
  c->seek({1, {25, 3, 1}});  // between blocks: the next one
  ASSERT_TRUE((b = c->next()));
  EXPECT_EQ(b->loc.line, 4u);
  c->seek({1, {1000, 99, 1}});
  EXPECT_FALSE(c->next());
  EXPECT_EQ(c->rejectedBlocks(), 0u);
  // Each cursor reads on its own.
  std::unique_ptr<BlockCursor> other = programs.open(1);
  ASSERT_TRUE((b = other->next()));
  EXPECT_EQ(b->loc.line, 1u);
  EXPECT_FALSE(programs.open(42)->next());  // a file not stored: no blocks
}

TEST(StoredProgramStore, PositionsKeepTheLanguageTheirBlocksWereReadIn) {
  // A file that switches to DIN and back: each stored position names its language, the
  // encoding keeps it, and a cursor seeks to a DIN position as to any other.
  BlockStore s = labelledStore();
  s.files[0].blocks[1].position.language = frontend::Language::Din;
  s.files[0].record_end.language = frontend::Language::Din;
  std::string error;
  std::optional<BlockStore> decoded = decodeBlockStore(encodeBlockStore(s), error);
  ASSERT_TRUE(decoded) << error;
  EXPECT_EQ(diffStore(s, *decoded), "");
  EXPECT_EQ(decoded->files[0].blocks[1].position.language, frontend::Language::Din);
  EXPECT_EQ(decoded->files[0].blocks[0].position.language, frontend::Language::Iso);
  StoredProgramStore programs(*decoded);
  std::unique_ptr<BlockCursor> c = programs.open(1);
  c->seek({1, decoded->files[0].blocks[1].position});
  ASSERT_TRUE(c->next());
  EXPECT_EQ(c->lastPoint().position, decoded->files[0].blocks[1].position);
}

}  // namespace
}  // namespace ncc::eval
