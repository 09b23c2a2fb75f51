//! The geometric subproblems closed-form inverse kinematics reduces to (Paden and Kahan's, in
//! Murray, Li and Sastry's *A Mathematical Introduction to Robotic Manipulation*, 1994): a
//! rotation about a known axis taking one vector to another, two rotations about intersecting
//! axes, and `a cos t + b sin t = c`.

#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use nalgebra::Vector3;

/// `R(axis, angle) v` by Rodrigues' formula (`axis` a unit vector).
#[must_use]
pub(crate) fn rotate(axis: &Vector3<f64>, angle: f64, v: &Vector3<f64>) -> Vector3<f64> {
    let (s, c) = angle.sin_cos();
    v * c + axis.cross(v) * s + axis * (axis.dot(v) * (1.0 - c))
}

/// The angle about `axis` that turns `from` to `to` as nearly as their components across the
/// axis allow: `atan2(axis . (u x v), u . v)` of those components. 0 when either has none.
#[must_use]
pub(crate) fn angle_about(axis: &Vector3<f64>, from: &Vector3<f64>, to: &Vector3<f64>) -> f64 {
    let u = from - axis * axis.dot(from);
    let v = to - axis * axis.dot(to);
    axis.dot(&u.cross(&v)).atan2(u.dot(&v))
}

/// How `a cos t + b sin t = c` is solved.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Trig {
    /// Both solutions (equal on the boundary, `|c| = hypot(a, b)` up to `slack`).
    Two([f64; 2]),
    /// `a = b = 0 = c`: any `t`.
    Any,
    /// No solution: `|c|` exceeds `hypot(a, b)` by this much (beyond `slack`).
    None(f64),
}

/// Solves `a cos t + b sin t = c`; `|c|` up to `slack` beyond `hypot(a, b)` counts as on the
/// boundary.
#[must_use]
pub(crate) fn cos_sin(a: f64, b: f64, c: f64, slack: f64) -> Trig {
    let r = a.hypot(b);
    if r <= slack {
        return if c.abs() <= slack {
            Trig::Any
        } else {
            Trig::None(c.abs() - r)
        };
    }
    if c.abs() > r + slack {
        return Trig::None(c.abs() - r);
    }
    let phi = b.atan2(a);
    let delta = (c / r).clamp(-1.0, 1.0).acos();
    Trig::Two([phi + delta, phi - delta])
}

/// The intermediate vectors `z` of two rotations about axes `w1`, `w2` through the origin
/// (unit, not parallel) with `R(w1, t1) R(w2, t2) p = q`: `z = R(w2, t2) p = R(w1, -t1) q`
/// keeps `w2 . z = w2 . p` and `w1 . z = w1 . q` and `|z| = |p|`. Two, one (on the boundary,
/// within `slack` of `|p|^2`) or none (`Err` with how far `|z|^2` would fall short).
pub(crate) fn two_axes(
    w1: &Vector3<f64>,
    w2: &Vector3<f64>,
    p: &Vector3<f64>,
    q: &Vector3<f64>,
    slack: f64,
) -> Result<[Vector3<f64>; 2], f64> {
    let cross = w1.cross(w2);
    let k = w1.dot(w2);
    let (a, b) = (w1.dot(q), w2.dot(p));
    let denominator = k * k - 1.0;
    let alpha = (k * b - a) / denominator;
    let beta = (k * a - b) / denominator;
    // |z|^2 - |alpha w1 + beta w2|^2 over |w1 x w2|^2, written so that nothing cancels where
    // it is near zero (a wrist singularity): with a = w1 . q, b = w2 . p and s = |w1 x q| (so
    // |q|^2 = a^2 + s^2, and |z| = |q|), it is (s^2 (1 - k^2) - (a k - b)^2) / (1 - k^2)^2.
    // The plain difference leaves rounding of order eps in gamma^2, sqrt(eps) in gamma: a
    // singular wrist would come back 1.5e-8 rad off its axis.
    let s = w1.cross(q).norm();
    let sin2 = cross.norm_squared();
    let (m, root) = ((a * k - b).abs(), sin2.sqrt());
    let gamma2 = (s * root - m) * (s * root + m) / (sin2 * sin2);
    if gamma2 < -slack {
        return Err(-gamma2);
    }
    let gamma = gamma2.max(0.0).sqrt();
    let base = w1 * alpha + w2 * beta;
    Ok([base + cross * gamma, base - cross * gamma])
}
