//! The geometric subproblems closed-form inverse kinematics reduces to (Paden and Kahan's, in
//! Murray, Li and Sastry's *A Mathematical Introduction to Robotic Manipulation*, 1994): a
//! rotation about a known axis taking one vector to another, two rotations about intersecting
//! axes, and `a cos t + b sin t = c`.
//!
//! Angles travel as [`Turn`]s, their cosine and sine: each stage rotates vectors by the angles
//! the stages before it found, and with the pair at hand that costs a few multiplications
//! where the angle would cost a `sin_cos` (10 ns, as much as 40 of them). The angle itself is
//! read once, by one `atan2`, where it becomes a joint value.

#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use nalgebra::Vector3;

use super::atan2::atan2;

/// A rotation angle as its cosine and sine, `c^2 + s^2 = 1` to rounding.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Turn {
    pub c: f64,
    pub s: f64,
}

impl Turn {
    /// The zero angle.
    pub const ZERO: Self = Self { c: 1.0, s: 0.0 };

    /// The angle of the direction `(x, y)`; zero when both are zero, as `atan2(0, 0)` is.
    #[must_use]
    pub fn of(x: f64, y: f64) -> Self {
        let n = (x * x + y * y).sqrt();
        if n > 0.0 {
            let inv = 1.0 / n;
            Self {
                c: x * inv,
                s: y * inv,
            }
        } else {
            Self::ZERO
        }
    }

    /// `-t`.
    #[must_use]
    pub fn inverse(self) -> Self {
        Self {
            c: self.c,
            s: -self.s,
        }
    }

    /// `t + pi`: exact, which is what lets a wrist's second solution come from its first.
    #[must_use]
    pub fn opposite(self) -> Self {
        Self {
            c: -self.c,
            s: -self.s,
        }
    }

    /// `self + other`.
    #[must_use]
    pub fn then(self, other: Self) -> Self {
        Self {
            c: self.c * other.c - self.s * other.s,
            s: self.s * other.c + self.c * other.s,
        }
    }

    /// `R(axis, t) v` by Rodrigues' formula (`axis` a unit vector).
    #[must_use]
    pub fn rotate(self, axis: &Vector3<f64>, v: &Vector3<f64>) -> Vector3<f64> {
        v * self.c + axis.cross(v) * self.s + axis * (axis.dot(v) * (1.0 - self.c))
    }
}

/// The angle about `axis` that turns `from` to `to`, as `(cos, sin)` scaled by the product of
/// their lengths across the axis: `(u . v, axis . (u x v))` of those components. `atan2` of it
/// is the angle (0 when either has no component across), [`Turn::of`] the unit pair.
#[must_use]
pub(crate) fn about(axis: &Vector3<f64>, from: &Vector3<f64>, to: &Vector3<f64>) -> (f64, f64) {
    let u = from - axis * axis.dot(from);
    let v = to - axis * axis.dot(to);
    (u.dot(&v), axis.dot(&u.cross(&v)))
}

/// An angle found as a `(cos, sin)` direction: the joint value (one `atan2`) and the unit pair
/// the next stages rotate by.
pub(crate) fn angle_and_turn((x, y): (f64, f64)) -> (f64, Turn) {
    (atan2(y, x), Turn::of(x, y))
}

/// How `a cos t + b sin t = c` is solved.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Trig {
    /// Both solutions `phi +- delta` (equal on the boundary, `|c| = hypot(a, b)` up to
    /// `slack`).
    Two(Roots),
    /// `a = b = 0 = c`: any `t`.
    Any,
    /// No solution: `|c|` exceeds `hypot(a, b)` by this much (beyond `slack`).
    None(f64),
}

/// The solutions `phi +- delta` of `a cos t + b sin t = c`, with `phi = atan2(b, a)` and
/// `delta = acos(c / hypot(a, b))` in `[0, pi]`, both as turns.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Roots {
    pub phi: Turn,
    pub delta: Turn,
}

impl Roots {
    /// `[phi + delta, phi - delta]` as turns.
    #[must_use]
    pub fn turns(&self) -> [Turn; 2] {
        [
            self.phi.then(self.delta),
            self.phi.then(self.delta.inverse()),
        ]
    }

    /// `[phi + delta, phi - delta]` as angles, given `phi`'s: the callers whose `a` and `b` are
    /// constants read `phi` once per solve, so each pair costs one `atan2`.
    #[must_use]
    pub fn angles(&self, phi: f64) -> [f64; 2] {
        let delta = atan2(self.delta.s, self.delta.c);
        [phi + delta, phi - delta]
    }

    /// `phi`'s angle.
    #[must_use]
    pub fn phi(&self) -> f64 {
        atan2(self.phi.s, self.phi.c)
    }
}

/// Solves `a cos t + b sin t = c`; `|c|` up to `slack` beyond `hypot(a, b)` counts as on the
/// boundary.
#[must_use]
pub(crate) fn cos_sin(a: f64, b: f64, c: f64, slack: f64) -> Trig {
    // The callers' a, b and c are lengths (squared) of the arm or unit vectors' components,
    // far from overflow: no `hypot` needed.
    let r = (a * a + b * b).sqrt();
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
    let c = c.clamp(-r, r);
    // sin delta from (r - c)(r + c): exact differences where c is near +-r (the boundary),
    // where 1 - (c/r)^2 would lose the digits.
    let h = ((r - c) * (r + c)).sqrt();
    let inv = 1.0 / r;
    Trig::Two(Roots {
        phi: Turn {
            c: a * inv,
            s: b * inv,
        },
        delta: Turn {
            c: c * inv,
            s: h * inv,
        },
    })
}

/// Two rotations about axes `w1`, `w2` through the origin (unit, not parallel):
/// `R(w1, t1) R(w2, t2) p = q`. What depends on the axes alone is kept, for callers that solve
/// many of these with one pair of axes.
#[derive(Debug, Clone, Copy)]
pub(crate) struct AxisPair {
    w1: Vector3<f64>,
    w2: Vector3<f64>,
    cross: Vector3<f64>,
    k: f64,
    /// `|w1 x w2|`, and the reciprocals of `k^2 - 1` and of `|w1 x w2|^4`.
    root: f64,
    inv_denominator: f64,
    inv_sin4: f64,
}

impl AxisPair {
    pub fn new(w1: &Vector3<f64>, w2: &Vector3<f64>) -> Self {
        let cross = w1.cross(w2);
        let sin2 = cross.norm_squared();
        let k = w1.dot(w2);
        Self {
            w1: *w1,
            w2: *w2,
            cross,
            k,
            root: sin2.sqrt(),
            inv_denominator: 1.0 / (k * k - 1.0),
            inv_sin4: 1.0 / (sin2 * sin2),
        }
    }

    /// The intermediate vectors `z = R(w2, t2) p = R(w1, -t1) q`, given `b = w2 . p`: they keep
    /// `w2 . z = b` and `w1 . z = w1 . q` and `|z| = |q|` (`= |p|`). Two, one (on the boundary,
    /// within `slack` of `|q|^2`) or none (`Err` with how far `|z|^2` would fall short).
    pub fn meet(&self, b: f64, q: &Vector3<f64>, slack: f64) -> Result<[Vector3<f64>; 2], f64> {
        let (w1, w2, k) = (&self.w1, &self.w2, self.k);
        let a = w1.dot(q);
        let alpha = (k * b - a) * self.inv_denominator;
        let beta = (k * a - b) * self.inv_denominator;
        // |z|^2 - |alpha w1 + beta w2|^2 over |w1 x w2|^2, written so that nothing cancels
        // where it is near zero (a wrist singularity): with s = |w1 x q| (so |q|^2 = a^2 +
        // s^2), it is (s^2 (1 - k^2) - (a k - b)^2) / (1 - k^2)^2. The plain difference leaves
        // rounding of order eps in gamma^2, sqrt(eps) in gamma: a singular wrist would come
        // back 1.5e-8 rad off its axis.
        let s = w1.cross(q).norm();
        let m = (a * k - b).abs();
        let gamma2 = (s * self.root - m) * (s * self.root + m) * self.inv_sin4;
        if gamma2 < -slack {
            return Err(-gamma2);
        }
        let gamma = gamma2.max(0.0).sqrt();
        let base = w1 * alpha + w2 * beta;
        Ok([base + self.cross * gamma, base - self.cross * gamma])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn roots_solve_the_equation_and_agree_with_acos() {
        for (a, b, c) in [
            (1.0, 2.0, 0.5),
            (-0.3, 0.1, -0.2),
            (0.0, 1.0, 1.0),
            (2.0, 0.0, -2.0),
        ] {
            let Trig::Two(roots) = cos_sin(a, b, c, 1e-12) else {
                panic!("{a} {b} {c}");
            };
            let phi = f64::atan2(b, a);
            let delta = (c / f64::hypot(a, b)).clamp(-1.0, 1.0).acos();
            let angles = roots.angles(roots.phi());
            for (t, want) in angles.iter().zip([phi + delta, phi - delta]) {
                assert!((t - want).abs() < 1e-15, "{t} {want}");
                assert!((a * t.cos() + b * t.sin() - c).abs() < 1e-15);
            }
            for (turn, t) in roots.turns().iter().zip(angles) {
                assert!((turn.c - t.cos()).abs() < 1e-15 && (turn.s - t.sin()).abs() < 1e-15);
            }
        }
        assert_eq!(cos_sin(0.0, 0.0, 0.0, 1e-12), Trig::Any);
        assert_eq!(cos_sin(1.0, 0.0, 3.0, 1e-12), Trig::None(2.0));
    }

    #[test]
    fn turns_rotate_as_angles_do() {
        let axis = Vector3::new(1.0, 2.0, -2.0) / 3.0;
        let v = Vector3::new(0.3, -0.7, 0.2);
        let (t, u) = (0.7_f64, -2.9_f64);
        let turn = |a: f64| Turn {
            c: a.cos(),
            s: a.sin(),
        };
        let rotated = turn(t).then(turn(u)).rotate(&axis, &v);
        let twice = turn(u).rotate(&axis, &turn(t).rotate(&axis, &v));
        assert!((rotated - twice).norm() < 1e-15);
        let back = turn(t).inverse().rotate(&axis, &turn(t).rotate(&axis, &v));
        assert!((back - v).norm() < 1e-15);
        let (angle, unit) = angle_and_turn(about(&axis, &v, &rotated));
        assert!((angle - (t + u)).abs() < 1e-14, "{angle}");
        assert!((unit.then(turn(t + u).inverse()).s).abs() < 1e-15);
        assert_eq!(Turn::of(0.0, 0.0), Turn::ZERO);
    }
}
