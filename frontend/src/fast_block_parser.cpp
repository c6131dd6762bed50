#include "fast_block_parser.h"

#include <algorithm>

#include "lexical.h"
#include "number_text.h"

namespace ncc::frontend {

namespace {

// A cursor over one block. Every method either consumes what it expects or returns false,
// upon which the whole block is declined.
class PlainScanner {
 public:
  PlainScanner(std::string_view text, SourceLocation start) : text_(text), start_(start) {}

  // Fills `b`, cleared first (its vectors keep their capacity, its words are reused in
  // place); false to decline.
  bool run(ast::Block& b) {
    b.loc = start_;
    b.skip_level = -1;
    b.sequence.reset();
    b.program_number.reset();
    b.percent = false;
    b.statements.clear();
    b.comments.clear();
    skipBlanks();
    if (peek() == '%') {
      ++pos_;
      b.percent = true;
    } else if (peek() == '/') {
      ++pos_;
      skipBlanks();
      b.skip_level = 1;
      if (startsNumber()) {
        std::string_view level = numberToken();
        if (level.size() != 1 || !isDigit(level[0])) return false;
        b.skip_level = level[0] - '0';
      }
    }
    // One allocation for the words of a usual block: a word takes two characters at least,
    // and a CAM block has fewer than eight.
    b.words.reserve(std::min<size_t>(8, (text_.size() - pos_ + 1) / 2));
    size_t used = 0;  // the words of `b` filled so far
    for (skipBlanks(); pos_ < text_.size(); skipBlanks()) {
      const char c = text_[pos_];
      if (c == '(') {
        size_t close = text_.find(')', pos_);
        if (close == std::string_view::npos) return false;
        b.comments.emplace_back(text_.substr(pos_ + 1, close - pos_ - 1));
        pos_ = close + 1;
      } else if (isLetter(c)) {
        const char letter = upperAscii(c);
        const SourceLocation where = here();
        ++pos_;
        if (letter == 'N' || letter == 'O') {
          if (!blockNumber(letter == 'N' ? b.sequence : b.program_number)) return false;
          continue;
        }
        ast::Word& w = word(b, used);
        w.address = ast::Address(letter);
        w.loc = where;
        if (!value(w.value)) return false;
      } else if (c == ',') {
        const SourceLocation where = here();
        ++pos_;
        skipBlanks();
        const char letter = upperAscii(peek());
        if (!isCommaAddressLetter(letter)) return false;
        ++pos_;
        ast::Word& w = word(b, used);
        const char comma_address[2] = {',', letter};
        w.address = ast::Address(std::string_view(comma_address, 2));
        w.loc = where;
        if (!value(w.value)) return false;
      } else if (c == ':') {
        ++pos_;
        if (!blockNumber(b.program_number)) return false;
      } else {
        return false;
      }
    }
    b.words.resize(used);
    return true;
  }

 private:
  // The next word of `b`: one left from the block filled before (its strings and vectors
  // keep their storage; value() sets the rest), else a new one.
  static ast::Word& word(ast::Block& b, size_t& used) {
    if (used == b.words.size()) {
      b.words.emplace_back();
    } else {
      b.words[used].value.op = ast::Op::None;
      b.words[used].value.args.clear();
    }
    return b.words[used++];
  }

  char peek() const { return pos_ < text_.size() ? text_[pos_] : '\0'; }
  void skipBlanks() {
    while (pos_ < text_.size() && isBlank(text_[pos_])) ++pos_;
  }
  SourceLocation here() const {
    return SourceLocation{start_.file, start_.line, start_.column + static_cast<uint32_t>(pos_)};
  }
  bool startsNumber() const {
    return isDigit(peek()) || (peek() == '.' && pos_ + 1 < text_.size() && isDigit(text_[pos_ + 1]));
  }
  // The NUMBER token of Iso.g4: [0-9]+ ('.' [0-9]*)? | '.' [0-9]+ ; call after startsNumber().
  std::string_view numberToken() {
    const size_t begin = pos_;
    while (isDigit(peek())) ++pos_;
    if (peek() == '.') {
      ++pos_;
      while (isDigit(peek())) ++pos_;
    }
    return text_.substr(begin, pos_ - begin);
  }

  // sign? NUMBER, blanks allowed around the sign; written into the word in place (a block is
  // built once, not moved word by word).
  bool value(ast::Expr& e) {
    skipBlanks();
    const SourceLocation where = here();
    bool negative = false, sign = false;
    if (peek() == '+' || peek() == '-') {
      negative = peek() == '-';
      sign = true;
      ++pos_;
      skipBlanks();
    }
    if (!startsNumber()) return false;
    const SourceLocation number_at = here();
    std::optional<NumberText> n = readNumber(numberToken());
    if (!n) return false;
    e.kind = ast::Expr::Kind::Number;
    e.number = negative ? -n->value : n->value;
    e.has_point = n->has_point;
    e.loc = sign ? where : number_at;
    e.digits = n->digits;
    return true;
  }

  // N, O and ':' take unsigned integer digits, once per block.
  bool blockNumber(std::optional<int64_t>& slot) {
    skipBlanks();
    if (slot || !startsNumber()) return false;
    std::string_view digits = numberToken();
    if (digits.find('.') != std::string_view::npos) return false;
    std::optional<int64_t> n = readInteger(digits);
    if (!n) return false;
    slot = *n;
    return true;
  }

  std::string_view text_;
  SourceLocation start_;
  size_t pos_ = 0;
};

}  // namespace

bool parsePlainBlock(std::string_view text, SourceLocation start, ast::Block& out) {
  return PlainScanner(text, start).run(out);
}

std::optional<ast::Block> parsePlainBlock(std::string_view text, SourceLocation start) {
  ast::Block b;
  if (!parsePlainBlock(text, start, b)) return std::nullopt;
  return b;
}

}  // namespace ncc::frontend
