#pragma once
// Builds the block store of a compiled program (eval/block_store.h): the parsed blocks of the
// main file and of every program the run may reach, for the VM to prepare blocks at run time
// with the compiler's own evaluation and lowering.
//
// The files: the main file; every file the compile opened or found (SourceProgramStore records
// them); and, closed over, the targets of the literal calls in every stored block (M98 P, with
// both readings of a P that may carry a repeat count in its high digits, G65 P, G66 P,
// G66.1 P) and the machine file's code macros. A target an O block of the calling file holds
// needs nothing more; any other is looked up in the program folder (ProgramLibrary steps 2-3)
// and, when found, recorded in folder_programs. A computed target (`M98 P#1`) that the compile
// never asked for is not stored: the VM then reports the program as not found.
//
// Each file is read from its start with a fresh BlockReader to the end of its record. A block
// that does not parse is reported as the reader does (an error, so the compile fails), also
// in text the compile never reached: one verdict for what the run may reach. The exception is
// the text after the main program's M02/M30 (BlockStoreTargets::main_end), never an error.
#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "ncc/eval/block_store.h"
#include "ncc/support/diagnostics.h"
#include "source_program_store.h"

namespace ncc::driver {

struct BlockStoreTargets {
  // The machine file's code macros: code ("M6") -> an O number ("9006") or a program name.
  std::map<std::string, std::string> code_macros;
  // The program part of M98 P when P may carry a repeat count in its high digits (FANUC
  // Pnnnnmmmm: 4); 0 when it never does. Both the whole P and its low digits are looked up.
  int program_number_digits = 4;
  // The block where the compile's main program ended with M02/M30 (the last block lowering
  // saw), if it did: the text after it up to the next program (O block) or the end of the
  // record is never executed and not parsed by the compile (docs/cli.md, The end of a
  // program), so a block there that does not parse is left out without a diagnostic.
  std::optional<eval::ProgramPoint> main_end;
};

// Where the main program in `file` ends when the compile stopped before it did (the rest is
// prepared at run time): its first block, before the next program, that programs M02 or M30
// as a literal. The builder uses it when BlockStoreTargets::main_end is not given.
std::optional<eval::ProgramPoint> writtenMainEnd(SourceProgramStore& store, uint32_t file);

// `store`: the compile's store, after the compile (its records say what the run asked for).
// The result's ahead_blocks, limits and saved_variables are left at their defaults.
eval::BlockStore buildBlockStore(SourceProgramStore& store, uint32_t main_file,
                                 const BlockStoreTargets& targets, DiagnosticEngine& diags);

}  // namespace ncc::driver
