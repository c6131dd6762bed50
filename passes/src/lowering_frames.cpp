// The DIN programmable frame (Sinumerik Fundamentals, "Frames"): TRANS/ATRANS translate,
// ROT/AROT rotate (RPL= in the plane, or X Y Z in space), SCALE/ASCALE scale, MIRROR/AMIRROR
// mirror the programmed coordinates. The plain command replaces the whole programmable frame
// by its one component (alone, it deletes the frame); the A-form acts onto the frame in force,
// in the coordinates that frame makes. The frame is one map (TransformState::programmable)
// that acts on a programmed point before the other transform stages
// (lowering_transform_map.cpp). A frame instruction moves nothing; the programmed point stays,
// and the next move goes to its image under the new frame, incremental words included
// (MD42440 FRAME_OFFSET_INCR_PROG = 1, the default: "the offset is traversed also when the
// axis is programmed incrementally"), as the ISO transforms do.
#include <cmath>

#include "absl/strings/str_cat.h"
#include "affine.h"
#include "lowering_context.h"

namespace ncc::passes {

namespace {

using Component = FrameCommand::Component;
constexpr const char* kSlotName[] = {"X", "Y", "Z"};

// The frame instruction stands alone in its block with its axis words (and RPL= for a
// rotation): N, the label and comments aside (Fundamentals: "frame instructions are programmed
// in a block of their own").
bool alone(BlockContext& ctx, const FrameCommand& c) {
  for (const ast::Word& w : ctx.block.words) {
    const std::string_view a = w.address;
    if (a == c.name || ctx.core.machine->axisIndex(a) >= 0) continue;
    if (a == "RPL" && c.component == Component::Rotation) continue;
    ctx.fail(Alarm::TransformNotAlone, w.loc,
             absl::StrCat(std::string(c.name), " is programmed in a block of its own: ",
                          std::string(a), " cannot be given with it"));
    return false;
  }
  return true;
}

// The slot (0 X, 1 Y, 2 Z) of each axis word; an axis that is no X, Y or Z is refused.
bool slotWords(BlockContext& ctx, const FrameCommand& c,
               std::array<const WordValue*, 3>& words) {
  words = {};
  for (int i = 0; i < ctx.axisCount(); ++i) {
    const std::optional<WordValue>& w = ctx.words.axes[i];
    if (!w) continue;
    int slot = -1;
    for (int s = 0; s < 3; ++s)
      if (ctx.core.xyz[s] == i) slot = s;
    if (slot < 0) {
      ctx.fail(Alarm::AddressNotSupported, w->loc,
               absl::StrCat(std::string(c.name), " ", std::string(w->address),
                            ": frames on axes other than X, Y and Z are not supported yet"));
      return false;
    }
    words[slot] = &*w;
  }
  return true;
}

double degrees(const BlockContext& ctx, const WordValue& w) {
  return ctx.settings.values.rotary(w.value, w.point);
}

// The component the instruction programs, as a map of programmed points; nullopt after an error.
std::optional<ir::Affine> component(BlockContext& ctx, const FrameCommand& c,
                                    const std::array<const WordValue*, 3>& words) {
  const std::array<int8_t, 3>& xyz = ctx.core.xyz;
  const Vec3 origin{};
  switch (c.component) {
    case Component::Translation: {
      ir::Affine m = identityAffine(xyz);
      for (int s = 0; s < 3; ++s)
        if (words[s]) m.t[s] = ctx.axisValue(xyz[s], *words[s]);
      return m;
    }
    case Component::Rotation: {
      if (ctx.words.rpl) {
        for (const WordValue* w : words)
          if (w) {
            ctx.fail(Alarm::AddressWithoutMeaning, w->loc,
                     absl::StrCat(std::string(c.name), ": give either RPL= (a rotation in the "
                                  "plane) or the angles about X, Y and Z, not both"));
            return std::nullopt;
          }
        const auto sl = planeSlots(ctx.next.modal.plane);
        Vec3 axis{};
        axis[sl[2]] = 1.0;
        return rotation(xyz, origin, axis, degrees(ctx, *ctx.words.rpl));
      }
      // In space: the angles as roll, pitch and yaw (MD10600 FRAME_ANGLE_INPUT_MODE = 1, the
      // default): about Z first, then the new Y, then the new X.
      ir::Affine m = identityAffine(xyz);
      for (int s : {2, 1, 0}) {
        if (!words[s]) continue;
        Vec3 axis{};
        axis[s] = 1.0;
        m = compose(m, rotation(xyz, origin, axis, degrees(ctx, *words[s])));
      }
      return m;
    }
    case Component::Scale: {
      Vec3 f{1, 1, 1};
      for (int s = 0; s < 3; ++s) {
        if (!words[s]) continue;
        f[s] = words[s]->value;
        if (f[s] == 0.0 || !std::isfinite(f[s])) {
          ctx.fail(Alarm::ScaleFactorRange, words[s]->loc,
                   absl::StrCat(std::string(c.name), " ", kSlotName[s], "0: a scale factor cannot be 0"));
          return std::nullopt;
        }
      }
      return scaling(xyz, origin, f);
    }
    case Component::Mirror: {
      // The value is not read: MIRROR X0 mirrors X (the manual writes 0).
      Vec3 f{1, 1, 1};
      for (int s = 0; s < 3; ++s)
        if (words[s]) f[s] = -1.0;
      return scaling(xyz, origin, f);
    }
  }
  return std::nullopt;
}

}  // namespace

bool frameTakesAxisWords(const BlockContext& ctx) { return ctx.words.frame != nullptr; }

void applyFrameInstruction(BlockContext& ctx) {
  const FrameCommand* c = ctx.words.frame;
  if (!c) {
    if (ctx.words.rpl)
      ctx.fail(Alarm::AddressWithoutMeaning, ctx.words.rpl->loc,
               "RPL= (a rotation in the plane) has a meaning with ROT or AROT only");
    return;
  }
  if (ctx.failed || !alone(ctx, *c)) return;
  std::array<const WordValue*, 3> words;
  if (!slotWords(ctx, *c, words)) return;
  const bool programmed = words[0] || words[1] || words[2] || ctx.words.rpl;
  const std::optional<ir::Affine>& in_force = ctx.core.cs().transforms->programmable;
  std::optional<ir::Affine> frame;  // the programmable frame after the block; nullopt: none
  if (programmed) {
    std::optional<ir::Affine> m = component(ctx, *c, words);
    if (!m) return;
    frame = c->additive && in_force ? compose(*in_force, *m) : *m;
    if (isIdentity(*frame)) frame.reset();
  } else if (c->additive) {
    frame = in_force;  // ATRANS alone adds nothing
  }
  // The tool stays where it is (TransformState::tool_at, kept as it was).
  ctx.next.transforms.edit().programmable = frame;
}

}  // namespace ncc::passes
