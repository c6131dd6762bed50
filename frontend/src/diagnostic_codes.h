#pragma once
// The frontend's diagnostic codes (documented in docs/frontend.md). The controllers' manuals
// give no alarm numbers for these lexical faults, so they are ncc codes.
namespace ncc::frontend::codes {

inline constexpr const char* kCannotRead = "NCC1000";         // file cannot be opened
inline constexpr const char* kUnexpectedChar = "NCC1001";     // character outside the alphabet
inline constexpr const char* kNoValue = "NCC1002";            // address letter without a value
inline constexpr const char* kUnclosedBracket = "NCC1003";    // '[' without ']'
inline constexpr const char* kUnopenedBracket = "NCC1004";    // ']' without '['
inline constexpr const char* kUnclosedComment = "NCC1005";    // '(' without ')'
inline constexpr const char* kUnexpectedToken = "NCC1006";    // token where it cannot stand
inline constexpr const char* kSkipNotAtStart = "NCC1007";     // '/' in the middle of a block
inline constexpr const char* kSkipLevel = "NCC1008";          // '/n' with n outside 0..9
inline constexpr const char* kBlockNumber = "NCC1009";        // N/O not an unsigned integer
inline constexpr const char* kIncomplete = "NCC1010";         // block ends inside a statement
inline constexpr const char* kArity = "NCC1011";              // function argument count
inline constexpr const char* kLoopId = "NCC1012";             // DO m / END m not an integer
inline constexpr const char* kCommaAddress = "NCC1013";       // ',X' other than ,A ,C ,R
inline constexpr const char* kDuplicateNumber = "NCC1014";    // two N (or O) in one block
inline constexpr const char* kNumberRange = "NCC1015";        // number does not fit
inline constexpr const char* kNesting = "NCC1016";            // brackets or signs nested too deep
inline constexpr const char* kExprDepth = "NCC1017";          // expression deeper than ast::kMaxExprDepth
inline constexpr const char* kUnclosedString = "NCC1018";     // DIN '"' without '"'
inline constexpr const char* kUnknownType = "NCC1019";        // DIN DEF of an unknown type
inline constexpr const char* kDinNotSupported = "NCC1090";    // DIN construct not built yet

}  // namespace ncc::frontend::codes
