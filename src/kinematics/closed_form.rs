//! Closed-form inverse kinematics of two and three links: both elbow branches.
//!
//! This file holds the closed forms over the whole annulus. Keeping the branches that fit joint
//! ranges is a separate step (`in_ranges`), the same fitting the prismatic closed forms use, so
//! that the formulas here stay as the paper has them.

use core::f64::consts::PI;
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use nalgebra::{Isometry2, Point2, SVector, Vector2};

#[cfg(doc)]
use super::REACH_TOLERANCE;
use super::{annulus_check, check_lengths, wrap_angle};
use crate::ArmError;

mod in_ranges;
mod position;
#[cfg(test)]
mod tests;

pub use in_ranges::{ik2_in_ranges, ik3_in_ranges};
pub use position::ik3_position;

/// Closed-form inverse kinematics of a two- or three-link arm, both solutions.
///
/// `#[derive(PlanarArm)]` implements it for two revolute links (`Target = Point2<f64>`, via
/// [`ik2`] or [`ik2_equal`]) and for three (`Target = Isometry2<f64>`, via [`ik3`]). The free
/// functions for joint ranges ([`ik2_in_ranges`], [`ik3_in_ranges`]) and for prismatic joints
/// ([`ik_rp`](super::ik_rp), [`ik_pr`](super::ik_pr) for a position,
/// [`ik_prr`](super::ik_prr) for a pose) have the same shape, for the arms they name.
pub trait ClosedFormIk<const N: usize> {
    /// `Point2<f64>` for two links, `Isometry2<f64>` for three.
    type Target;
    /// Both solutions, in the order the function behind it documents: for revolute links
    /// index 0 has `sin q2 >= 0`, index 1 has `sin q2 <= 0`. On the outer or inner boundary
    /// both are the same configuration, and when joint ranges leave one solution, both
    /// entries hold it.
    ///
    /// # Errors
    /// [`ArmError::NonFinite`] for NaN or infinite targets, [`ArmError::Unreachable`] for
    /// targets outside the work-space or its joint ranges.
    fn inverse_kinematics(&self, target: &Self::Target) -> Result<[SVector<f64, N>; 2], ArmError>;
}

/// The target's coordinates, with `-0.0` turned into `0.0` so that `atan2` never sees a
/// negative zero in the denominator.
#[inline]
pub(super) fn target_coordinates(target: &Point2<f64>) -> Result<(f64, f64), ArmError> {
    if target.x.is_finite() && target.y.is_finite() {
        Ok((target.x + 0.0, target.y + 0.0))
    } else {
        Err(ArmError::NonFinite { argument: "target" })
    }
}

/// Both two-link solutions `(q1, q2)` for lengths `a1, a2 >= 0` and a target known to lie in
/// the annulus (up to the tolerance): `q2` in `[0, pi]` first, then its mirror image.
#[inline]
fn ik2_unsigned(a1: f64, a2: f64, x: f64, y: f64) -> [(f64, f64); 2] {
    // Scale so the longer link has length 1: nothing below can overflow or underflow.
    let scale = a1.max(a2);
    if scale == 0.0 {
        return [(0.0, 0.0); 2];
    }
    let (l1, l2) = (a1 / scale, a2 / scale);
    let (x, y) = (x / scale, y / scale);
    if l1 == 0.0 || l2 == 0.0 {
        // One link has (numerically) no length: the other points at the target.
        let theta = y.atan2(x);
        return [(theta, 0.0); 2];
    }
    let r = x.hypot(y);
    let den = 2.0 * l1 * l2;
    let (outer, inner) = (l1 + l2, (l1 - l2).abs());
    // 1 - cos q2 and 1 + cos q2 in factored form: accurate near both boundaries, and clamped
    // so that a target within the tolerance outside the annulus lands on the boundary.
    let one_minus = ((outer - r) * (outer + r) / den).clamp(0.0, 2.0);
    let one_plus = ((r - inner) * (r + inner) / den).clamp(0.0, 2.0);
    let c2 = 0.5 * (one_plus - one_minus);
    let s2 = (one_minus * one_plus).sqrt();
    let q2 = s2.atan2(c2);
    // The paper's sin q1, cos q1 (times r^2) for each sign of sin q2.
    let (k1, k2) = (l1 + l2 * c2, l2 * s2);
    let up = (k1 * y - k2 * x).atan2(k1 * x + k2 * y);
    let down = (k1 * y + k2 * x).atan2(k1 * x - k2 * y);
    [(up, q2), (down, -q2)]
}

/// Turns the solutions for `|l1|, |l2|` into solutions for the signed lengths (a link of
/// negative length is the positive one turned by pi), keeps the branch order, and wraps.
#[inline]
fn ik2_signed(l1: f64, l2: f64, solutions: [(f64, f64); 2]) -> [SVector<f64, 2>; 2] {
    let (flip1, flip2) = (l1 < 0.0, l2 < 0.0);
    let shift1 = if flip1 { PI } else { 0.0 };
    let shift2 = if flip2 { PI } else { 0.0 };
    let convert = |(p1, p2): (f64, f64)| {
        Vector2::new(wrap_angle(p1 - shift1), wrap_angle(p2 + shift1 - shift2))
    };
    let [a, b] = solutions;
    if flip1 == flip2 {
        [convert(a), convert(b)]
    } else {
        [convert(b), convert(a)]
    }
}

/// Closed-form inverse kinematics of a two-link arm with lengths `l1`, `l2`: both elbow
/// solutions for the tip position `target`.
///
/// `cos q2` comes from the law of cosines, `q1` from `atan2` of the paper's expressions for
/// `sin q1` and `cos q1`. Index 0 has `sin q2 >= 0`, index 1 has `sin q2 <= 0`; on the inner or
/// outer boundary both are the same configuration. A target outside the annulus
/// `|l1 - l2| ..= l1 + l2` by at most [`REACH_TOLERANCE`]` * (l1 + l2)` is treated as lying on
/// the boundary. When `l1 == l2` the origin is reachable with `q2 = pi` and any `q1`; the
/// solution returned is `(0, pi)` for both branches. Angles are in (-pi, pi].
///
/// # Errors
/// [`ArmError::NonFinite`] (`"lengths"` or `"target"`) for NaN or infinite arguments;
/// [`ArmError::Unreachable`] with `radius = |target|`, `inner = |l1 - l2|`, `outer = l1 + l2`
/// and the distance outside the annulus.
///
/// # Example
/// ```
/// use planar_arm::kinematics::ik2;
/// use planar_arm::nalgebra::Point2;
///
/// let [elbow_up, elbow_down] = ik2(1.0, 0.5, &Point2::new(1.0, 0.5)).unwrap();
/// for q in [elbow_up, elbow_down] {
///     let x = q[0].cos() + 0.5 * (q[0] + q[1]).cos();
///     let y = q[0].sin() + 0.5 * (q[0] + q[1]).sin();
///     assert!((x - 1.0).abs() < 1e-12 && (y - 0.5).abs() < 1e-12);
/// }
/// assert!(elbow_up[1].sin() >= 0.0 && elbow_down[1].sin() <= 0.0);
/// ```
#[inline]
pub fn ik2(l1: f64, l2: f64, target: &Point2<f64>) -> Result<[SVector<f64, 2>; 2], ArmError> {
    check_lengths(&[l1, l2])?;
    let (x, y) = target_coordinates(target)?;
    let (a1, a2) = (l1.abs(), l2.abs());
    annulus_check(x.hypot(y), (a1 - a2).abs(), a1 + a2, [x, y])?;
    Ok(ik2_signed(l1, l2, ik2_unsigned(a1, a2, x, y)))
}

/// Closed-form inverse kinematics of a two-link arm whose links both have length `l`, by the
/// paper's simplified formulas `cos(q2 / 2) = r / (2 l)` and `q1 + q2 / 2 = atan2(y, x)`.
///
/// The work-space is the disk of radius `2 l`. The origin is reached in infinitely many ways
/// (`q2 = pi`, `q1` free); both branches then return `(0, pi)`. Otherwise as [`ik2`]: index 0
/// has `sin q2 >= 0`, angles are in (-pi, pi], and the boundary tolerance is
/// [`REACH_TOLERANCE`]` * 2 l`.
///
/// # Errors
/// [`ArmError::NonFinite`] for NaN or infinite arguments; [`ArmError::Unreachable`]
/// (`inner = 0`, `outer = 2 l`) beyond the disk.
///
/// # Example
/// ```
/// use planar_arm::kinematics::ik2_equal;
/// use planar_arm::nalgebra::Point2;
///
/// let [a, b] = ik2_equal(1.0, &Point2::origin()).unwrap();
/// assert_eq!(a, b);
/// assert_eq!(a[1], std::f64::consts::PI);
/// ```
#[inline]
pub fn ik2_equal(l: f64, target: &Point2<f64>) -> Result<[SVector<f64, 2>; 2], ArmError> {
    check_lengths(&[l])?;
    let (x, y) = target_coordinates(target)?;
    let a = l.abs();
    annulus_check(x.hypot(y), 0.0, 2.0 * a, [x, y])?;
    let solutions = if a == 0.0 {
        [(0.0, 0.0); 2]
    } else {
        let (x, y) = (x / a, y / a);
        let r = x.hypot(y);
        if r == 0.0 {
            [(0.0, PI); 2]
        } else {
            // q2 / 2 = acos(r / 2), computed as an atan2 that stays accurate near r = 2.
            let half = ((2.0 - r) * (2.0 + r)).max(0.0).sqrt().atan2(r);
            let theta = y.atan2(x);
            [(theta - half, 2.0 * half), (theta + half, -2.0 * half)]
        }
    };
    Ok(ik2_signed(l, l, solutions))
}

/// Closed-form inverse kinematics of a three-link arm: both solutions that put the tip at
/// `target.translation` with the last link at the absolute angle `phi = target.rotation`.
///
/// The wrist (joint 3) must be at `(x - l3 cos phi, y - l3 sin phi)`; the first two links reach
/// it by [`ik2_equal`] when `l1 == l2` and by [`ik2`] otherwise, and `q3 = phi - q1 - q2` (the
/// paper misprints this as `-q2 - q1`). Index 0 has `sin q2 >= 0`; angles are in (-pi, pi].
///
/// # Errors
/// [`ArmError::NonFinite`] for NaN or infinite arguments; [`ArmError::Unreachable`] when the
/// wrist point lies outside the two-link annulus, with `target` and `orientation` the pose
/// asked for, `radius` the wrist's distance from the base and `inner`, `outer` the two-link
/// radii.
///
/// # Example
/// ```
/// use planar_arm::kinematics::ik3;
/// use planar_arm::nalgebra::{Isometry2, Vector2};
///
/// let target = Isometry2::new(Vector2::new(1.2, 0.4), 0.3);
/// let [q, _] = ik3(1.0, 0.8, 0.2, &target).unwrap();
/// assert!((q[0] + q[1] + q[2] - 0.3).abs() < 1e-12);
/// ```
#[inline]
pub fn ik3(
    l1: f64,
    l2: f64,
    l3: f64,
    target: &Isometry2<f64>,
) -> Result<[SVector<f64, 3>; 2], ArmError> {
    check_lengths(&[l1, l2, l3])?;
    let t = target.translation.vector;
    let rotation = target.rotation.complex();
    if !(t.x.is_finite() && t.y.is_finite() && rotation.re.is_finite() && rotation.im.is_finite()) {
        return Err(ArmError::NonFinite { argument: "target" });
    }
    let phi = target.rotation.angle();
    let (s, c) = phi.sin_cos();
    let wrist = Point2::new(t.x - l3 * c, t.y - l3 * s);
    if !(wrist.x.is_finite() && wrist.y.is_finite()) {
        let (a1, a2) = (l1.abs(), l2.abs());
        return Err(ArmError::Unreachable {
            target: [t.x, t.y],
            orientation: Some(phi),
            radius: f64::INFINITY,
            inner: (a1 - a2).abs(),
            outer: a1 + a2,
            distance: f64::INFINITY,
        });
    }
    let solutions = if l1 == l2 {
        ik2_equal(l1, &wrist)
    } else {
        ik2(l1, l2, &wrist)
    };
    // The caller asked for the tip, not the wrist: name the tip pose in the error.
    let solutions = solutions.map_err(|e| match e {
        ArmError::Unreachable {
            radius,
            inner,
            outer,
            distance,
            ..
        } => ArmError::Unreachable {
            target: [t.x, t.y],
            orientation: Some(phi),
            radius,
            inner,
            outer,
            distance,
        },
        other => other,
    })?;
    Ok(solutions.map(|q| SVector::<f64, 3>::new(q[0], q[1], wrap_angle(phi - q[0] - q[1]))))
}
