#pragma once
// What a block of text starts with, found without parsing it: the program index scans whole
// files for N labels and O numbers this way, much faster than the parser and without
// reporting anything. It reads the text as the parsers do (lower-case letters, blanks
// anywhere between tokens, `( )` comments, a leading '%' or block skip '/', '/1'..'/9').
#include <cstdint>
#include <string_view>

namespace ncc::frontend {

struct BlockStart {
  enum class Kind : uint8_t {
    Blank,     // nothing a control reads: blanks, comments, a block skip mark alone
    Percent,   // the '%' tape mark
    Sequence,  // first word N n
    Program,   // first word O n or :n
    Other,     // anything else (including text the parser would reject)
  };
  Kind kind = Kind::Blank;
  int64_t number = 0;  // Sequence, Program
};

// `text`: one block (a line, or the part between ';' ends of block), without the ';'.
BlockStart blockStart(std::string_view text);

// The jump label of a DIN block (`MA1` of `N20 MA1: R3=R1`), as written: after blanks, a block
// skip mark and the block number (N n or :n), a name and ':'. Empty when there is none.
std::string_view blockLabel(std::string_view text);
// Labels are names: upper and lower case are the same.
bool sameLabel(std::string_view written, std::string_view upper);

}  // namespace ncc::frontend
