#pragma once
// What the two ANTLR block parsers (ISO: antlr_block_parser.cpp, DIN: din_block_parser.cpp)
// share: the first-error listener, the exception that ends a rejected block, the depth
// message, and the tokens' text and locations in the block's line.
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include "absl/strings/str_cat.h"
#include "antlr4-runtime.h"
#include "lexical.h"
#include "ncc/frontend/ast.h"
#include "ncc/support/diagnostics.h"

namespace ncc::frontend {

// Remembers the first error the parser reports; the message is ours, built from the token.
class FirstErrorListener : public antlr4::BaseErrorListener {
 public:
  void syntaxError(antlr4::Recognizer*, antlr4::Token* offending, size_t, size_t,
                   const std::string&, std::exception_ptr) override {
    if (!seen) offending_token = offending;
    seen = true;
  }
  void clear() {
    seen = false;
    offending_token = nullptr;
  }
  bool seen = false;
  antlr4::Token* offending_token = nullptr;
};

// Thrown by a builder after it has reported a diagnostic; caught where the parse started.
struct BlockRejected {};

// Deeper nesting than this is refused before parsing: the parsers and the AST are recursive,
// and no controller allows more than a handful of bracket levels (FANUC: 5).
inline constexpr int kMaxNesting = 64;

inline std::string tooDeep() {
  return absl::StrCat("expression nested deeper than ", ast::kMaxExprDepth,
                      " levels (each operator, sign, bracket and function is one)");
}

// The lexer and parser of one grammar, made once and reused for every block (their set-up costs
// more than a parse).
template <class Lexer, class Parser>
struct AntlrEngine {
  AntlrEngine() : lexer(&input), tokens(&lexer), parser(&tokens) {
    lexer.removeErrorListeners();
    parser.removeErrorListeners();
    parser.addErrorListener(&errors);
  }

  // Lexes `text` in its lexical form (`upper`); the tokens, EOF last.
  std::vector<antlr4::Token*> lex(std::string_view text) {
    upper = lexicalForm(text);
    input.load(upper);
    lexer.setInputStream(&input);
    tokens.setTokenSource(&lexer);
    tokens.fill();
    return tokens.getTokens();
  }

  // The block's parse tree: SLL prediction is enough for these grammars, LL the exact fallback
  // when SLL fails. nullptr with `offending` set at a syntax error. The tree lives until
  // reset().
  typename Parser::BlockContext* parse(antlr4::Token*& offending) {
    typename Parser::BlockContext* tree = run(antlr4::atn::PredictionMode::SLL);
    if (errors.seen) tree = run(antlr4::atn::PredictionMode::LL);
    offending = errors.offending_token;
    return errors.seen ? nullptr : tree;
  }
  void reset() { parser.getTreeTracker().reset(); }

  std::string upper;
  antlr4::ANTLRInputStream input;
  Lexer lexer;
  antlr4::CommonTokenStream tokens;
  Parser parser;
  FirstErrorListener errors;

 private:
  typename Parser::BlockContext* run(antlr4::atn::PredictionMode mode) {
    tokens.seek(0);
    parser.getTreeTracker().reset();
    parser.setTokenStream(&tokens);
    errors.clear();
    parser.template getInterpreter<antlr4::atn::ParserATNSimulator>()->setPredictionMode(mode);
    return parser.block();
  }
};

// One block's text as its builder reads it: `original` as written, `upper` its lexical form
// (lexical.h: same length, so an index is a column of both), `start` where it is in the file.
class BlockText {
 public:
  BlockText(std::string_view original, const std::string& upper, SourceLocation start,
            DiagnosticEngine& diags)
      : original_(original), upper_(upper), start_(start), diags_(diags) {}

  // Reports and rejects the block.
  [[noreturn]] void fail(const char* code, SourceLocation where, std::string message) {
    diags_.error(code, where, std::move(message));
    throw BlockRejected{};
  }

  SourceLocation at(size_t index) const {
    return SourceLocation{start_.file, start_.line, start_.column + static_cast<uint32_t>(index)};
  }
  SourceLocation at(const antlr4::Token* t) const { return at(t->getStartIndex()); }
  SourceLocation at(antlr4::tree::TerminalNode* n) const { return at(n->getSymbol()); }

  // Token text as written (original case); for EOF, empty.
  std::string_view written(const antlr4::Token* t) const {
    if (t->getType() == antlr4::Token::EOF) return {};
    return original_.substr(t->getStartIndex(), t->getStopIndex() - t->getStartIndex() + 1);
  }
  std::string_view upper(const antlr4::Token* t) const {
    return std::string_view(upper_).substr(t->getStartIndex(),
                                           t->getStopIndex() - t->getStartIndex() + 1);
  }
  std::string_view upper(antlr4::tree::TerminalNode* n) const { return upper(n->getSymbol()); }

 protected:
  std::string_view original_;
  const std::string& upper_;
  SourceLocation start_;
  DiagnosticEngine& diags_;
};

}  // namespace ncc::frontend
