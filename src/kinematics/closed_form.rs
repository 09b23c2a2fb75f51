//! Closed-form inverse kinematics of two and three links: both elbow branches.

use core::f64::consts::PI;
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use nalgebra::{Isometry2, Point2, SVector, Vector2};

use super::prismatic::excluded;
use super::range::{check_ranges, fit_branches, Range};
#[cfg(doc)]
use super::REACH_TOLERANCE;
use super::{annulus_check, check_lengths, wrap_angle};
use crate::{ArmError, Joint};

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

/// [`ik2`] within joint ranges: the elbow solutions whose angles lie in `ranges` (radians,
/// `None` for a free joint, an infinite bound no bound), for an arm whose joints have limits
/// (a derived arm's [`Link::range`](crate::Link::range)).
///
/// An angle satisfies a range when some `q + 2 pi k` lies in it, and that representative is
/// returned: the angle in (-pi, pi] when it lies in the range, else the representative nearest
/// the side of the range it lies beyond. Angles within [`REACH_TOLERANCE`] radians of a range
/// are clamped onto it. The branch order is [`ik2`]'s (index 0 has `sin q2 >= 0`); when only one
/// branch lies within the ranges, both entries hold it.
///
/// # Errors
/// As [`ik2`], and: [`ArmError::NonFinite`] (`"ranges"`) for a NaN bound,
/// [`ArmError::OutOfRange`] (`"range"`, the 0-based joint) for `lower > upper`,
/// [`ArmError::Unreachable`] for a target in the annulus that neither branch reaches within the
/// ranges, with `radius`, `inner` and `outer` as [`ik2`]'s and `distance` how far the nearer
/// branch's angle lies outside its range (radians; the branch's larger excess, the smaller over
/// the branches).
///
/// # Example
/// ```
/// use planar_arm::kinematics::{ik2, ik2_in_ranges};
/// use planar_arm::nalgebra::Point2;
///
/// let target = Point2::new(1.0, 0.5);
/// let [up, down] = ik2(1.0, 0.5, &target).unwrap();
/// // An elbow that bends one way only keeps one branch, in both entries.
/// let bent = [None, Some((0.0, std::f64::consts::PI))];
/// assert_eq!(ik2_in_ranges(1.0, 0.5, bent, &target).unwrap(), [up, up]);
/// let other = [None, Some((-std::f64::consts::PI, 0.0))];
/// assert_eq!(ik2_in_ranges(1.0, 0.5, other, &target).unwrap(), [down, down]);
/// ```
#[inline]
pub fn ik2_in_ranges(
    l1: f64,
    l2: f64,
    ranges: [Option<(f64, f64)>; 2],
    target: &Point2<f64>,
) -> Result<[SVector<f64, 2>; 2], ArmError> {
    check_ranges(&ranges)?;
    let solutions = ik2(l1, l2, target)?;
    let (x, y) = target_coordinates(target)?;
    let (a1, a2) = (l1.abs(), l2.abs());
    let radii = ((a1 - a2).abs(), a1 + a2);
    fit_revolute(solutions, &ranges)
        .map_err(|excess| excluded([x, y], None, x.hypot(y), radii, excess))
}

/// [`ik3`] within joint ranges, as [`ik2_in_ranges`] is [`ik2`] within them: the solutions
/// whose three angles lie in `ranges` (representatives, tolerance and branch order as there).
///
/// # Errors
/// As [`ik3`] and [`ik2_in_ranges`]: [`ArmError::Unreachable`] for a pose whose wrist lies in
/// the two-link annulus but that neither branch reaches within the ranges, with `target`,
/// `orientation`, `radius` (the wrist's), `inner` and `outer` as [`ik3`]'s and `distance` how
/// far the nearer branch's angle lies outside its range (radians).
///
/// # Example
/// ```
/// use planar_arm::kinematics::ik3_in_ranges;
/// use planar_arm::nalgebra::{Isometry2, Vector2};
///
/// let target = Isometry2::new(Vector2::new(1.2, 0.4), 0.3);
/// let wrist_up = [None, Some((0.0, 3.2)), Some((-4.0, 4.0))];
/// let [q, same] = ik3_in_ranges(1.0, 0.8, 0.2, wrist_up, &target).unwrap();
/// assert_eq!(q, same);
/// assert!(q[1] >= 0.0 && (q[0] + q[1] + q[2] - 0.3).abs() < 1e-12);
/// ```
#[inline]
pub fn ik3_in_ranges(
    l1: f64,
    l2: f64,
    l3: f64,
    ranges: [Option<(f64, f64)>; 3],
    target: &Isometry2<f64>,
) -> Result<[SVector<f64, 3>; 2], ArmError> {
    check_ranges(&ranges)?;
    let solutions = ik3(l1, l2, l3, target)?;
    let t = target.translation.vector;
    let phi = target.rotation.angle();
    let wrist = t - Vector2::new(phi.cos(), phi.sin()) * l3;
    let (a1, a2) = (l1.abs(), l2.abs());
    let radii = ((a1 - a2).abs(), a1 + a2);
    fit_revolute(solutions, &ranges)
        .map_err(|excess| excluded([t.x, t.y], Some(phi), wrist.norm(), radii, excess))
}

/// The branches of an all-revolute closed form that fit `ranges`, or the smallest excess.
fn fit_revolute<const N: usize>(
    solutions: [SVector<f64, N>; 2],
    ranges: &[Range; N],
) -> Result<[SVector<f64, N>; 2], f64> {
    let branches = solutions.map(|q| core::array::from_fn(|i| q[i]));
    fit_branches(&[Joint::Revolute; N], ranges, 0.0, branches).map(|b| b.map(SVector::from))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::test_support::{angle_gap, fk, in_range, pose_of, Rng, PAIRS, TRIPLES};
    use crate::kinematics::REACH_TOLERANCE;
    use core::f64::consts::TAU;
    use nalgebra::Vector3;
    use proptest::prelude::*;

    fn check_two_link_solutions(l1: f64, l2: f64, target: Point2<f64>, q: &[SVector<f64, 2>; 2]) {
        let scale = l1.abs() + l2.abs();
        for (branch, qb) in q.iter().enumerate() {
            let (x, y, _) = fk(&[l1, l2], qb.as_slice());
            assert!(
                (x - target.x).hypot(y - target.y) <= 1e-12 * scale,
                "l = ({l1}, {l2}), target {target}, branch {branch}: reached ({x}, {y})"
            );
            assert!(qb.iter().all(|a| in_range(*a)), "{qb} not in (-pi, pi]");
            let s2 = qb[1].sin();
            if branch == 0 {
                assert!(s2 >= -1e-15, "branch 0 has sin q2 = {s2}");
            } else {
                assert!(s2 <= 1e-15, "branch 1 has sin q2 = {s2}");
            }
        }
    }

    #[test]
    fn ik2_round_trip_over_dense_workspace() {
        for (l1, l2) in PAIRS {
            let (inner, outer) = ((l1 - l2).abs(), l1 + l2);
            for i in 0..=48 {
                let r = inner + (outer - inner) * f64::from(i) / 48.0;
                for j in 0..72 {
                    let theta = f64::from(j) * TAU / 72.0;
                    let target = Point2::new(r * theta.cos(), r * theta.sin());
                    let q = ik2(l1, l2, &target).unwrap();
                    check_two_link_solutions(l1, l2, target, &q);
                    if l1 == l2 {
                        let qe = ik2_equal(l1, &target).unwrap();
                        check_two_link_solutions(l1, l2, target, &qe);
                        for (a, b) in q.iter().zip(&qe) {
                            assert!(angle_gap(a[0], b[0]) < 1e-6 && angle_gap(a[1], b[1]) < 1e-6);
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn ik2_recovers_sampled_configurations() {
        let mut rng = Rng(1);
        for (l1, l2) in PAIRS {
            for _ in 0..2000 {
                let q = Vector2::new(rng.angle(), rng.angle());
                if q[1].sin().abs() < 1e-3 {
                    continue;
                }
                let (x, y, _) = fk(&[l1, l2], q.as_slice());
                let target = Point2::new(x, y);
                let solutions = ik2(l1, l2, &target).unwrap();
                check_two_link_solutions(l1, l2, target, &solutions);
                let same = &solutions[usize::from(q[1].sin() < 0.0)];
                assert!(
                    angle_gap(same[0], q[0]) < 1e-8 && angle_gap(same[1], q[1]) < 1e-8,
                    "l = ({l1}, {l2}): {q} came back as {same}"
                );
            }
        }
    }

    #[test]
    fn signed_and_zero_lengths() {
        let mut rng = Rng(2);
        for (l1, l2) in [(-1.0, 0.5), (1.0, -0.5), (-0.7, -1.3), (-1.0, -1.0)] {
            for _ in 0..500 {
                let q = Vector2::new(rng.angle(), rng.angle());
                let (x, y, _) = fk(&[l1, l2], q.as_slice());
                let target = Point2::new(x, y);
                check_two_link_solutions(l1, l2, target, &ik2(l1, l2, &target).unwrap());
                if l1 == l2 {
                    check_two_link_solutions(l1, l2, target, &ik2_equal(l1, &target).unwrap());
                }
            }
        }
        // One link of length zero: the work-space is a circle.
        let on_circle = Point2::new(0.6, 0.8);
        check_two_link_solutions(0.0, 1.0, on_circle, &ik2(0.0, 1.0, &on_circle).unwrap());
        check_two_link_solutions(1.0, 0.0, on_circle, &ik2(1.0, 0.0, &on_circle).unwrap());
        assert!(ik2(0.0, 1.0, &Point2::new(0.5, 0.0)).is_err());
        // Both zero: only the origin.
        assert_eq!(
            ik2(0.0, 0.0, &Point2::origin()).unwrap(),
            [Vector2::zeros(); 2]
        );
        assert!(ik2_equal(0.0, &Point2::new(1e-300, 0.0)).is_err());
    }

    #[test]
    fn boundary_targets_give_one_configuration() {
        for (l1, l2) in PAIRS {
            let (inner, outer) = ((l1 - l2).abs(), l1 + l2);
            for j in 0..36 {
                let (s, c) = (f64::from(j) * TAU / 36.0).sin_cos();
                // On the outer circle: stretched, q2 = 0.
                let [a, b] = ik2(l1, l2, &Point2::new(outer * c, outer * s)).unwrap();
                assert!(
                    a[1].abs() < 1e-6
                        && angle_gap(a[0], b[0]) < 1e-6
                        && angle_gap(a[1], b[1]) < 1e-6
                );
                // Just outside, within the tolerance: clamped onto the circle, identical branches.
                let out = outer * (1.0 + 0.5 * REACH_TOLERANCE);
                let [a, b] = ik2(l1, l2, &Point2::new(out * c, out * s)).unwrap();
                assert_eq!(a, b);
                assert_eq!(a[1], 0.0);
                // On the inner circle: folded, q2 = pi.
                if inner > 0.0 {
                    let [a, b] = ik2(l1, l2, &Point2::new(inner * c, inner * s)).unwrap();
                    assert!(angle_gap(a[1], PI) < 1e-6 && angle_gap(a[0], b[0]) < 1e-6);
                    let inside = inner - 0.25 * REACH_TOLERANCE * outer;
                    let [a, b] = ik2(l1, l2, &Point2::new(inside * c, inside * s)).unwrap();
                    assert_eq!(a, b);
                    assert_eq!(a[1], PI);
                }
            }
        }
    }

    #[test]
    fn unreachable_targets_report_the_distance() {
        for (l1, l2) in PAIRS {
            let (inner, outer) = ((l1 - l2).abs(), l1 + l2);
            for d in [3.0 * REACH_TOLERANCE, 1e-6, 0.1, 10.0] {
                let r = outer * (1.0 + d);
                match ik2(l1, l2, &Point2::new(0.0, -r)) {
                    Err(ArmError::Unreachable {
                        target,
                        orientation,
                        radius,
                        inner: i,
                        outer: o,
                        distance,
                    }) => {
                        assert_eq!((target, orientation), ([0.0, -r], None));
                        assert_eq!((radius, i, o), (r, inner, outer));
                        assert!((distance - (r - outer)).abs() <= 1e-15 * r && distance > 0.0);
                    }
                    other => panic!("expected Unreachable, got {other:?}"),
                }
                let r = inner - outer * d;
                if r > 0.0 {
                    match ik2(l1, l2, &Point2::new(-r, 0.0)) {
                        Err(ArmError::Unreachable { distance, .. }) => {
                            assert!((distance - outer * d).abs() <= 1e-12 * outer);
                        }
                        other => panic!("expected Unreachable, got {other:?}"),
                    }
                }
            }
            if l1 != l2 {
                assert_eq!(
                    ik2(l1, l2, &Point2::origin()),
                    Err(ArmError::Unreachable {
                        target: [0.0, 0.0],
                        orientation: None,
                        radius: 0.0,
                        inner,
                        outer,
                        distance: inner
                    })
                );
            }
        }
        assert!(matches!(
            ik2_equal(1.0, &Point2::new(3.0, 0.0)),
            Err(ArmError::Unreachable { distance, .. }) if distance == 1.0
        ));
    }

    #[test]
    fn origin_with_equal_links() {
        for l in [1.0, 0.25, 7.0] {
            let expected = [Vector2::new(0.0, PI); 2];
            for origin in [Point2::origin(), Point2::new(-0.0, -0.0)] {
                assert_eq!(ik2_equal(l, &origin).unwrap(), expected);
                assert_eq!(ik2(l, l, &origin).unwrap(), expected);
                let (x, y, _) = fk(&[l, l], &[0.0, PI]);
                assert!(x.hypot(y) < 1e-15 * l);
            }
            // Three links whose wrist must sit at the origin.
            let (l3, phi) = (0.3 * l, 2.0_f64);
            let target = Isometry2::new(Vector2::new(l3 * phi.cos(), l3 * phi.sin()), phi);
            for q in ik3(l, l, l3, &target).unwrap() {
                assert_eq!((q[0], q[1]), (0.0, PI));
                assert!(angle_gap(q[2], phi - PI) < 1e-15);
            }
        }
    }

    #[test]
    fn ik3_round_trip_and_reachability() {
        let mut rng = Rng(3);
        for (l1, l2, l3) in TRIPLES {
            let reach = l1 + l2 + l3;
            let (mut solved, mut refused) = (0, 0);
            for _ in 0..20_000 {
                let r = reach * rng.range(0.0, 1.05);
                let (theta, phi) = (rng.angle(), rng.range(-10.0, 10.0));
                let (x, y) = (r * theta.cos(), r * theta.sin());
                let target = Isometry2::new(Vector2::new(x, y), phi);
                let wrist = (x - l3 * phi.cos()).hypot(y - l3 * phi.sin());
                let (inner, outer) = ((l1 - l2).abs(), l1 + l2);
                let margin = 1e-9 * outer;
                match ik3(l1, l2, l3, &target) {
                    Ok(solutions) => {
                        solved += 1;
                        assert!(wrist >= inner - 2.0 * margin && wrist <= outer + 2.0 * margin);
                        for (branch, q) in solutions.iter().enumerate() {
                            let (tx, ty, tphi) = fk(&[l1, l2, l3], q.as_slice());
                            assert!((tx - x).hypot(ty - y) < 1e-12 * reach);
                            assert!(angle_gap(tphi, phi) < 1e-12);
                            assert!(q.iter().all(|a| in_range(*a)));
                            let s2 = q[1].sin();
                            assert!(if branch == 0 {
                                s2 >= -1e-15
                            } else {
                                s2 <= 1e-15
                            });
                        }
                    }
                    Err(ArmError::Unreachable {
                        target: asked,
                        orientation,
                        radius,
                        inner: i,
                        outer: o,
                        distance,
                    }) => {
                        refused += 1;
                        // The error names the tip pose asked for, not the wrist.
                        assert_eq!(asked, [x, y]);
                        assert!(angle_gap(orientation.unwrap(), phi) < 1e-15);
                        assert!(wrist < inner || wrist > outer);
                        assert!((radius - wrist).abs() < 1e-12 * reach);
                        assert_eq!((i, o), (inner, outer));
                        let expected = if wrist > outer {
                            wrist - outer
                        } else {
                            inner - wrist
                        };
                        assert!((distance - expected).abs() < 1e-12 * reach && distance > 0.0);
                    }
                    Err(e) => panic!("unexpected {e:?}"),
                }
            }
            assert!(
                solved > 1000 && refused > 500,
                "{solved} solved, {refused} refused"
            );
        }
    }

    #[test]
    fn ik3_recovers_sampled_configurations() {
        let mut rng = Rng(4);
        for (l1, l2, l3) in TRIPLES {
            for _ in 0..2000 {
                let q = Vector3::new(rng.angle(), rng.angle(), rng.angle());
                if q[1].sin().abs() < 1e-3 {
                    continue;
                }
                let target = pose_of(&[l1, l2, l3], &q);
                let solutions = ik3(l1, l2, l3, &target).unwrap();
                let same = &solutions[usize::from(q[1].sin() < 0.0)];
                for k in 0..3 {
                    assert!(angle_gap(same[k], q[k]) < 1e-8, "{q} came back as {same}");
                }
            }
        }
    }

    /// Whether some `a + 2 pi k` lies in `range`, by the test's own rule.
    fn turns_into(a: f64, range: Option<(f64, f64)>) -> bool {
        range.is_none_or(|(lo, hi)| a + TAU * ((lo - a) / TAU).ceil() <= hi)
    }

    fn within(a: f64, range: Option<(f64, f64)>) -> bool {
        range.is_none_or(|(lo, hi)| lo <= a && a <= hi)
    }

    #[test]
    fn ik2_and_ik3_in_ranges() {
        let mut rng = Rng(24);
        let two: [[Option<(f64, f64)>; 2]; 3] = [
            [None, Some((0.0, PI))],
            [Some((-1.0, 2.0)), Some((-2.5, 0.5))],
            [Some((3.0, 5.0)), None],
        ];
        for (l1, l2) in PAIRS {
            for ranges in two {
                let (mut single, mut refused) = (0, 0);
                for _ in 0..2000 {
                    let q = Vector2::new(rng.angle(), rng.angle());
                    let (x, y, _) = fk(&[l1, l2], q.as_slice());
                    let target = Point2::new(x, y);
                    let free = ik2(l1, l2, &target).unwrap();
                    let fits = free.map(|b| (0..2).all(|k| turns_into(b[k], ranges[k])));
                    match ik2_in_ranges(l1, l2, ranges, &target) {
                        Ok(qs) => {
                            if fits[0] && fits[1] {
                                assert!(qs[0][1].sin() >= -1e-15 && qs[1][1].sin() <= 1e-15);
                            }
                            for b in &qs {
                                let (tx, ty, _) = fk(&[l1, l2], b.as_slice());
                                assert!((tx - x).hypot(ty - y) <= 1e-12 * (l1 + l2));
                                assert!(within(b[0], ranges[0]) && within(b[1], ranges[1]));
                            }
                            // Branch order kept; a lone survivor fills both entries.
                            for (b, free) in qs.iter().zip(&free) {
                                if fits[0] && fits[1] {
                                    assert!(angle_gap(b[0], free[0]) < 1e-12);
                                }
                            }
                            if fits[0] != fits[1] {
                                single += 1;
                                assert_eq!(qs[0], qs[1]);
                                let kept = &free[usize::from(fits[1])];
                                assert!(angle_gap(qs[0][1], kept[1]) < 1e-12);
                            }
                        }
                        Err(ArmError::Unreachable {
                            distance, radius, ..
                        }) => {
                            refused += 1;
                            assert!(!fits[0] && !fits[1] && distance > 0.0);
                            assert!((radius - x.hypot(y)).abs() < 1e-15 * (1.0 + radius));
                        }
                        Err(e) => panic!("{e:?}"),
                    }
                }
                assert!(single > 100, "{ranges:?}: {single} with one branch");
                if ranges[0].is_some() {
                    assert!(refused > 50, "{ranges:?}: {refused} refused");
                }
            }
        }
        // Outside the annulus: the annulus error, whatever the ranges.
        assert_eq!(
            ik2_in_ranges(1.0, 0.5, two[0], &Point2::new(2.0, 0.0)),
            ik2(1.0, 0.5, &Point2::new(2.0, 0.0))
        );
        assert!(matches!(
            ik2_in_ranges(1.0, 0.5, [Some((1.0, 0.0)), None], &Point2::new(1.0, 0.0)),
            Err(ArmError::OutOfRange {
                what: "range",
                link: Some(0),
                ..
            })
        ));
        let three = [Some((-1.0, 1.0)), Some((0.0, PI)), Some((-1.0, 1.0))];
        let (mut solved, mut refused) = (0, 0);
        for (l1, l2, l3) in TRIPLES {
            for _ in 0..2000 {
                let q = Vector3::new(rng.angle(), rng.angle(), rng.angle());
                let target = pose_of(&[l1, l2, l3], &q);
                let free = ik3(l1, l2, l3, &target).unwrap();
                let fits = free.map(|b| (0..3).all(|k| turns_into(b[k], three[k])));
                match ik3_in_ranges(l1, l2, l3, three, &target) {
                    Ok(qs) => {
                        solved += 1;
                        assert!(fits[0] || fits[1]);
                        for b in &qs {
                            let (x, y, phi) = fk(&[l1, l2, l3], b.as_slice());
                            let t = target.translation.vector;
                            assert!((x - t.x).hypot(y - t.y) < 1e-12 * (l1 + l2 + l3));
                            assert!(angle_gap(phi, target.rotation.angle()) < 1e-12);
                            assert!((0..3).all(|k| within(b[k], three[k])));
                        }
                    }
                    Err(ArmError::Unreachable {
                        distance,
                        orientation,
                        ..
                    }) => {
                        refused += 1;
                        assert!(!fits[0] && !fits[1] && distance > 0.0 && orientation.is_some());
                    }
                    Err(e) => panic!("{e:?}"),
                }
            }
        }
        assert!(
            solved > 1000 && refused > 1000,
            "{solved} solved, {refused} refused"
        );
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(4000))]

        #[test]
        fn ik2_round_trip_for_random_lengths(
            l1 in 1e-3..1e3_f64,
            l2 in 1e-3..1e3_f64,
            u in 0.0..=1.0_f64,
            theta in -PI..PI,
        ) {
            let (inner, outer) = ((l1 - l2).abs(), l1 + l2);
            let r = inner + (outer - inner) * u;
            let target = Point2::new(r * theta.cos(), r * theta.sin());
            let q = ik2(l1, l2, &target).unwrap();
            check_two_link_solutions(l1, l2, target, &q);
        }
    }
}
