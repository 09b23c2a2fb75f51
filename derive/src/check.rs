//! Physical validation, apart from attribute parsing: what a well-formed attribute can still
//! get wrong. Produces the engine's exact [`ArmSpec`].

use num_traits::{Signed, Zero};
use planar_arm_core::ring::{parse_decimal, ratio, show, to_f64, Rational};
use planar_arm_core::{ArmSpec, LinkSpec};

use crate::ast::Arm;
use crate::attr::{Value, COM, INERTIA, LENGTH, MASS};
use crate::ctxt::Ctxt;

/// Standard gravity, 9.80665 m/s^2, exactly.
fn standard_gravity() -> Rational {
    parse_decimal("9.80665").unwrap_or_else(|| ratio(980_665, 100_000))
}

/// Rejects values that are not finite, non-zero `f64`s when they are non-zero exactly.
fn representable(cx: &Ctxt, what: &str, v: &Value) -> bool {
    match to_f64(&v.value) {
        None => {
            cx.error_spanned_by(
                &v.tokens,
                format!("{what} {} is too large for f64", short(&v.value)),
            );
            false
        }
        Some(x) if x == 0.0 && !v.value.is_zero() => {
            cx.error_spanned_by(
                &v.tokens,
                format!("{what} is too small for f64 (it rounds to zero)"),
            );
            false
        }
        Some(_) => true,
    }
}

fn short(r: &Rational) -> String {
    let s = show(r);
    if s.len() > 40 {
        format!("{}...", &s[..40])
    } else {
        s
    }
}

/// Validates the parsed arm; `None` after recording errors in `cx`.
pub fn check(cx: &Ctxt, arm: &Arm<'_>) -> Option<ArmSpec> {
    let mut ok = true;
    let gravity = match &arm.gravity {
        Some(g) => {
            if g.value.is_negative() {
                cx.error_spanned_by(
                    &g.tokens,
                    "gravity is a magnitude along -y and cannot be negative; use 0 for a horizontal arm",
                );
                ok = false;
            }
            ok &= representable(cx, "gravity", g);
            g.value.clone()
        }
        None => standard_gravity(),
    };
    let mut links = Vec::new();
    for link in &arm.links {
        let name = link.name();
        let a = &link.attrs;
        let required = |key: &str| -> Option<&Value> {
            let v = a.get(key);
            if v.is_none() {
                cx.error_spanned_by(
                    &link.field.ident,
                    format!(
                        "link `{name}` is missing `{key}`: add `{key} = ...` to its #[arm(...)]"
                    ),
                );
            }
            v
        };
        let (Some(length), Some(mass)) = (required(LENGTH), required(MASS)) else {
            ok = false;
            continue;
        };
        if !length.value.is_positive() {
            cx.error_spanned_by(
                &length.tokens,
                format!("link `{name}`: length must be positive"),
            );
            ok = false;
        }
        if !mass.value.is_positive() {
            cx.error_spanned_by(
                &mass.tokens,
                format!("link `{name}`: mass must be positive"),
            );
            ok = false;
        }
        ok &= representable(cx, "length", length) & representable(cx, "mass", mass);
        let rod = LinkSpec::rod(length.value.clone(), mass.value.clone());
        let inertia = match a.get(INERTIA) {
            Some(i) => {
                if i.value.is_negative() {
                    cx.error_spanned_by(
                        &i.tokens,
                        format!(
                            "link `{name}`: inertia about the centre of mass cannot be negative"
                        ),
                    );
                    ok = false;
                }
                ok &= representable(cx, "inertia", i);
                i.value.clone()
            }
            None => rod.inertia.clone(),
        };
        let com = match a.get(COM) {
            Some(c) => {
                ok &= representable(cx, "com", c);
                c.value.clone()
            }
            None => rod.com.clone(),
        };
        if inertia.is_zero() && com.is_zero() {
            // A point mass on the joint axis adds nothing to that joint's inertia, so M would
            // be singular and forward dynamics undefined.
            let tokens = a
                .get(INERTIA)
                .map_or_else(|| quote::quote!(), |v| v.tokens.clone());
            cx.error_spanned_by(
                tokens,
                format!(
                    "link `{name}`: zero inertia with the centre of mass on the joint makes the mass matrix singular; \
                     give it a positive inertia or move `com` off the joint"
                ),
            );
            ok = false;
        }
        links.push(LinkSpec {
            length: length.value.clone(),
            mass: mass.value.clone(),
            inertia,
            com,
        });
    }
    (ok && links.len() == arm.links.len()).then_some(ArmSpec { links, gravity })
}
