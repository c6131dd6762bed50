// The coordinate transform codes: G68/G69 rotation (2-D in the plane, 3-D about I J K), G51/G50
// scaling, G51.1/G50.1 mirror and Mazak's G92.5 work coordinate rotation, read into
// TransformState. lowering_transform_map.cpp composes them into the map the `transform` pass
// applies; lowering_figure_rotation.cpp is Mazak's figure rotation. What differs between the
// controls is TransformRules (dialect_table.h); docs/transforms.md gives each rule with its
// manual.
#include <cmath>
#include <numbers>

#include "absl/strings/str_cat.h"
#include "affine.h"
#include "lowering_context.h"

namespace ncc::passes {

namespace {

constexpr const char* kSlotName[] = {"X", "Y", "Z"};

const TransformRules& rules(const BlockContext& ctx) { return *ctx.table.transforms; }
const std::array<int8_t, 3>& xyz(const BlockContext& ctx) { return ctx.core.xyz; }

// The block's word on slot s (X, Y, Z), or null.
const std::optional<WordValue>* slotWord(const BlockContext& ctx, int s) {
  const int i = xyz(ctx)[s];
  return i >= 0 && i < kMaxAxes ? &ctx.words.axes[i] : nullptr;
}

// The programmed point (work coordinates) on the slots.
Vec3 programmed(const BlockContext& ctx) {
  const AxisValues w = ctx.baseWork();
  Vec3 p{};
  for (int s = 0; s < 3; ++s)
    if (xyz(ctx)[s] >= 0) p[s] = w[xyz(ctx)[s]];
  return p;
}

// An axis word that is no X, Y or Z (the transforms act on those three): an error.
bool onlyXyzWords(BlockContext& ctx, const char* code) {
  for (int i = 0; i < ctx.axisCount(); ++i) {
    if (!ctx.words.axes[i]) continue;
    bool slot = false;
    for (int s = 0; s < 3; ++s) slot = slot || xyz(ctx)[s] == i;
    if (!slot) {
      ctx.fail(Alarm::AddressWithoutMeaning, ctx.words.axes[i]->loc,
               absl::StrCat("address ", std::string(ctx.words.axes[i]->address), " has no meaning in ", code,
                            " (it acts on X, Y and Z)"));
      return false;
    }
  }
  return true;
}

double angle(const BlockContext& ctx, const WordValue& w) {
  return ctx.settings.values.rotary(w.value, w.point);
}

bool angleInRange(BlockContext& ctx, const WordValue& w, double degrees, const char* code) {
  if (std::isfinite(degrees) && std::fabs(degrees) <= 360.0 + 1e-9) return true;
  ctx.fail(Alarm::RotationAngleRange, w.loc,
           absl::StrCat(code, " R", w.value, ": the angle must be within -360 to 360 degrees"));
  return false;
}

// ---- G68 ----------------------------------------------------------------------------------
void pushRotation(BlockContext& ctx, const GWord& g, const ir::Affine& r, bool stacks) {
  TransformState& t = ctx.next.transforms.edit();
  if (t.figure_call) {  // Mazak §13-8 6., §13-7 note 4
    ctx.fail(Alarm::FigureRotationWithRotation, g.loc,
             "G68 cannot be given during a figure rotation (M98 with I J K)");
    return;
  }
  if (!stacks || t.rotations.empty()) {
    t.rotations.assign(1, r);
    return;
  }
  const int max = rules(ctx).max_rotations;
  if (max > 0 && static_cast<int>(t.rotations.size()) >= max) {
    if (!rules(ctx).extra_rotation_replaces_last) {
      ctx.fail(Alarm::RotationNesting, g.loc,
               absl::StrCat("G68: ", max, " rotations are in force already; G69 cancels them"));
      return;
    }
    t.rotations.back() = r;
    return;
  }
  t.rotations.push_back(r);
}

void rotation3d(BlockContext& ctx, const GWord& g) {
  const TransformRules& r = rules(ctx);
  ctx.used_ijk = true;
  Vec3 v{};
  const std::optional<WordValue>* ijk[] = {&ctx.words.i, &ctx.words.j, &ctx.words.k};
  for (int s = 0; s < 3; ++s)
    if (*ijk[s]) v[s] = ctx.lengthValue(**ijk[s]);
  const int nonzero = (v[0] != 0) + (v[1] != 0) + (v[2] != 0);
  if (r.rotation_3d_unit_axis_only) {
    // Mazak ch. 22 §2: I, J and K are all required, exactly one of them 1.
    bool unit = nonzero == 1 && *ijk[0] && *ijk[1] && *ijk[2];
    for (double c : v) unit = unit && (c == 0 || std::fabs(std::fabs(c) - 1.0) < 1e-9);
    if (!unit) {
      ctx.fail(Alarm::RotationVector, g.loc,
               "G68 I J K: all three are needed and exactly one of them is 1 (the axis of the "
               "rotation)");
      return;
    }
  }
  if (nonzero == 0) {  // a zero vector: the normal of the plane in force (Siemens §3.1.10)
    const auto sl = planeSlots(ctx.next.modal.plane);
    v = {};
    v[sl[2]] = 1.0;
  }
  const Vec3 here = programmed(ctx);
  Vec3 centre{};
  for (int s = 0; s < 3; ++s) {
    const auto* w = slotWord(ctx, s);
    if (w && *w)
      centre[s] = ctx.axisValue(xyz(ctx)[s], **w);  // always absolute
    else if (!r.rotation_3d_centre_is_origin)
      centre[s] = here[s];
  }
  double deg = ctx.settings.default_rotation_angle;
  if (ctx.words.r) {
    ctx.used_r = true;
    deg = angle(ctx, *ctx.words.r);
    if (!angleInRange(ctx, *ctx.words.r, deg, "G68")) return;
  } else if (r.rotation_angle_required) {
    ctx.fail(Alarm::TransformWordMissing, g.loc, "G68 needs the angle R");
    return;
  }
  ir::Affine turn = rotation(xyz(ctx), centre, v, deg);
  if (r.rotation_3d_centre_is_new_zero) {
    // The program zero moves to the centre, then the system turns there: p -> c + R p.
    turn = rotation(xyz(ctx), {}, v, deg);
    turn.t = {centre[0], centre[1], centre[2]};
  }
  ctx.next.transforms.edit().rotation_3d = true;
  pushRotation(ctx, g, turn, r.rotation_stacks_3d);
}

void rotation2d(BlockContext& ctx, const GWord& g) {
  const TransformRules& r = rules(ctx);
  TransformState& t = ctx.next.transforms.edit();
  const auto sl = planeSlots(ctx.next.modal.plane);
  for (int s = 0; s < 3; ++s) {
    const auto* w = slotWord(ctx, s);
    if (s == sl[2] && w && *w) {
      ctx.fail(Alarm::AddressWithoutMeaning, (*w)->loc,
               absl::StrCat("address ", std::string((*w)->address), " has no meaning in a G68 rotation in the ",
                            kSlotName[sl[0]], kSlotName[sl[1]], " plane (I J K make it 3-D)"));
      return;
    }
  }
  const Vec3 here = programmed(ctx);
  Vec3 centre = here;  // omitted: where the G68 block is (all three manuals)
  for (int s : {sl[0], sl[1]}) {
    const auto* w = slotWord(ctx, s);
    if (w && *w) centre[s] = ctx.axisValue(xyz(ctx)[s], **w);  // always absolute
  }
  double deg = ctx.settings.default_rotation_angle;
  if (ctx.words.r) {
    ctx.used_r = true;
    deg = angle(ctx, *ctx.words.r);
    const bool incremental = (r.rotation_angle_follows_distance ||
                              ctx.settings.rotation_angle_incremental) &&
                             ctx.words.r->mode == ir::DistanceMode::Incremental;
    // Stacked (Siemens): the new frame turns relative to the one in force already.
    if (incremental && !t.rotations.empty() && !r.rotation_stacks_2d) deg += t.angle_2d;
    if (!angleInRange(ctx, *ctx.words.r, deg, "G68")) return;
  } else if (r.rotation_angle_required) {
    ctx.fail(Alarm::TransformWordMissing, g.loc, "G68 needs the angle R");
    return;
  }
  Vec3 axis{};
  axis[sl[2]] = 1.0;  // counterclockwise seen from the plane's third axis
  t.angle_2d = deg;
  pushRotation(ctx, g, rotation(xyz(ctx), centre, axis, deg), r.rotation_stacks_2d);
}

// ---- G51 ----------------------------------------------------------------------------------
// The factor written as P (or I J K): a point gives the value, no point counts increments.
double factorValue(const BlockContext& ctx, const WordValue& w) {
  const TransformRules& r = rules(ctx);
  if (w.point) return w.value;
  return w.value * (r.scale_p_fixed_increment ? r.scale_p_increment : ctx.settings.scale_factor_unit);
}

bool checkFactor(BlockContext& ctx, const WordValue& w, double& f, bool may_be_negative) {
  const TransformRules& r = rules(ctx);
  if (r.scale_tiny_factor_is_one && std::fabs(f) < 1e-6) f = 1.0;
  const bool sign_ok = may_be_negative || f > 0.0;
  if (std::isfinite(f) && sign_ok && f != 0.0 && std::fabs(f) <= r.scale_factor_max + 1e-9)
    return true;
  ctx.fail(Alarm::ScaleFactorRange, w.loc,
           absl::StrCat("G51 ", std::string(w.address), w.value, ": the scale factor must be ",
                        may_be_negative ? "non-zero" : "positive", " and at most ",
                        r.scale_factor_max));
  return false;
}

void scale(BlockContext& ctx, const GWord& g) {
  const TransformRules& r = rules(ctx);
  if (!onlyXyzWords(ctx, "G51")) return;
  TransformState& t = ctx.next.transforms.edit();
  const bool adds = r.rescale_adds_axes && t.scaling;
  if (!adds) {
    t.scaled = {};
    t.scale_centre = {};
    t.scale_factor = {1.0, 1.0, 1.0};
  }
  // The factors: P for every axis, or I J K per axis.
  Vec3 factor{1.0, 1.0, 1.0};
  const double fallback =
      ctx.settings.default_scale_factor > 0 ? ctx.settings.default_scale_factor : 1.0;
  const std::optional<WordValue>* ijk[] = {&ctx.words.i, &ctx.words.j, &ctx.words.k};
  auto ignored = [&](const WordValue& w, const char* why) {
    ctx.core.diags.warning(std::string(ctx.table.alarm(Alarm::AddressWithoutMeaning)), w.loc,
                           absl::StrCat("G51 ", std::string(w.address), " is ignored: ", why));
  };
  if (ctx.settings.scale_per_axis) {
    ctx.used_ijk = true;
    for (int s = 0; s < 3; ++s) {
      factor[s] = fallback;
      if (!*ijk[s]) continue;
      factor[s] = factorValue(ctx, **ijk[s]);
      if (!checkFactor(ctx, **ijk[s], factor[s], true)) return;
    }
    if (ctx.words.p) {
      ctx.used_p = true;
      ignored(*ctx.words.p, "the factors are I, J, K (scale_per_axis = true)");
    }
  } else {
    double f = fallback;
    if (ctx.words.p) {
      ctx.used_p = true;
      const WordValue& p = *ctx.words.p;
      // Mazak §13-10 4.7: a point is read only after G51 (`P0.5 G51` is P = 0, i.e. x1).
      f = r.scale_p_point_only_after_g51 && p.point && p.order < g.order ? 0.0
                                                                          : factorValue(ctx, p);
      if (!checkFactor(ctx, p, f, false)) return;
    }
    factor = {f, f, f};
    for (int s = 0; s < 3; ++s)
      if (*ijk[s]) {
        ctx.used_ijk = true;
        ignored(**ijk[s], "the factor is P (scale_per_axis = false)");
      }
  }
  const Vec3 here = programmed(ctx);
  for (int s = 0; s < 3; ++s) {
    if (xyz(ctx)[s] < 0) continue;
    const auto* w = slotWord(ctx, s);
    if (w && *w) {
      double v = ctx.axisValue(xyz(ctx)[s], **w);
      if (r.scale_centre_follows_distance && (*w)->mode == ir::DistanceMode::Incremental)
        v += here[s];
      t.scale_centre[s] = v;
      t.scaled[s] = true;
    } else if (!t.scaled[s]) {
      switch (r.scale_centre_omitted) {
        case TransformRules::ScaleCentre::CurrentPosition:
          t.scale_centre[s] = here[s];
          t.scaled[s] = true;
          break;
        case TransformRules::ScaleCentre::WorkOrigin:
          t.scale_centre[s] = 0.0;
          t.scaled[s] = true;
          break;
        case TransformRules::ScaleCentre::AxisNotScaled: break;
      }
    }
  }
  t.scale_factor = factor;
  t.scaling = true;
}

// ---- G51.1 / G50.1 ------------------------------------------------------------------------
bool mirrorAllowed(BlockContext& ctx, const GWord& g) {
  const TransformState& t = *ctx.next.transforms;
  if (!rules(ctx).mirror_only_outside_others || (!t.scaling && t.rotations.empty())) return true;
  ctx.fail(Alarm::TransformOrder, g.loc,
           absl::StrCat(gCodeName(g.entry->code10), " cannot be given while ",
                        t.scaling ? "scaling (G51)" : "coordinate rotation (G68)",
                        " is in force: mirror, scaling and rotation are switched on in that "
                        "order and off in the reverse order"));
  return false;
}

void mirror(BlockContext& ctx, const GWord& g) {
  if (!onlyXyzWords(ctx, "G51.1") || !mirrorAllowed(ctx, g)) return;
  TransformState& t = ctx.next.transforms.edit();
  const Vec3 here = programmed(ctx);
  bool any = false;
  for (int s = 0; s < 3; ++s) {
    const auto* w = slotWord(ctx, s);
    if (!w || !*w) continue;
    double v = ctx.axisValue(xyz(ctx)[s], **w);
    if (rules(ctx).mirror_centre_follows_distance && (*w)->mode == ir::DistanceMode::Incremental)
      v += here[s];
    t.mirrored[s] = true;
    t.mirror_centre[s] = v;
    any = true;
  }
  if (!any)
    ctx.fail(Alarm::TransformWordMissing, g.loc,
             "G51.1 needs the axis to mirror and its centre (X, Y or Z)");
}

void mirrorCancel(BlockContext& ctx, const GWord& g) {
  if (!onlyXyzWords(ctx, "G50.1") || !mirrorAllowed(ctx, g)) return;
  TransformState& t = ctx.next.transforms.edit();
  bool any = false;
  for (int s = 0; s < 3; ++s) {
    const auto* w = slotWord(ctx, s);
    if (w && *w) {
      t.mirrored[s] = false;  // the coordinate itself is ignored (Mazak §13-11)
      any = true;
    }
  }
  if (!any) t.mirrored = {};  // G50.1 alone: every axis
}

// The plane's alone-rule (Siemens §3.1.9, §3.2.3): G68/G69/G51/G50 blocks hold no other G code
// than the plane (the manual's own format is `G17 G68 X Y R`).
bool alone(BlockContext& ctx, const GWord& g, bool always = false) {
  if (!always && !rules(ctx).transform_block_alone) return true;
  for (size_t i = 0; i < ctx.words.modal.size(); ++i) {
    const auto& other = ctx.words.modal[i];
    if (!other || other->entry == g.entry || other->entry->group == GGroup::Plane) continue;
    ctx.fail(Alarm::TransformNotAlone, other->loc,
             absl::StrCat(gCodeName(g.entry->code10), " must stand alone in its block (",
                          gCodeName(other->entry->code10), " is not allowed with it)"));
    return false;
  }
  if (ctx.words.one_shot) {
    ctx.fail(Alarm::TransformNotAlone, ctx.words.one_shot->loc,
             absl::StrCat(gCodeName(g.entry->code10), " must stand alone in its block"));
    return false;
  }
  return true;
}

}  // namespace

bool transformTakesAxisWords(const BlockContext& ctx) {
  for (GGroup group : {GGroup::Rotation, GGroup::Scaling, GGroup::Mirror}) {
    const auto& w = ctx.words.group(group);
    if (!w) continue;
    const GAction a = w->entry->action;
    if (a == GAction::Rotation || a == GAction::Scaling || a == GAction::Mirror ||
        a == GAction::MirrorCancel)
      return true;
  }
  return false;
}

void applyTransformCodes(BlockContext& ctx) {
  if (!ctx.table.transforms) return;
  // Read here, written (edit()) only by the codes that change it: most blocks have none.
  const TransformState& t = *ctx.next.transforms;
  // Mazak ch. 22 §2 and the §5.1 table: scaling and the work systems G54-G59 are refused while
  // a 3-D G68 is in force (943).
  if (t.rotation_3d && rules(ctx).rotation_3d_restricted) {
    for (GGroup group : {GGroup::Scaling, GGroup::WorkOffset}) {
      const auto& w = ctx.words.group(group);
      if (!w) continue;
      ctx.fail(Alarm::TransformOrder, w->loc,
               absl::StrCat(gCodeName(w->entry->code10),
                            " cannot be given while a 3-D coordinate conversion (G68 with I J K) "
                            "is in force"));
      return;
    }
  }
  const GWord* taker = nullptr;  // the code whose words the axis words are
  for (GGroup group : {GGroup::Rotation, GGroup::Scaling, GGroup::Mirror}) {
    const auto& w = ctx.words.group(group);
    if (!w || ctx.failed) continue;
    const GAction a = w->entry->action;
    if (a == GAction::Rotation || a == GAction::Scaling || a == GAction::Mirror ||
        a == GAction::MirrorCancel) {
      if (taker) {
        ctx.fail(Alarm::OneShotConflict, w->loc,
                 absl::StrCat(gCodeName(w->entry->code10), " and ",
                              gCodeName(taker->entry->code10),
                              " both take the axis words: give them in separate blocks"));
        return;
      }
      taker = &*w;
    }
    if ((a == GAction::Rotation || a == GAction::RotationCancel || a == GAction::Scaling ||
         a == GAction::ScalingCancel) &&
        !alone(ctx, *w))
      return;
    // Mazak ch. 22 §5.2: a 3-D G68 (or the G69 of one) holds no other G code than the plane.
    const bool three_d = (a == GAction::Rotation && (ctx.words.i || ctx.words.j || ctx.words.k)) ||
                         (a == GAction::RotationCancel && ctx.next.transforms->rotation_3d);
    if (three_d && rules(ctx).rotation_3d_restricted && !alone(ctx, *w, true)) return;
    switch (a) {
      case GAction::Rotation:
        if (ctx.words.i || ctx.words.j || ctx.words.k)
          rotation3d(ctx, *w);
        else
          rotation2d(ctx, *w);
        break;
      case GAction::RotationCancel: {
        TransformState& edited = ctx.next.transforms.edit();
        edited.rotations.clear();
        edited.angle_2d = 0.0;
        edited.rotation_3d = false;
        break;
      }
      case GAction::Scaling: scale(ctx, *w); break;
      case GAction::ScalingCancel: {
        TransformState& edited = ctx.next.transforms.edit();
        edited.scaling = false;
        edited.scaled = {};
        break;
      }
      case GAction::Mirror: mirror(ctx, *w); break;
      case GAction::MirrorCancel: mirrorCancel(ctx, *w); break;
      default: break;
    }
  }
  // Mazak 817: the move after G92.5 is a line; an arc would start off its circle.
  if (!ctx.failed && ctx.next.transforms->work_rotation_just_set && !ctx.words.one_shot &&
      ctx.words.anyAxis() && !taker) {
    if (ctx.next.motion == GAction::ArcCW || ctx.next.motion == GAction::ArcCCW) {
      ctx.fail(Alarm::ArcAfterWorkRotation, ctx.motionLoc(),
               "the move after G92.5 must be G00 or G01, not an arc");
      return;
    }
    ctx.next.transforms.edit().work_rotation_just_set = false;
  }
}

void scalingCancelMove(BlockContext& ctx) {
  if (ctx.failed || !ctx.table.transforms || !rules(ctx).scale_cancel_moves) return;
  const auto& g = ctx.words.group(GGroup::Scaling);
  if (!g || g->entry->action != GAction::ScalingCancel || !ctx.core.cs().transforms->scaling) return;
  for (const ir::Operation& op : ctx.ops)
    if (std::holds_alternative<ir::Rapid>(op) || std::holds_alternative<ir::Linear>(op) ||
        std::holds_alternative<ir::Arc>(op))
      return;  // the block's own move goes to the unscaled point already
  // §13-10 3.B: every axis moves back by the deviation scaling made, in the motion mode.
  const AxisValues to = ctx.baseWork();
  if (ctx.next.motion == GAction::Linear && checkFeed(ctx, false))
    ctx.ops.push_back(ir::Linear{to, ir::Space::Work, ctx.next.modal.feed,
                                 ctx.next.modal.feed_mode == ir::FeedMode::PerRevolution});
  else if (!ctx.failed)
    ctx.ops.push_back(ir::Rapid{to, ir::Space::Work, ctx.settings.rapid_type});
}

void cancelScalingAfterReference(BlockContext& ctx) {
  if (ctx.table.transforms && rules(ctx).reference_return_cancels_scaling) {
    if (ctx.next.transforms->scaling) {
      TransformState& t = ctx.next.transforms.edit();
      t.scaling = false;
      t.scaled = {};
    }
  }
}

void workRotation(BlockContext& ctx, const GWord& g) {
  if (!onlyXyzWords(ctx, "G92.5")) return;
  TransformState& t = ctx.next.transforms.edit();
  const auto sl = planeSlots(ctx.next.modal.plane);
  // The centre: machine coordinates, each kept when omitted; the one off the plane is kept for
  // a later G92.5 in another plane (§14-13 3. (9): `G19 G92.5 J2. K3.` turns about Y20 Z30).
  for (int s = 0; s < 3; ++s) {
    const auto* w = slotWord(ctx, s);
    if (w && *w) t.work_rotation_centre[s] = ctx.axisValue(xyz(ctx)[s], **w);
  }
  // The angle: R, else the direction of the plane's vector (I J in G17, K I in G18, J K in
  // G19; the third is ignored); R beats the vector (§14-13 3.); none, or R0, cancels.
  const std::optional<WordValue>* ijk[] = {&ctx.words.i, &ctx.words.j, &ctx.words.k};
  if (*ijk[0] || *ijk[1] || *ijk[2]) ctx.used_ijk = true;
  std::optional<double> deg;
  if (ctx.words.r) {
    ctx.used_r = true;
    deg = angle(ctx, *ctx.words.r);
    if (!angleInRange(ctx, *ctx.words.r, *deg, "G92.5")) return;
  } else {
    double a = 0.0, b = 0.0;
    if (*ijk[sl[0]]) a = ctx.lengthValue(**ijk[sl[0]]);
    if (*ijk[sl[1]]) b = ctx.lengthValue(**ijk[sl[1]]);
    if (a != 0.0 || b != 0.0) deg = std::atan2(b, a) * 180.0 / std::numbers::pi;
  }
  if (!deg || *deg == 0.0) {
    t.work_rotation.reset();
  } else {
    Vec3 axis{};
    axis[sl[2]] = 1.0;
    t.work_rotation = rotation(xyz(ctx), t.work_rotation_centre, axis, *deg);
    t.work_rotation_just_set = true;
  }
  (void)g;
}

}  // namespace ncc::passes
