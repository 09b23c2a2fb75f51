//! Physical validation, apart from attribute parsing: what a well-formed attribute can still
//! get wrong. Produces the engine's exact [`ArmSpec`].

use num_traits::{Signed, Zero};
use planar_arm_core::ring::{parse_decimal, ratio, to_f64, Rational};
use planar_arm_core::{ArmSpec, LinkSpec};

use crate::ast::{Arm, Link};
use crate::attr::{Value, COM, INERTIA, LENGTH, MASS};
use crate::ctxt::Ctxt;

/// Standard gravity, 9.80665 m/s^2, exactly.
fn standard_gravity() -> Rational {
    parse_decimal("9.80665").unwrap_or_else(|| ratio(980_665, 100_000))
}

/// Rejects values outside the finite range of `f64`, and non-zero values that round to zero.
fn representable(cx: &Ctxt, what: &str, v: &Value) -> bool {
    match to_f64(&v.value) {
        None => {
            cx.error_spanned_by(
                &v.tokens,
                format!("{what} is too large for f64; use a value below 1e308"),
            );
            false
        }
        Some(x) if x == 0.0 && !v.value.is_zero() => {
            cx.error_spanned_by(
                &v.tokens,
                format!(
                    "{what} is too small for f64 (it rounds to zero); use a value above 1e-308"
                ),
            );
            false
        }
        Some(_) => true,
    }
}

/// Validates the parsed arm; `None` after recording errors in `cx`.
pub fn check(cx: &Ctxt, arm: &Arm<'_>) -> Option<ArmSpec> {
    let mut ok = true;
    let gravity = match &arm.gravity {
        Some(g) => {
            // #[arm(gravity = 9.81)]
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
        match check_link(cx, link) {
            Some(spec) => links.push(spec),
            None => ok = false,
        }
    }
    (ok && links.len() == arm.links.len()).then_some(ArmSpec { links, gravity })
}

/// Validates one link: every problem is reported, not only the first.
fn check_link(cx: &Ctxt, link: &Link<'_>) -> Option<LinkSpec> {
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

    // #[arm(length = 0.5)], #[arm(mass = 2)]: positive.
    let mut positive = |key: &str| -> Option<Rational> {
        let v = a.get(key)?;
        let mut good = representable(cx, key, v);
        if !v.value.is_positive() {
            cx.error_spanned_by(
                &v.tokens,
                format!("link `{name}`: {key} must be positive, for example `{key} = 0.5`"),
            );
            good = false;
        }
        ok &= good;
        good.then(|| v.value.clone())
    };
    let length = positive(LENGTH);
    let mass = positive(MASS);

    // #[arm(inertia = 0.02)]: about the centre of mass, not negative.
    let inertia = a.get(INERTIA).and_then(|i| {
        let mut good = representable(cx, "inertia", i);
        if i.value.is_negative() {
            cx.error_spanned_by(
                &i.tokens,
                format!("link `{name}`: inertia about the centre of mass cannot be negative; use 0 for a point mass"),
            );
            good = false;
        }
        ok &= good;
        good.then(|| i.value.clone())
    });
    // #[arm(com = 0.25)]: any sign (a counterweight lies behind the joint).
    let com = a.get(COM).and_then(|c| {
        let good = representable(cx, "com", c);
        ok &= good;
        good.then(|| c.value.clone())
    });
    if !ok {
        return None;
    }
    let rod = LinkSpec::rod(length?, mass?);
    let inertia = inertia.unwrap_or(rod.inertia);
    let com = com.unwrap_or(rod.com);
    if inertia.is_zero() && com.is_zero() {
        // Joint k then moves none of link k's mass: with nothing after it (or nothing after it
        // that resists) M is singular and forward dynamics undefined. Both keys are explicit
        // here, since a positive rod's defaults are positive.
        let tokens = a
            .get(INERTIA)
            .or_else(|| a.get(COM))
            .map_or_else(|| a.tokens.clone(), |v| v.tokens.clone());
        cx.error_spanned_by(
            tokens,
            format!(
                "link `{name}`: zero inertia with `com = 0` puts the link's mass on its joint axis, \
                 which can make the mass matrix singular; give it a positive inertia or a non-zero `com`"
            ),
        );
        return None;
    }
    Some(LinkSpec {
        length: rod.length,
        mass: rod.mass,
        inertia,
        com,
    })
}
