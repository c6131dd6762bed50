// The block driver and the public Lowering class. A block is decoded (block_words), its modal
// codes and F/H/D/S/T words are applied, then either its one-shot code or its motion is
// lowered by the concept it belongs to (see lowering_context.h for the list), its M codes are
// placed around that, words nothing read are reported, and only an error-free block commits:
// offset-table writes, the new controller state and one IR block. A block that depends on
// state an earlier rejected block left unknown is lowered silently (lowering_recovery.cpp).
// This file holds the order of those steps and nothing of their semantics.
#include "ncc/passes/lowering.h"

#include <optional>

#include "absl/strings/str_cat.h"
#include "expr_text.h"
#include "lowering_context.h"

namespace ncc::passes {

namespace {

// The block's modal G codes into the state (work-offset selection is a coordinate-system
// concern and goes there).
void applyModalCodes(BlockContext& ctx) {
  ir::Modal& m = ctx.next.modal;
  auto action = [&](GGroup g) -> std::optional<GAction> {
    if (const auto& w = ctx.words.group(g)) return w->entry->action;
    return std::nullopt;
  };
  if (auto a = action(GGroup::Motion)) ctx.next.motion = *a;
  if (auto a = action(GGroup::Plane))
    m.plane = *a == GAction::PlaneXY   ? ir::Plane::XY
              : *a == GAction::PlaneZX ? ir::Plane::ZX
                                       : ir::Plane::YZ;
  if (auto a = action(GGroup::Distance))
    m.distance =
        *a == GAction::Absolute ? ir::DistanceMode::Absolute : ir::DistanceMode::Incremental;
  if (auto a = action(GGroup::FeedMode))
    m.feed_mode = *a == GAction::PerMinute       ? ir::FeedMode::PerMinute
                  : *a == GAction::PerRevolution ? ir::FeedMode::PerRevolution
                                                 : ir::FeedMode::InverseTime;
  if (auto a = action(GGroup::Units))
    m.units = *a == GAction::Inch ? ir::Units::Inch : ir::Units::Millimetre;
  if (auto a = action(GGroup::PathControl))
    m.path = *a == GAction::ExactStopMode    ? ir::PathControl::ExactStop
             : *a == GAction::CornerOverride ? ir::PathControl::CornerOverride
             : *a == GAction::TappingMode    ? ir::PathControl::Tapping
                                             : ir::PathControl::Continuous;
  if (const auto& w = ctx.words.group(GGroup::WorkOffset)) selectWorkOffset(ctx, *w);
}

// G10: the L number decides between work offsets (coordinate systems) and tool offsets.
void dataSet(BlockContext& ctx, const GWord& g) {
  if (!ctx.words.l) {
    ctx.fail(Alarm::DataSetFormat, g.loc, "G10 needs L2, L10-L13 or L20");
    return;
  }
  ctx.used_l = true;
  auto l = ctx.integer(*ctx.words.l);
  if (!l) return;
  bool add = ctx.next.modal.distance == ir::DistanceMode::Incremental;
  if (*l == 2 || *l == 20) return dataSetWork(ctx, g, static_cast<int>(*l), add);
  if (*l >= 10 && *l <= 13) return dataSetRegister(ctx, g, static_cast<int>(*l), add);
  ctx.fail(Alarm::DataSetFormat, ctx.words.l->loc,
           absl::StrCat("G10 L", *l, " is not supported; ncc knows L2, L10-L13 and L20"));
}

// The block's one-shot code, to the concept it belongs to.
void oneShot(BlockContext& ctx) {
  const GWord& g = *ctx.words.one_shot;
  switch (g.entry->action) {
    case GAction::Dwell: return dwell(ctx, g);
    case GAction::DwellFeedOrSpindle: return dwellFeedOrSpindle(ctx, g);
    case GAction::DataSet: return dataSet(ctx, g);
    case GAction::ReferenceCheck: return referenceCheck(ctx, g);
    case GAction::ReferenceReturn: return referenceReturn(ctx, g, 1);
    case GAction::ReferenceReturnN: return referenceReturn(ctx, g, referenceNumber(ctx, g, 2));
    case GAction::LocalShift: return localShift(ctx, g);
    case GAction::MachineCoordinates: return machineCoordinateMove(ctx, g);
    case GAction::SetShift: return setShift(ctx);
    case GAction::ResetShift: return resetShift(ctx, g);
    case GAction::Skip: return skipMove(ctx, g);
    case GAction::PositionOffset: return positionOffsetMove(ctx, g);
    case GAction::WorkRotation: return workRotation(ctx, g);
    default: return;
  }
}

// Words no code of the block reads.
void checkUnused(BlockContext& ctx) {
  if (ctx.failed) return;
  auto unused = [&](const std::optional<WordValue>& w, bool used) {
    if (!w || used || ctx.failed) return;
    const std::string context =
        ctx.words.one_shot ? gCodeName(ctx.words.one_shot->entry->code10) : "this block";
    ctx.fail(Alarm::AddressWithoutMeaning, w->loc,
             absl::StrCat("address ", std::string(w->address), " has no meaning in ", context));
  };
  bool arc_block = !ctx.words.one_shot &&
                   (ctx.next.motion == GAction::ArcCW || ctx.next.motion == GAction::ArcCCW);
  unused(ctx.words.i, ctx.used_ijk || arc_block);
  unused(ctx.words.j, ctx.used_ijk || arc_block);
  unused(ctx.words.k, ctx.used_ijk || ctx.used_k || arc_block);
  unused(ctx.words.q, ctx.used_q);
  unused(ctx.words.r, ctx.used_r);
  unused(ctx.words.p, ctx.used_p);
  unused(ctx.words.l, ctx.used_l);
  unused(ctx.words.corner, ctx.corner.has_value());
  unused(ctx.words.line_angle, ctx.used_angle);
}

// The offset-table writes, the new controller state and the IR block.
void commit(BlockContext& ctx) {
  OffsetTables& tables = ctx.core.tables;
  for (const TableWrite& w : ctx.table_writes) {
    auto set = [&](double& slot, double v) { slot = w.add ? slot + v : v; };
    switch (w.target) {
      case TableWrite::Target::Work: {
        AxisValues& stored = tables.work[w.work_name.str()];
        for (int i = 0; i < ctx.axisCount(); ++i)
          if (w.axes & (1u << i)) set(stored[i], w.values[i]);
        if (!ctx.behaviour.work_offset_write_on_reselect && w.work_name == ctx.next.work_name)
          ctx.next.work_value = stored;
        break;
      }
      case TableWrite::Target::External: break;  // applied to the state directly
      case TableWrite::Target::Length: set(tables.length[w.number], w.values[0]); break;
      case TableWrite::Target::LengthWear: set(tables.length_wear[w.number], w.values[0]); break;
      case TableWrite::Target::Radius: set(tables.radius[w.number], w.values[0]); break;
      case TableWrite::Target::RadiusWear: set(tables.radius_wear[w.number], w.values[0]); break;
    }
  }
  for (const TableWrite& w : ctx.table_writes)
    for (const ir::SetVariable& v : variablesOf(w, ctx.next, tables, ctx.table, ctx.axisCount()))
      ctx.ops.push_back(v);
  // Built in place: a default block would first build its modal state's strings.
  ir::Block out{
      .loc = ctx.block.loc,
      .sequence = ctx.block.sequence.value_or(-1),
      .modal = ctx.next.modal,
      .frame = frameOf(ctx.next, ctx.behaviour),
      .transform = transformOf(ctx),
      .exact_stop =
          ctx.words.exact_stop.has_value() || ctx.next.modal.path == ir::PathControl::ExactStop,
      .ops = std::move(ctx.ops),
      .corner = ctx.corner,
      .comp = ctx.comp,
  };
  out.modal.work_offset = ctx.next.work_name;
  // While something is unknown (only after an error: the run fails anyway) targets may rest
  // on it; later passes would judge them (travel limits) and report consequences.
  const bool unknown = ctx.next.unknown.any();
  ctx.core.commitBlock();  // the block's state is the controller's (ctx is done)
  if (unknown) return;
  ctx.core.out.accept(std::move(out));
}

// A block rejected with a diagnostic: the state stays as it was, but what the block would
// have written is unknown from now on.
// A plane selected by a parallel axis (`G17 U_ Y_`: the UY plane, Mazak §6-2, Sinumerik ISO
// §3.1.8 with GEOAX) is not built yet: the arcs that follow would run in the base plane, so the
// block is refused rather than read wrongly. U, V, W are the parallel axes of X, Y, Z (the
// manuals' examples). A parallel axis beside its base axis leaves the base plane (Mazak: the
// base axis has priority) and just moves.
void rejectParallelAxisPlane(BlockContext& ctx, const MachineConfig& machine) {
  const auto& plane = ctx.words.group(GGroup::Plane);
  if (!plane) return;
  auto word = [&](std::string_view name) -> const std::optional<WordValue>* {
    const int i = machine.axisIndex(name);
    return i >= 0 && i < kMaxAxes ? &ctx.words.axes[i] : nullptr;
  };
  static constexpr std::pair<std::string_view, std::string_view> kParallel[] = {
      {"X", "U"}, {"Y", "V"}, {"Z", "W"}};
  for (const auto& axes : kParallel) {
    const std::optional<WordValue>* p = word(axes.second);
    const std::optional<WordValue>* b = word(axes.first);
    if (!p || !*p || (b && *b)) continue;
    ctx.fail(Alarm::CodeNotSupported, (*p)->loc,
             absl::StrCat("a plane selected by the parallel axis ", std::string(axes.second),
                          " (instead of ", std::string(axes.first),
                          ") is not supported yet: the arcs would run in the base plane"));
    return;
  }
}

LowerResult reject(BlockContext& ctx) {
  forgetRejected(ctx.core.cs(), ctx.block, ctx.table, *ctx.core.machine);
  return LowerResult{};
}

// A block lowered silently (it depends on unknown state): no diagnostic, no IR, no table
// writes; the state takes what the block determines (relearn).
LowerResult settleSilent(BlockContext& ctx, LowerResult result) {
  relearn(ctx);
  ctx.core.commitBlock();
  return result;
}

// Lowers one block on a copy of the controller state; commits it only without errors.
LowerResult lowerBlock(LoweringCore& core, const ast::Block& block) {
  BlockContext ctx(core, block);
  LowerResult result;
  DecodeContext decode{ctx.table,           *core.machine,           *core.addresses,
                       ctx.settings.policy, core.cs().modal.distance, core.diags};
  decode.cycle_in_force = core.cs().cycle.code10 != 0;
  if (!decodeBlock(block, decode, ctx.words)) return reject(ctx);

  applyModalCodes(ctx);
  applyPolarCode(ctx);
  applyCycleCodes(ctx);
  rejectParallelAxisPlane(ctx, *core.machine);
  if (ctx.words.k && repeatCountIsK(ctx)) {  // a cycle's K counts holes: no length
    DecodedBlock audited = ctx.words;
    audited.k.reset();
    core.decimal_points.block(audited, ctx.settings.values, ctx.next.modal.units, *core.machine,
                              polarAngleAxis(ctx));
  } else {
    core.decimal_points.block(ctx.words, ctx.settings.values, ctx.next.modal.units, *core.machine,
                              polarAngleAxis(ctx));
  }
  Dependence depends = dependsOnUnknown(ctx);
  ctx.silent = depends.words;
  ctx.checkFormats();
  if (ctx.failed) return ctx.silent ? settleSilent(ctx, result) : reject(ctx);
  applyFeed(ctx);
  applyLengthOffset(ctx);
  applyRadiusOffsetNumber(ctx);
  applySpindleAndToolWords(ctx);
  if (ctx.failed) {
    if (ctx.silent) return settleSilent(ctx, result);
    reject(ctx);
    return result;
  }
  ctx.silent = depends.words || depends.motion;
  applyTransformCodes(ctx);
  applyFrameInstruction(ctx);
  applyCutterComp(ctx);
  // G68 / G51 / G51.1 / G50.1 take the axis words as their centres, a DIN frame instruction as
  // its values: such a block moves nothing.
  const bool centres = transformTakesAxisWords(ctx) || frameTakesAxisWords(ctx);
  // G16: the plane words become Cartesian before anything reads them.
  if (!ctx.failed && !centres) convertPolarWords(ctx);
  if (ctx.failed || centres)
    ;
  else if (ctx.words.one_shot)
    oneShot(ctx);
  else if (cornerArcBlock(ctx))
    ;  // G39: the corner arc is the compensation pass's
  else if (inCycle(ctx))
    lowerCycle(ctx);
  else
    lowerMotion(ctx);
  scalingCancelMove(ctx);
  machineFunctions(ctx, result);
  finishCutterComp(ctx, result.program_end);
  checkSkipDependence(ctx);
  if (ctx.needs_run_time) {
    result.needs_run_time = std::move(ctx.needs_run_time);
    return result;
  }
  checkUnused(ctx);
  if (ctx.silent) return settleSilent(ctx, result);
  if (ctx.failed) return reject(ctx);
  relearn(ctx);
  trackTool(ctx);
  commit(ctx);
  return result;
}

}  // namespace

struct Lowering::State : LoweringCore {
  using LoweringCore::LoweringCore;
};

Lowering::Lowering(LoweringOptions options, DiagnosticEngine& diags, ir::BlockSink& out)
    : state_(std::make_unique<State>(std::move(options), diags, out)) {}

Lowering::~Lowering() = default;

LowerResult Lowering::lower(const ast::Block& block) {
  State& st = *state_;
  if (!st.table) {
    if (!st.reported_dialect)
      st.diags.error("NCC2002", block.loc,
                     absl::StrCat("lowering of ", std::string(dialectName(st.options.dialect)),
                                  " programs is not supported yet (fanuc-m, mazak-m and "
                                  "siemens-iso-m are)"));
    st.reported_dialect = true;
    return {};
  }
  if (skips(block)) return {};
  if (block.words.empty() && block.statements.empty()) return {};
  if (!st.useLanguage(block.language)) {
    // The reader switches language only where the dialect has G290/G291 (languageTables).
    st.diags.error("NCC2002", block.loc,
                   absl::StrCat(std::string(dialectName(st.options.dialect)),
                                " has no DIN language: the block cannot be lowered"));
    return {};
  }
  st.resolveSkip();
  return lowerBlock(st, block);
}

bool Lowering::skips(const ast::Block& block) const {
  const State& st = *state_;
  if (!st.table || block.skip_level < 0) return false;
  const int level = block.skip_level == 0 ? 1 : block.skip_level;
  return (st.settings.block_skip && level <= 1) || st.settings.skip_levels.count(level) > 0;
}

bool Lowering::checkStatically(const ast::Block& block) const {
  const State& st = *state_;
  if (!st.table || skips(block)) return true;
  const LoweringCore::LanguageLowering& ll = st.languages[static_cast<size_t>(block.language)];
  if (!ll.table) return false;
  DecodeContext decode{*ll.table,          *st.machine,           *ll.addresses,
                       ll.settings.policy, st.cs().modal.distance, st.diags};
  decode.statically = true;
  return decodeBlock(block, decode).has_value();
}

eval::SystemVariables& Lowering::systemVariables() { return state_->system_variables; }

void Lowering::variablesWritten(SourceLocation loc, std::vector<ir::SetVariable> writes) {
  State& st = *state_;
  if (writes.empty() || !st.table || st.cs().unknown.any()) return;
  ir::Block out;
  out.loc = loc;
  out.modal = st.cs().modal;
  out.modal.work_offset = st.cs().work_name;
  out.frame = frameOf(st.cs(), st.table->behaviour);
  out.ops.assign(std::make_move_iterator(writes.begin()), std::make_move_iterator(writes.end()));
  out.comp = compensationInForce(st, st.cs(), loc);
  st.out.accept(std::move(out));
}

double Lowering::argumentValue(const ast::Word& word) const {
  const State& st = *state_;
  double v = 0.0;
  bool point = false;
  if (!foldLiteral(word.value, v, point) || point || !st.table || !st.settings.values.standard)
    return v;
  static constexpr std::string_view kLengthAddresses = "IJKRQ";
  const bool length = st.machine->axisIndex(word.address) >= 0 ||
                      (word.address.size() == 1 &&
                       kLengthAddresses.find(word.address[0]) != std::string_view::npos);
  return length ? v * st.settings.values.lengthIncrement(st.cs().modal.units) : v;
}

double Lowering::leastIncrement() const {
  const State& st = *state_;
  return st.settings.values.lengthIncrement(st.cs().modal.units);
}

int Lowering::addressDigits() const { return state_->settings.values.digits; }

bool Lowering::figureRotationBegin(const std::array<std::optional<double>, 3>& ijk) {
  return !state_->table || passes::figureRotationBegin(*state_, ijk);
}

void Lowering::figureRotationRun(int64_t run) {
  if (state_->table) passes::figureRotationRun(*state_, run);
}

void Lowering::figureRotationEnd() {
  if (state_->table) passes::figureRotationEnd(*state_);
}

void Lowering::blockUnreadable() {
  if (state_->table) forgetEverything(state_->cs());
}

void Lowering::finish() {
  if (state_->table) state_->decimal_points.finish(state_->diags, state_->settings.values);
  state_->out.finish();
}

}  // namespace ncc::passes
