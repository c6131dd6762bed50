#pragma once
// The compile pipeline: frontend (block by block) -> lowering -> passes -> a final IR sink.
// Everything streams: memory does not grow with program length.
#include <filesystem>
#include <ostream>
#include <string>

#include "ncc/driver/session.h"
#include "ncc/ir/ir.h"

namespace ncc::driver {

// Runs frontend, lowering and passes, delivering machine-space IR blocks to `sink`.
// Returns true when no error was reported.
bool compileToSink(Session& session, ir::BlockSink& sink);

// `ncc check`: the whole pipeline up to the backend, keeping only the diagnostics.
bool check(Session& session);

// `ncc compile --emit=ast`: the parsed blocks printed back, one per line.
bool emitAst(Session& session, std::ostream& out);
// `ncc compile --emit=ir`: the IR after all passes, as text.
bool emitIr(Session& session, std::ostream& out);
// Bytecode into a stream (seekable: the section table is patched at the end).
bool emitBytecode(Session& session, std::ostream& out);

}  // namespace ncc::driver
