//! What well-formed spatial attributes can still get wrong, and the engine's exact
//! `SpatialArmSpec` when nothing is.

use num_traits::{Signed, Zero};
use planar_arm_core::mechanics::spatial::{
    unit_axis, FixedAngle, SpatialArmSpec, SpatialBody, SpatialGeometry, SpatialJointSpec,
};
use planar_arm_core::ring::{ratio, to_f64, Rational};
use planar_arm_core::Poly;
use quote::ToTokens;

use super::angle::Angle;
use super::ast::{SpatialArm, SpatialJoint};
use super::attr::{Convention, Scalar, Spanned, INERTIA_KEYS};
use crate::ctxt::Ctxt;

fn fixed(a: &Option<Spanned<Angle>>) -> FixedAngle {
    a.as_ref().map_or_else(FixedAngle::zero, |a| FixedAngle {
        radians: a.value.radians.clone(),
        pi_multiple: a.value.pi_multiple.clone(),
    })
}

fn or_zero(v: &Option<Scalar>) -> Poly {
    v.as_ref().map_or_else(Poly::default, |v| v.value.clone())
}

/// A literal value that must not be negative.
fn not_negative(cx: &Ctxt, v: &Option<Scalar>, message: &str) -> bool {
    match v
        .as_ref()
        .and_then(|v| v.value.as_rational().map(|r| (r, &v.tokens)))
    {
        Some((r, tokens)) if r.is_negative() => {
            cx.error_spanned_by(tokens, message);
            false
        }
        _ => true,
    }
}

/// A valid arm: the engine's spec, its joints' names, and the file it was read from.
pub struct Checked {
    pub spec: SpatialArmSpec,
    pub names: Vec<String>,
    pub file: Option<crate::models::Imported>,
}

/// The joints of an arm read from a model file; `None` after recording the error.
fn imported(cx: &Ctxt, arm: &SpatialArm<'_>) -> Option<Option<crate::models::Imported>> {
    let a = &arm.attrs;
    if a.model_written && (a.model.is_none() || a.malformed) {
        // The key's error is reported; reading a file on top would only add to it.
        return None;
    }
    let Some((format, lit)) = &a.model else {
        for lit in a.base.iter().chain(&a.tip) {
            // #[arm(tip = "tool0")] on a hand-written arm
            cx.error_spanned_by(
                lit,
                "`base` and `tip` choose the chain of a model file; they go with `urdf = \"..\"` \
                 or `mjcf = \"..\"`",
            );
        }
        return (a.base.is_none() && a.tip.is_none()).then_some(None);
    };
    if let Some(t) = a
        .tool_xyz
        .as_ref()
        .map(|t| &t.tokens)
        .or(a.tool_rpy.as_ref().map(|t| &t.tokens))
    {
        cx.error_spanned_by(
            t,
            "an arm read from a file has its tool frame at the file's `tip`: name that body or \
             link with `tip = \"..\"`",
        );
        return None;
    }
    let name = |l: &Option<syn::LitStr>| l.as_ref().map(syn::LitStr::value);
    match crate::models::import(
        *format,
        &lit.value(),
        name(&a.base).as_deref(),
        name(&a.tip).as_deref(),
    ) {
        Ok(file) => Some(Some(file)),
        Err(e) => {
            cx.error_spanned_by(lit, e.0);
            None
        }
    }
}

/// Validates the parsed arm; `None` after recording errors in `cx`.
pub fn check(cx: &Ctxt, arm: &SpatialArm<'_>) -> Option<Checked> {
    let mut ok = true;
    for p in &arm.attrs.params {
        if let Err(msg) = arm.f64_field(&p.name) {
            cx.error_spanned_by(&p.tokens, msg);
            ok = false;
        }
    }
    let file = imported(cx, arm)?;
    let first = arm
        .joints
        .iter()
        .find_map(|j| j.attrs.geometry.as_ref().map(|g| (g.convention, j.name())));
    let mut joints = Vec::new();
    for joint in &arm.joints {
        for p in &joint.attrs.params {
            if let Err(msg) = arm.f64_field(&p.name) {
                cx.error_spanned_by(&p.tokens, msg);
                ok = false;
            }
        }
        match check_joint(cx, joint, first.as_ref()) {
            Some(spec) => joints.push(spec),
            None => ok = false,
        }
    }
    ok &= joints.len() == arm.joints.len();
    let mut names: Vec<String> = arm.joints.iter().map(SpatialJoint::name).collect();
    if let Some(f) = &file {
        joints.clone_from(&f.joints);
        names.clone_from(&f.names);
    }
    let a = &arm.attrs;
    let triple = |t: &Option<Spanned<[Poly; 3]>>, default: [Poly; 3]| {
        t.as_ref().map_or(default, |t| t.value.clone())
    };
    // Standard gravity down the base's z axis, as URDF and MuJoCo assume.
    let down = Poly::constant(ratio(-981, 100));
    let from_file = file.as_ref().and_then(|f| f.gravity.clone());
    let gravity = triple(
        &a.gravity,
        from_file.unwrap_or([Poly::default(), Poly::default(), down]),
    );
    let tool_xyz = triple(
        &a.tool_xyz,
        file.as_ref().map_or_else(
            || [Poly::default(), Poly::default(), Poly::default()],
            |f| f.tool_xyz.clone(),
        ),
    );
    let tool_rpy = a.tool_rpy.as_ref().map_or_else(
        || {
            file.as_ref().map_or_else(
                || [FixedAngle::zero(), FixedAngle::zero(), FixedAngle::zero()],
                |f| f.tool_rpy.clone(),
            )
        },
        |r| {
            r.value.clone().map(|x| FixedAngle {
                radians: x.radians,
                pi_multiple: x.pi_multiple,
            })
        },
    );
    let payload = check_payload(cx, a);
    ok &= payload.is_ok();
    ok.then(|| Checked {
        spec: SpatialArmSpec {
            joints,
            gravity,
            tool_xyz,
            tool_rpy,
            payload: payload.ok().flatten(),
        },
        names,
        file,
    })
}

/// The payload at the tool frame, if the struct gives one; `Err` after recording errors.
fn check_payload(cx: &Ctxt, a: &super::attr::SpatialAttrs) -> Result<Option<SpatialBody>, ()> {
    if a.payload.is_none() {
        for tokens in &a.payload_extras {
            // #[arm(payload_com = (0, 0, 0.1))] alone
            cx.error_spanned_by(
                tokens,
                "a payload's centre of mass or inertia needs its mass: add `payload = <kg>` \
                 (the payload is held at the tool frame)",
            );
        }
        return if a.payload_extras.is_empty() {
            Ok(None)
        } else {
            Err(())
        };
    }
    let mut ok = not_negative(cx, &a.payload, "a payload's mass cannot be negative");
    ok &= check_inertia(cx, "the payload's", &a.payload_inertia);
    if !ok {
        return Err(());
    }
    Ok(Some(SpatialBody {
        mass: or_zero(&a.payload),
        com: a.payload_com.as_ref().map_or_else(
            || [Poly::default(), Poly::default(), Poly::default()],
            |c| c.value.clone(),
        ),
        inertia: core::array::from_fn(|i| or_zero(&a.payload_inertia[i])),
    }))
}

fn check_joint(
    cx: &Ctxt,
    joint: &SpatialJoint<'_>,
    first: Option<&(Convention, String)>,
) -> Option<SpatialJointSpec> {
    let name = joint.name();
    let a = &joint.attrs;
    let mut ok = true;
    let Some(g) = &a.geometry else {
        if a.geometry_written {
            // The geometry written could not be read; that error is reported.
            return None;
        }
        // At the #[arm(...)], or at the field's name when it has none.
        let tokens = if a.tokens.is_empty() {
            joint.field.ident.to_token_stream()
        } else {
            a.tokens.clone()
        };
        cx.error_spanned_by(
            tokens,
            format!(
                "joint `{name}` has no geometry: write `dh(a = .., alpha = .., d = .., theta = ..)`, \
                 `mdh(...)`, or `origin(xyz = (..), rpy = (..)), axis = (..)` in its #[arm(...)]"
            ),
        );
        return None;
    };
    if let Some((convention, first_name)) = first {
        if *convention != g.convention {
            cx.error_spanned_by(
                &g.tokens,
                format!(
                    "joint `{name}` is written with `{}` but `{first_name}` with `{}`; write every joint of \
                     an arm in one convention",
                    g.convention.key(),
                    convention.key()
                ),
            );
            ok = false;
        }
    }
    let geometry = match g.convention {
        Convention::Dh | Convention::Mdh => {
            if let Some(axis) = &a.axis {
                cx.error_spanned_by(
                    &axis.tokens,
                    format!("`axis` goes with `origin(...)`; a `{}` joint moves about or along its z axis", g.convention.key()),
                );
                ok = false;
            }
            let (a_, alpha, d, theta) = (
                or_zero(&g.a),
                fixed(&g.alpha),
                or_zero(&g.d),
                fixed(&g.theta),
            );
            if g.convention == Convention::Dh {
                SpatialGeometry::Dh {
                    a: a_,
                    alpha,
                    d,
                    theta,
                }
            } else {
                SpatialGeometry::Mdh {
                    a: a_,
                    alpha,
                    d,
                    theta,
                }
            }
        }
        Convention::Origin => {
            let z = || {
                [
                    Rational::zero(),
                    Rational::zero(),
                    Rational::from_integer(1.into()),
                ]
            };
            let axis = match &a.axis {
                // Reported, and replaced so that `unit_axis` does not divide by its length.
                Some(x) if x.value.iter().all(Zero::is_zero) => {
                    cx.error_spanned_by(&x.tokens, format!("joint `{name}`: a zero axis moves nothing; give its direction, e.g. `axis = (0, 0, 1)`"));
                    ok = false;
                    z()
                }
                Some(x) => x.value.clone(),
                None => z(),
            };
            let xyz = g.xyz.as_ref().map_or_else(
                || [Poly::default(), Poly::default(), Poly::default()],
                |t| t.value.clone(),
            );
            let rpy = g.rpy.as_ref().map_or_else(
                || [FixedAngle::zero(), FixedAngle::zero(), FixedAngle::zero()],
                |r| {
                    r.value.clone().map(|x| FixedAngle {
                        radians: x.radians,
                        pi_multiple: x.pi_multiple,
                    })
                },
            );
            SpatialGeometry::Urdf {
                xyz,
                rpy,
                axis: unit_axis(&axis),
            }
        }
    };
    ok &= not_negative(
        cx,
        &a.mass,
        &format!("joint `{name}`: a mass cannot be negative"),
    );
    ok &= not_negative(
        cx,
        &a.armature,
        &format!("joint `{name}`: armature cannot be negative"),
    );
    ok &= not_negative(
        cx,
        &a.damping,
        &format!("joint `{name}`: damping cannot be negative (it would feed energy in)"),
    );
    ok &= not_negative(
        cx,
        &a.frictionloss,
        &format!("joint `{name}`: frictionloss cannot be negative (it would feed energy in)"),
    );
    ok &= not_negative(
        cx,
        &a.stiffness,
        &format!("joint `{name}`: a spring's stiffness cannot be negative (it would push the joint away)"),
    );
    ok &= check_inertia(cx, &format!("joint `{name}`:"), &a.inertia);
    let range = a.range.as_ref().and_then(|r| {
        let (lo, hi) = &r.value;
        if to_f64(lo) >= to_f64(hi) {
            cx.error_spanned_by(
                &r.tokens,
                format!("joint `{name}`: a range needs lower < upper as f64 values"),
            );
            ok = false;
            return None;
        }
        Some((lo.clone(), hi.clone()))
    });
    let inertia: [Poly; 6] = core::array::from_fn(|i| or_zero(&a.inertia[i]));
    ok.then(|| SpatialJointSpec {
        geometry,
        kind: joint.kind,
        mass: or_zero(&a.mass),
        com: a.com.as_ref().map_or_else(
            || [Poly::default(), Poly::default(), Poly::default()],
            |c| c.value.clone(),
        ),
        inertia,
        range,
        armature: or_zero(&a.armature),
        damping: or_zero(&a.damping),
        frictionloss: or_zero(&a.frictionloss),
        stiffness: or_zero(&a.stiffness),
        springref: or_zero(&a.springref),
    })
}

/// Literal inertia tensors must have no negative moment on the diagonal. The triangle
/// inequality is not required: published models break it (Corke's PUMA 560 gives the waist only
/// `Iyy`), and kinematics and gravity do not depend on the tensor.
fn check_inertia(cx: &Ctxt, whose: &str, inertia: &[Option<Scalar>; 6]) -> bool {
    let mut ok = true;
    for (i, v) in inertia.iter().enumerate().take(3) {
        if let Some(v) = v {
            if v.value.as_rational().is_some_and(|r| r.is_negative()) {
                cx.error_spanned_by(
                    &v.tokens,
                    format!("{whose} inertia `{}` cannot be negative", INERTIA_KEYS[i]),
                );
                ok = false;
            }
        }
    }
    ok
}
