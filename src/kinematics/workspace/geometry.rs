//! The geometry behind a [`Workspace`]'s answers: how far outside a region a point lies, and
//! the area of each region.
//!
//! Kept apart from the region type because the areas are integrals whose derivations the
//! comments carry; the methods that dispatch on the region do not need them to be read.

use core::f64::consts::{FRAC_PI_2, PI, TAU};
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

#[cfg(doc)]
use super::{Region, Workspace};
use crate::kinematics::range::Range;

/// The distance of an [`ArmError::Unreachable`], else (never, for the callers) infinity.
pub(super) fn unreachable_distance(error: Option<crate::ArmError>) -> f64 {
    match error {
        Some(crate::ArmError::Unreachable { distance, .. }) => distance,
        _ => f64::INFINITY,
    }
}

/// An area whose terms overflowed (`inf - inf`) is beyond `f64::MAX`: infinity, not NaN.
pub(super) fn overflowed(area: f64) -> f64 {
    if area.is_nan() {
        f64::INFINITY
    } else {
        area.max(0.0)
    }
}

/// `annulus_check` as a bool, with the given slack.
pub(super) fn annulus_check_slack(radius: f64, inner: f64, outer: f64, slack: f64) -> bool {
    (radius - outer).max(inner - radius) <= slack
}

/// `pi (outer^2 - inner^2)`, 0 for a circle (also when the sum of the radii overflows).
pub(super) fn annulus_area(inner: f64, outer: f64) -> f64 {
    if outer > inner {
        PI * (outer - inner) * (outer + inner)
    } else {
        0.0
    }
}

/// The area of [`Region::Swept`]: at height `y` the points are the carriage segment widened
/// by `[-ho, -hi]` and `[hi, ho]` (`ho = sqrt(outer^2 - y^2)`, `hi = sqrt(inner^2 - y^2)` or
/// 0), two intervals of length `L + ho - hi` (`L = to - from`) that overlap by
/// `max(0, L - 2 hi)`. Integrated over `y`:
/// `pi (outer^2 - inner^2) + 4 L outer - 2 L (outer - inner) - K(L, inner)`, with
/// `K(L, r) = integral of max(0, L - 2 sqrt(r^2 - y^2)) over |y| <= r`.
pub(super) fn swept_area(from: f64, to: f64, inner: f64, outer: f64) -> f64 {
    let length = to - from;
    if length == 0.0 {
        return annulus_area(inner, outer);
    }
    if outer == 0.0 {
        return 0.0;
    }
    if length.is_infinite() {
        return f64::INFINITY;
    }
    annulus_area(inner, outer) + 4.0 * length * outer
        - 2.0 * length * (outer - inner)
        - overlap_integral(length, inner)
}

/// `K(L, r)`, the integral of `max(0, L - 2 sqrt(r^2 - y^2))` over `|y| <= r`: with
/// `sin a = L / 2r`, the integrand is positive for `|y| > r cos a`, and
/// `K = 2 L r (1 - cos a) - 2 r^2 (a - sin a cos a)` (`2 L r - pi r^2` once `L >= 2 r`).
fn overlap_integral(length: f64, r: f64) -> f64 {
    if r == 0.0 {
        return 0.0;
    }
    if length >= 2.0 * r {
        return 2.0 * length * r - PI * r * r;
    }
    let s = length / (2.0 * r);
    let a = s.asin();
    let c = (1.0 - s) * (1.0 + s);
    let c = c.sqrt();
    // 1 - cos a = s^2 / (1 + cos a), without cancellation for small L.
    2.0 * length * r * (s * s / (1.0 + c)) - 2.0 * r * r * (a - s * c)
}

/// The sub-intervals of `lo ..= hi` (`hi - lo <= 2 pi`) that the arc `range` covers, as angles
/// between `lo` and `hi`; none, one or two.
fn clip(range: Range, lo: f64, hi: f64) -> [Option<(f64, f64)>; 2] {
    let Some((a, b)) = range else {
        return [Some((lo, hi)), None];
    };
    if b - a >= TAU {
        return [Some((lo, hi)), None];
    }
    // The copy of the arc that starts in lo - 2 pi .. lo, and the next one.
    let start = a - TAU * ((a - lo) / TAU).floor() - TAU;
    let width = b - a;
    let part = |s: f64| {
        let (p, q) = (s.max(lo), (s + width).min(hi));
        (p <= q).then_some((p, q))
    };
    [part(start), part(start + TAU)]
}

/// The area of the polar arm's region: `s (cos t, sin t)` with `s` in `reach + range2` and
/// `t` in `range1`. The part with `s >= 0` is a sector of width `w` between the radii of the
/// positive slides, the part with `s <= 0` the opposite sector between those of the negative
/// ones; they overlap between the common radii over `2 max(0, w - pi)` of angle.
pub(super) fn polar_area(reach: f64, range1: Range, range2: Range) -> f64 {
    let width = range1.map_or(TAU, |(lo, hi)| (hi - lo).min(TAU));
    let (from, to) = range2.map_or((f64::NEG_INFINITY, f64::INFINITY), |(lo, hi)| {
        (reach + lo, reach + hi)
    });
    if width == 0.0 || from == to {
        return 0.0;
    }
    if from.is_infinite() || to.is_infinite() {
        return f64::INFINITY;
    }
    let ring = |r1: f64, r2: f64| {
        if r2 > r1 {
            (r2 - r1) * (r2 + r1) / 2.0
        } else {
            0.0
        }
    };
    let positive = (to >= 0.0).then(|| (from.max(0.0), to));
    let negative = (from <= 0.0).then(|| ((-to).max(0.0), -from));
    let sector = |piece: Option<(f64, f64)>| piece.map_or(0.0, |(r1, r2)| width * ring(r1, r2));
    let overlap = match (positive, negative) {
        (Some((a1, a2)), Some((b1, b2))) => {
            2.0 * (width - PI).max(0.0) * ring(a1.max(b1), a2.min(b2))
        }
        _ => 0.0,
    };
    sector(positive) + sector(negative) - overlap
}

/// The area of the slider's region: `(c + r cos t, r sin t)` for `c` in `l1 + range1`, `t`
/// in `range2` (turned by pi for a negative `l2`), `r = |l2|`. At the height `y = r sin t`
/// (`|t| <= pi / 2`) the link pointing forward (angle `t`, if allowed) covers the segment
/// shifted by `r cos t`, the one pointing back (angle `pi - t`) the segment shifted by
/// `-r cos t`; each has the segment's length `L`, and they overlap by `max(0, L - 2 r cos t)`.
/// With `dy = r cos t dt`, the area is the integral over the allowed `t` of
/// `L r cos t` for each direction, less `r cos t max(0, L - 2 r cos t)` where both are.
pub(super) fn slider_area(l2: f64, range1: Range, range2: Range) -> f64 {
    let r = l2.abs();
    let length = range1.map_or(f64::INFINITY, |(lo, hi)| hi - lo);
    if r == 0.0 || length == 0.0 {
        return 0.0;
    }
    let turn = if l2 < 0.0 { PI } else { 0.0 };
    let forward = range2.map(|(lo, hi)| (lo + turn, hi + turn));
    // t such that pi - t is allowed: the arc reflected.
    let backward = range2.map(|(lo, hi)| (PI - hi - turn, PI - lo - turn));
    let (lo, hi) = (-FRAC_PI_2, FRAC_PI_2);
    let sines = |parts: [Option<(f64, f64)>; 2]| -> f64 {
        parts
            .iter()
            .flatten()
            .map(|(a, b)| r * (b.sin() - a.sin()))
            .sum()
    };
    let ahead = clip(forward, lo, hi);
    let behind = clip(backward, lo, hi);
    let covered = sines(ahead) + sines(behind);
    if length.is_infinite() {
        return if covered > 0.0 { f64::INFINITY } else { 0.0 };
    }
    // Where both directions are allowed, the overlap's integral: positive where
    // cos t < L / 2r, that is |t| > t0.
    let t0 = (length / (2.0 * r)).min(1.0).acos();
    let antiderivative = |t: f64| length * r * t.sin() - r * r * (t + t.sin() * t.cos());
    let mut overlap = 0.0;
    for (a, b) in ahead.iter().flatten() {
        for (c, d) in clip(backward, *a, *b).iter().flatten() {
            for (p, q) in [(c.max(lo), d.min(-t0)), (c.max(t0), d.min(hi))] {
                if p < q {
                    overlap += antiderivative(q) - antiderivative(p);
                }
            }
        }
    }
    length * covered - overlap
}
