//! Physical validation, apart from attribute parsing: what a well-formed attribute can still
//! get wrong. Produces the engine's exact [`ArmSpec`], its values polynomials in the run-time
//! parameters (constants when every value is a literal).
//!
//! Signs and ranges can only be checked for literal values; a value that names a parameter is
//! checked when the methods run (see the `planar_arm` docs on run-time parameters).

use num_traits::{Signed, Zero};
use planar_arm_core::ring::{parse_decimal, ratio, to_f64, Rational};
use planar_arm_core::spatial::FixedAngle;
use planar_arm_core::{down, ArmSpec, JointKind, LinkSpec, Offset, PayloadSpec, Poly};

use crate::ast::{Arm, Link};
use crate::attr::{
    Value, ARMATURE, COM, DAMPING, FRICTIONLOSS, GRAVITY, INERTIA, LENGTH, MASS, PAYLOAD,
    PAYLOAD_COM, PAYLOAD_INERTIA, RANGE, SPRINGREF, STIFFNESS,
};
use crate::ctxt::Ctxt;

/// Standard gravity, 9.80665 m/s^2, exactly.
fn standard_gravity() -> Rational {
    parse_decimal("9.80665").unwrap_or_else(|| ratio(980_665, 100_000))
}

/// Rejects coefficients outside the finite range of `f64`, and non-zero ones that round to
/// zero.
fn representable(cx: &Ctxt, what: &str, v: &Value) -> bool {
    let parts = std::iter::once(&v.value).chain(v.y.as_ref());
    for poly in parts {
        for (_, c) in poly.terms() {
            match to_f64(c) {
                None => {
                    cx.error_spanned_by(
                        &v.tokens,
                        format!("{what} is too large for f64; use a value below 1e308"),
                    );
                    return false;
                }
                Some(x) if x == 0.0 && !c.is_zero() => {
                    cx.error_spanned_by(
                        &v.tokens,
                        format!(
                            "{what} is too small for f64 (it rounds to zero); use a value above 1e-308"
                        ),
                    );
                    return false;
                }
                Some(_) => {}
            }
        }
    }
    true
}

/// Every `self.NAME` must be an `f64` field that is not a link.
fn params_exist(cx: &Ctxt, arm: &Arm<'_>) -> bool {
    let mut ok = true;
    for (_, v) in arm.values() {
        for p in &v.params {
            if let Err(msg) = arm.f64_field(&p.name) {
                cx.error_spanned_by(&p.tokens, msg);
                ok = false;
            }
        }
    }
    ok
}

/// A literal value that must not be negative (or must be positive).
fn sign_check(cx: &Ctxt, v: &Value, positive: bool, message: &str) -> bool {
    match v.value.as_rational() {
        Some(r) if r.is_negative() || (positive && r.is_zero()) => {
            cx.error_spanned_by(&v.tokens, message);
            false
        }
        _ => true,
    }
}

/// `gravity = g` (a magnitude along -y, not negative) or `gravity = (gx, gy)` (an
/// acceleration, any direction): representable, and a magnitude not negative.
fn gravity_check(cx: &Ctxt, g: &Value) -> bool {
    let mut ok = representable(cx, "gravity", g);
    if g.y.is_none() {
        // #[arm(gravity = -9.81)]
        ok &= sign_check(
            cx,
            g,
            false,
            "gravity = <number> is a magnitude along -y and cannot be negative; use 0 for a \
             horizontal arm, or give the acceleration as a pair `gravity = (gx, gy)`",
        );
    }
    ok
}

/// The acceleration `(gx, gy)` a `gravity` key gives.
fn gravity_of(g: &Value) -> (Poly, Poly) {
    match &g.y {
        Some(y) => (g.value.clone(), y.clone()),
        None => down(g.value.clone()),
    }
}

/// Validates the parsed arm; `None` after recording errors in `cx`.
pub fn check(cx: &Ctxt, arm: &Arm<'_>) -> Option<ArmSpec<Poly>> {
    let mut ok = params_exist(cx, arm);
    for lit in arm.attrs.base.iter().chain(&arm.attrs.tip) {
        // #[arm(tip = "hand")] on a hand-written arm
        cx.error_spanned_by(
            lit,
            "`base` and `tip` choose the chain of a model file; they go with `urdf = \"..\"` or \
             `mjcf = \"..\"`",
        );
        ok = false;
    }
    let gravity = match arm.get(GRAVITY) {
        Some(g) => {
            ok &= gravity_check(cx, g);
            gravity_of(g)
        }
        None => down(Poly::constant(standard_gravity())),
    };
    let payload = check_payload(cx, arm, &mut ok);
    let mut links = Vec::new();
    for link in &arm.links {
        match check_link(cx, link) {
            Some(spec) => links.push(spec),
            None => ok = false,
        }
    }
    let spec = (ok && links.len() == arm.links.len()).then_some(ArmSpec {
        links,
        gravity,
        payload,
    })?;
    definite(cx, arm, &spec).then_some(spec)
}

/// An arm read from a model file: its spec, and what the file says of it. `None` after the
/// error is reported.
pub fn check_file(
    cx: &Ctxt,
    arm: &Arm<'_>,
) -> Option<(ArmSpec<Poly>, crate::models::PlanarImport)> {
    let (format, lit) = arm.attrs.model.as_ref().filter(|_| !arm.attrs.malformed)?;
    let mut ok = params_exist(cx, arm);
    let own = arm.get(GRAVITY);
    let name = |l: &Option<syn::LitStr>| l.as_ref().map(syn::LitStr::value);
    let file = match crate::models::import_planar(
        *format,
        &lit.value(),
        name(&arm.attrs.base).as_deref(),
        name(&arm.attrs.tip).as_deref(),
        own.is_some(),
    ) {
        Ok(file) => file,
        Err(e) => {
            cx.error_spanned_by(lit, e.0);
            return None;
        }
    };
    let gravity = match own {
        Some(g) => {
            ok &= gravity_check(cx, g);
            gravity_of(g)
        }
        None => file.planar.gravity.clone(),
    };
    let payload = check_payload(cx, arm, &mut ok);
    let spec = ArmSpec {
        links: file.planar.links.clone(),
        gravity,
        payload,
    };
    if let Some((joint, _)) = spec
        .as_rational()
        .and_then(|l| planar_arm_core::definite::weak_joint(&l))
    {
        cx.error_spanned_by(
            lit,
            format!(
                "joint `{}`: its link moves (almost) no mass and turns no inertia, so its \
                 acceleration is undefined: a planar arm needs mass or armature there",
                file.names[joint]
            ),
        );
        return None;
    }
    ok.then_some((spec, file))
}

/// A literal arm whose mass matrix is singular (some joint moves no mass and turns no inertia,
/// or too little for `f64`) has no forward dynamics: refused at the link of the first such
/// joint. What merely looks degenerate (a link with its mass on its axis, a point cart) passes
/// when the rest of the chain, armature or a payload keeps `M` definite. Arms with run-time
/// parameters are checked by `Model::check` when their values are known.
fn definite(cx: &Ctxt, arm: &Arm<'_>, spec: &ArmSpec<Poly>) -> bool {
    let Some(literal) = spec.as_rational() else {
        return true;
    };
    let Some((joint, relative)) = planar_arm_core::definite::weak_joint(&literal) else {
        return true;
    };
    let link = &arm.links[joint];
    let a = &link.attrs;
    let tokens = a
        .get(INERTIA)
        .or_else(|| a.get(COM))
        .or_else(|| a.get(LENGTH))
        .map_or_else(|| a.tokens.clone(), |v| v.tokens.clone());
    let how = if relative == 0.0 {
        "is singular".to_string()
    } else {
        format!("is nearly singular (relative pivot {relative:.1e})")
    };
    cx.error_spanned_by(
        tokens,
        format!(
            "link `{}`: with these values the mass matrix {how}: its joint moves (almost) no mass \
             and turns no inertia, so its acceleration is undefined; give the link an inertia or a \
             centre of mass off its joint axis, add `armature`, or let a later link or the payload \
             carry mass",
            link.name()
        ),
    );
    false
}

/// `payload`, `payload_inertia`, `payload_com` on the struct.
fn check_payload(cx: &Ctxt, arm: &Arm<'_>, ok: &mut bool) -> Option<PayloadSpec<Poly>> {
    let zero = Poly::default;
    let (mass, inertia, com) = (
        arm.get(PAYLOAD),
        arm.get(PAYLOAD_INERTIA),
        arm.get(PAYLOAD_COM),
    );
    if mass.is_none() {
        // #[arm(payload_inertia = ...)] without #[arm(payload = ...)]
        if let Some(v) = inertia.or(com) {
            cx.error_spanned_by(
                &v.tokens,
                "a payload's inertia or offset needs its mass: add `payload = ...` to the struct's #[arm(...)]",
            );
            *ok = false;
        }
        return None;
    }
    let mut spec = PayloadSpec {
        mass: zero(),
        inertia: zero(),
        com: (zero(), zero()),
    };
    if let Some(m) = mass {
        // #[arm(payload = 0.5)] or #[arm(payload = self.payload)]
        *ok &= sign_check(
            cx,
            m,
            false,
            "the payload's mass cannot be negative; use 0 for none",
        );
        *ok &= representable(cx, "payload", m);
        spec.mass = m.value.clone();
    }
    if let Some(i) = inertia {
        // #[arm(payload_inertia = 0.001)]
        *ok &= sign_check(
            cx,
            i,
            false,
            "the payload's inertia about its centre of mass cannot be negative; use 0 for a point mass",
        );
        *ok &= representable(cx, "payload_inertia", i);
        spec.inertia = i.value.clone();
    }
    if let Some(c) = com {
        // #[arm(payload_com = (0.02, 0.0))]
        *ok &= representable(cx, "payload_com", c);
        spec.com = (c.value.clone(), c.y.clone().unwrap_or_default());
    }
    Some(spec)
}

/// Validates one link: every problem is reported, not only the first.
fn check_link(cx: &Ctxt, link: &Link<'_>) -> Option<LinkSpec<Poly>> {
    let name = link.name();
    let a = &link.attrs;
    let mut ok = true;

    let missing: Vec<&str> = [LENGTH, MASS]
        .into_iter()
        .filter(|k| a.get(k).is_none() && !a.accounted_for(k))
        .collect();
    match missing.as_slice() {
        [] => {}
        [key] => cx.error_spanned_by(
            &a.tokens,
            format!("link `{name}` is missing `{key}`: add `{key} = ...` to its #[arm(...)]"),
        ),
        _ => cx.error_spanned_by(
            &a.tokens,
            format!(
                "link `{name}` is missing `length` and `mass`: write #[arm(length = ..., mass = ...)]"
            ),
        ),
    }

    // #[arm(mass = 2)], #[arm(inertia = 0.02)], #[arm(armature = 0.01)],
    // #[arm(damping = 0.1)], #[arm(frictionloss = 0.2)]: not negative. A massless link (a
    // floating base's slides, which carry the bodies after them) is an arm like any other
    // where the mass matrix stays definite, which `definite` checks.
    let mut non_negative = |key: &str, message: String| -> Option<Poly> {
        let v = a.get(key)?;
        let mut good = representable(cx, key, v);
        good &= sign_check(cx, v, false, &message);
        ok &= good;
        good.then(|| v.value.clone())
    };
    let mass = non_negative(
        MASS,
        format!("link `{name}`: mass cannot be negative, for example `mass = 0.5`"),
    );
    // #[arm(length = 0)]: a point cart, or joints that share an axis point.
    let length = non_negative(
        LENGTH,
        format!("link `{name}`: length cannot be negative; it is the distance from this joint to the next"),
    );
    let inertia = non_negative(
        INERTIA,
        format!("link `{name}`: inertia about the centre of mass cannot be negative; use 0 for a point mass"),
    );
    let armature = non_negative(
        ARMATURE,
        format!("link `{name}`: armature (reflected rotor inertia) cannot be negative"),
    );
    let damping = non_negative(
        DAMPING,
        format!("link `{name}`: damping cannot be negative (it would feed energy in)"),
    );
    let frictionloss = non_negative(
        FRICTIONLOSS,
        format!("link `{name}`: frictionloss cannot be negative (it would feed energy in)"),
    );
    // #[arm(stiffness = 2, springref = -0.3)]: a spring that pushes away is not one.
    let stiffness = non_negative(
        STIFFNESS,
        format!("link `{name}`: stiffness cannot be negative (the spring would push away from springref)"),
    );
    let springref = a.get(SPRINGREF).and_then(|v| {
        let good = representable(cx, SPRINGREF, v);
        ok &= good;
        good.then(|| v.value.clone())
    });
    // #[arm(com = 0.25)] or #[arm(com = (0.11, 0.005))]: any sign (a counterweight lies behind
    // the joint).
    let com = a.get(COM).and_then(|c| {
        let good = representable(cx, "com", c);
        ok &= good;
        good.then(|| (c.value.clone(), c.y.clone().unwrap_or_default()))
    });
    let range = a.get(RANGE).and_then(|v| {
        let good = check_range(cx, &name, link.joint, v);
        ok &= good.is_some();
        good
    });
    if !ok {
        return None;
    }
    let rod = LinkSpec::rod(length?, mass?);
    let inertia = inertia.unwrap_or(rod.inertia);
    let com = com.unwrap_or(rod.com);
    Some(LinkSpec {
        length: rod.length,
        mass: rod.mass,
        inertia,
        com,
        armature: armature.unwrap_or_default(),
        damping: damping.unwrap_or_default(),
        frictionloss: frictionloss.unwrap_or_default(),
        stiffness: stiffness.unwrap_or_default(),
        springref: springref.unwrap_or_default(),
        joint: link.joint,
        range,
        offset: a
            .offset
            .clone()
            .filter(|o| *o != FixedAngle::zero())
            .map(|angle| {
                let (cos, sin) = angle.cos_sin();
                Offset { angle, cos, sin }
            }),
        reversed: a.reversed,
    })
}

/// `range = (lower, upper)`: two numbers (no run-time parameters: the bounds are documented and
/// shape the work-spaces), `lower < upper`.
fn check_range(cx: &Ctxt, name: &str, joint: JointKind, v: &Value) -> Option<(Rational, Rational)> {
    let unit = match joint {
        JointKind::Revolute => "radians",
        JointKind::Prismatic => "metres",
    };
    let (Some(lower), Some(upper)) = (
        v.value.as_rational(),
        v.y.as_ref().and_then(Poly::as_rational),
    ) else {
        cx.error_spanned_by(
            &v.tokens,
            format!(
                "link `{name}`: a range's bounds must be numbers ({unit}), not run-time parameters"
            ),
        );
        return None;
    };
    if !representable(cx, "range", v) {
        return None;
    }
    // As the f64 values the generated code and `Model::check` compare: `(1/3, 1/3 + 1e-30)` is
    // an empty range there.
    if to_f64(&lower) >= to_f64(&upper) {
        cx.error_spanned_by(
            &v.tokens,
            format!(
                "link `{name}`: a range needs lower < upper as f64 values ({unit}), found ({}, {})",
                show_f64(&lower),
                show_f64(&upper)
            ),
        );
        return None;
    }
    Some((lower, upper))
}

fn show_f64(r: &Rational) -> String {
    to_f64(r).map_or_else(|| r.to_string(), |x| format!("{x}"))
}
