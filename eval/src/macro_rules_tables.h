#pragma once
// The per-dialect MacroRules tables (one file each: macro_rules_<dialect>.cpp) and what they
// share: the NCC codes for errors a manual gives no number for, and the G65 argument table.
#include <array>
#include <cstdint>
#include <string_view>

#include "ncc/eval/macro_rules.h"

namespace ncc::eval::tables {

// NCC codes of the evaluator, indexed by EvalError (docs/macro.md, Dialect rules). A dialect
// copies this table and replaces the entries its manual numbers.
inline constexpr std::array<std::string_view, static_cast<size_t>(EvalError::kCount)>
    kNccCodes = {
        "NCC2400",  // VariableNumber
        "NCC2401",  // VariableReadOnly
        "NCC2402",  // DivisionByZero
        "NCC2403",  // Domain
        "NCC2404",  // ValueRange
        "NCC2405",  // BracketNesting
        "NCC2406",  // AddressValue
        "NCC2407",  // EndWithoutDo
        "NCC2408",  // DoNesting
        "NCC2409",  // DoNumber
        "NCC2410",  // LoopNotClosed
        "NCC2411",  // GotoTarget
        "NCC2412",  // ProgramNotFound
        "NCC2413",  // CallNesting
        "NCC2414",  // MacroNesting
        "NCC2415",  // UserAlarm (the shown number comes from user_alarms)
        "NCC2416",  // UserStop
        "NCC2417",  // ModalCallCancel
        "NCC2418",  // ArgumentBeforeCall
        "NCC2419",  // StepLimit
        "NCC2010",  // NotSupported: the code lowering gives a feature not built yet
        "NCC2420",  // FigureRotationNested
        "NCC2421",  // FigureRotationWithRotation
        "NCC0023",  // RunTimeValue: never an error (the rest is prepared at run time)
        "NCC2422",  // UndefinedName
        "NCC2423",  // ArrayIndex
        "NCC2424",  // JumpTarget
        "NCC2425",  // TypeMismatch
        "NCC2426",  // StructureNesting
        "NCC2427",  // StructureDepth
        "NCC2428",  // TooManyArguments
        "NCC2429",  // ArgumentNotVariable
        "NCC2430",  // ProcPlacement
        "NCC2431",  // NameDefinedTwice
        "NCC2432",  // TooManyValues
};

// Argument specification I: A#1 B#2 C#3 I#4 J#5 K#6 D#7 E#8 F#9 H#11 M#13 Q#17 R#18 S#19
// T#20 U#21 V#22 W#23 X#24 Y#25 Z#26; G L N O P are not arguments (Mazak §13-9-4 table,
// Siemens ISO §4.10 type I, FANUC the same letters).
inline constexpr std::array<uint8_t, 26> kArgumentSpec1 = {
    1,   // A
    2,   // B
    3,   // C
    7,   // D
    8,   // E
    9,   // F
    0,   // G
    11,  // H
    4,   // I
    5,   // J
    6,   // K
    0,   // L
    13,  // M
    0,   // N
    0,   // O
    0,   // P
    17,  // Q
    18,  // R
    19,  // S
    20,  // T
    21,  // U
    22,  // V
    23,  // W
    24,  // X
    25,  // Y
    26,  // Z
};

inline constexpr std::string_view kIsoProgramFiles[] = {"O{:04}.nc", "O{}.nc", "{:04}.nc",
                                                        "{}.nc"};

extern const MacroRules kFanucRules;      // fanuc-m, fanuc-t
extern const MacroRules kMazakRules;      // mazak-m
extern const MacroRules kSiemensIsoRules;  // siemens-iso-m, siemens-din

}  // namespace ncc::eval::tables
