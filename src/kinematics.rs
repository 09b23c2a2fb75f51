//! Inverse kinematics, inverse statics, work-spaces, manipulability and a damped-least-squares
//! solver for planar serial arms.
//!
//! The closed forms follow B. K. P. Horn, *Kinematics, Statics, and Dynamics of Two-D
//! Manipulators* (MIT AI working paper), re-derived, with these corrections to the printed text:
//!
//! - three-link inverse kinematics: the paper prints `theta3 = -theta2 - theta1`; the last angle
//!   is `q3 = phi - q1 - q2`, where `phi` is the orientation of the last link;
//! - usable (dexterous) work-space: the paper gives the central disk the radius
//!   `l3 - |l1 - l2|`; it is `min(l3 - |l1 - l2|, l1 + l2 - l3)`, and the annulus
//!   `l3 + |l1 - l2| ..= l1 + l2 - l3` exists exactly when `l3 <= min(l1, l2)` (its width is
//!   `2 (min(l1, l2) - l3)`), whether or not `l3 < |l1 - l2|`.
//!
//! The paper's inverse statics (the two-link `u`, `v` and the three-link 3 x 3 inverse with
//! determinant `l1 l2 sin q2`) are correct as printed; this module evaluates them in an
//! algebraically equal form that needs no product of lengths.
//!
//! Conventions: `q[0]` is link 1's angle from +x, `q[i]` (i > 0) is link i+1's angle relative
//! to link i, all zeros is the arm stretched along +x, joint 1 is at the origin and the tip is
//! at the end of the last link. Angles returned by the closed forms lie in (-pi, pi].
//!
//! Nothing here panics or returns NaN. The fallible functions answer NaN or infinite
//! arguments with [`ArmError::NonFinite`]; the infallible ones document what they make of
//! them. Lengths are used with their signs (a link of negative length is the positive one
//! turned by pi); the derive macro only passes positive ones.

use core::f64::consts::{PI, TAU};

use nalgebra::{Isometry2, Matrix2, Matrix3, Point2, SMatrix, SVector, Vector2, Vector3};

use crate::ArmError;

/// Relative tolerance on reach: a target whose distance from the base lies outside the
/// reachable annulus by at most `REACH_TOLERANCE * outer_radius` counts as lying on the
/// boundary (the law-of-cosines term is clamped into `[-1, 1]`); farther out it is
/// [`ArmError::Unreachable`]. [`Workspace::contains`] and [`DexterousWorkspace::contains`]
/// use the same slack, so they agree with the inverse kinematics.
pub const REACH_TOLERANCE: f64 = 1e-9;

/// Singularity threshold of the inverse statics: the configuration counts as singular when
/// `|l1 l2 sin q2| < SINGULAR_THRESHOLD * |l1 l2|`, that is when `|sin q2| < SINGULAR_THRESHOLD`
/// (or a length is zero). The error then reports `measure = l1 l2 sin q2` and
/// `threshold = SINGULAR_THRESHOLD * |l1 l2|`.
pub const SINGULAR_THRESHOLD: f64 = 1e-9;

/// Largest Euclidean norm, in radians, of one joint step taken by [`solve_dls`].
pub const DLS_MAX_STEP: f64 = 0.5;

/// Largest damping [`solve_dls`] tries before it concludes that no step reduces the error.
const DLS_MAX_DAMPING: f64 = 1e6;

/// Closed-form inverse kinematics of a two- or three-link arm, both elbow solutions.
///
/// `#[derive(PlanarArm)]` implements it for two links (`Target = Point2<f64>`, via [`ik2`] or
/// [`ik2_equal`]) and for three links (`Target = Isometry2<f64>`, via [`ik3`]).
pub trait ClosedFormIk<const N: usize> {
    /// `Point2<f64>` for two links, `Isometry2<f64>` for three.
    type Target;
    /// Both elbow solutions: index 0 has `sin q2 >= 0`, index 1 has `sin q2 <= 0`. On the outer
    /// or inner boundary both are the same configuration.
    ///
    /// # Errors
    /// [`ArmError::NonFinite`] for NaN or infinite targets, [`ArmError::Unreachable`] for
    /// targets outside the work-space.
    fn inverse_kinematics(&self, target: &Self::Target) -> Result<[SVector<f64, N>; 2], ArmError>;
}

/// Inverse statics of a two-link arm: the force the tip exerts, from the joint torques.
pub trait TipForce {
    /// The force `F` with `J^T F = tau` (see [`tip_force2`]).
    ///
    /// # Errors
    /// [`ArmError::NonFinite`] for NaN or infinite arguments, [`ArmError::Singular`] when
    /// `|sin q2| < SINGULAR_THRESHOLD`.
    fn tip_force(
        &self,
        q: &SVector<f64, 2>,
        tau: &SVector<f64, 2>,
    ) -> Result<Vector2<f64>, ArmError>;
}

/// Inverse statics of a three-link arm: the force and torque the tip exerts, from the joint
/// torques.
pub trait TipWrench {
    /// The force `F` and torque `T` with `J^T (F, T) = tau` (see [`tip_wrench3`]).
    ///
    /// # Errors
    /// [`ArmError::NonFinite`] for NaN or infinite arguments, [`ArmError::Singular`] when
    /// `|sin q2| < SINGULAR_THRESHOLD`.
    fn tip_wrench(
        &self,
        q: &SVector<f64, 3>,
        tau: &SVector<f64, 3>,
    ) -> Result<(Vector2<f64>, f64), ArmError>;
}

/// Wraps an angle into (-pi, pi]. `a` must be finite.
#[inline]
fn wrap_angle(a: f64) -> f64 {
    if a > -PI && a <= PI {
        a
    } else {
        let r = a.rem_euclid(TAU);
        if r > PI {
            r - TAU
        } else {
            r
        }
    }
}

#[inline]
fn check_lengths(lengths: &[f64]) -> Result<(), ArmError> {
    if lengths.iter().all(|l| l.is_finite()) {
        Ok(())
    } else {
        Err(ArmError::NonFinite {
            argument: "lengths",
        })
    }
}

#[inline]
fn check_vector<const N: usize>(
    v: &SVector<f64, N>,
    argument: &'static str,
) -> Result<(), ArmError> {
    if v.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(ArmError::NonFinite { argument })
    }
}

/// The target's coordinates, with `-0.0` turned into `0.0` so that `atan2` never sees a
/// negative zero in the denominator.
#[inline]
fn target_coordinates(target: &Point2<f64>) -> Result<(f64, f64), ArmError> {
    if target.x.is_finite() && target.y.is_finite() {
        Ok((target.x + 0.0, target.y + 0.0))
    } else {
        Err(ArmError::NonFinite { argument: "target" })
    }
}

/// `Ok` when `radius` lies in `inner ..= outer` up to `REACH_TOLERANCE * outer`.
#[inline]
fn annulus_check(radius: f64, inner: f64, outer: f64) -> Result<(), ArmError> {
    // How far outside the annulus, beyond the outer circle or inside the hole (at most one
    // of the two is positive).
    let distance = (radius - outer).max(inner - radius);
    if distance > REACH_TOLERANCE * outer {
        return Err(ArmError::Unreachable {
            radius,
            inner,
            outer,
            distance,
        });
    }
    Ok(())
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
    annulus_check(x.hypot(y), (a1 - a2).abs(), a1 + a2)?;
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
    annulus_check(x.hypot(y), 0.0, 2.0 * a)?;
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
/// wrist point lies outside the two-link annulus, with `radius` the wrist's distance from the
/// base and `inner`, `outer` the two-link radii.
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
            radius: f64::INFINITY,
            inner: (a1 - a2).abs(),
            outer: a1 + a2,
            distance: f64::INFINITY,
        });
    }
    let solutions = if l1 == l2 {
        ik2_equal(l1, &wrist)?
    } else {
        ik2(l1, l2, &wrist)?
    };
    Ok(solutions.map(|q| SVector::<f64, 3>::new(q[0], q[1], wrap_angle(phi - q[0] - q[1]))))
}

/// The singularity error of the inverse statics.
#[inline]
fn statics_singular(l1: f64, l2: f64, s2: f64) -> ArmError {
    ArmError::Singular {
        // l1 * s2 is finite, so the product is finite or infinite, never NaN.
        measure: l1 * s2 * l2,
        threshold: SINGULAR_THRESHOLD * (l1 * l2).abs(),
    }
}

/// Inverse statics of a two-link arm: the force `F = (u, v)` the tip exerts when the joints
/// apply the torques `tau`, i.e. the solution of `J^T F = tau`:
///
/// ```text
/// tau1 = (r1 + r2) x F,   tau2 = r2 x F,   (a, b) x (c, d) = a d - b c
/// u = (l2 c12 tau1 - (l1 c1 + l2 c12) tau2) / (l1 l2 s2)
/// v = (l2 s12 tau1 - (l1 s1 + l2 s12) tau2) / (l1 l2 s2)
/// ```
///
/// (the paper's formula, which is correct), evaluated as
/// `u = (c12 (tau1 - tau2) / l1 - c1 tau2 / l2) / s2` and likewise for `v`.
///
/// # Errors
/// [`ArmError::NonFinite`] (`"lengths"`, `"q"`, `"tau"`) for NaN or infinite arguments;
/// [`ArmError::Singular`] when `|sin q2| < SINGULAR_THRESHOLD` (see [`SINGULAR_THRESHOLD`]) or a
/// length is zero: the links are parallel and the torques cannot balance a force along them.
///
/// # Example
/// ```
/// use planar_arm::kinematics::tip_force2;
/// use planar_arm::nalgebra::Vector2;
///
/// // q = (0, pi/2): r1 = (1, 0), r2 = (0, 0.5), so tau1 = (r1 + r2) x F = v - 0.5 u and
/// // tau2 = r2 x F = -0.5 u.
/// let q = Vector2::new(0.0, std::f64::consts::FRAC_PI_2);
/// let f = tip_force2(1.0, 0.5, &q, &Vector2::new(1.0, 0.5)).unwrap();
/// assert!((f.y - 0.5 * f.x - 1.0).abs() < 1e-12 && (-0.5 * f.x - 0.5).abs() < 1e-12);
/// ```
#[inline]
pub fn tip_force2(
    l1: f64,
    l2: f64,
    q: &SVector<f64, 2>,
    tau: &SVector<f64, 2>,
) -> Result<Vector2<f64>, ArmError> {
    check_lengths(&[l1, l2])?;
    check_vector(q, "q")?;
    check_vector(tau, "tau")?;
    let (q1, q2) = (wrap_angle(q[0]), wrap_angle(q[1]));
    let (s1, c1) = q1.sin_cos();
    let (s12, c12) = (q1 + q2).sin_cos();
    let s2 = q2.sin();
    if s2.abs() < SINGULAR_THRESHOLD || l1 == 0.0 || l2 == 0.0 {
        return Err(statics_singular(l1, l2, s2));
    }
    // Scale the torques to at most 1 so that no intermediate overflows.
    let scale = tau.amax();
    if scale == 0.0 {
        return Ok(Vector2::zeros());
    }
    let (t1, t2) = (tau[0] / scale, tau[1] / scale);
    let (a, b) = ((t1 - t2) / l1, t2 / l2);
    let force = Vector2::new((c12 * a - c1 * b) / s2, (s12 * a - s1 * b) / s2) * scale;
    if force.iter().any(|f| f.is_nan()) {
        return Err(statics_singular(l1, l2, s2));
    }
    Ok(force)
}

/// Inverse statics of a three-link arm: the force `F = (u, v)` and torque `T` the tip exerts
/// when the joints apply the torques `tau`, i.e. the solution of
///
/// ```text
/// tau_i = T + (r_i + ... + r_3) x F,   r_k = l_k (cos phi_k, sin phi_k)
/// ```
///
/// with `phi_k` the absolute angle of link k. The 3 x 3 matrix has determinant `l1 l2 sin q2`;
/// its inverse (the paper prints it correctly) is
///
/// ```text
/// | u |      1       |  l2 c12     -(l1 c1 + l2 c12)        l1 c1             | | tau1 |
/// | v | = --------- |  l2 s12     -(l1 s1 + l2 s12)        l1 s1             | | tau2 |
/// | T |   l1 l2 s2   |  l2 l3 s3   -(l1 l3 s23 + l2 l3 s3)  l1 l2 s2 + l1 l3 s23 | | tau3 |
/// ```
///
/// evaluated without products of lengths: with `a = (tau1 - tau2) / l1`, `b = (tau2 - tau3) / l2`,
/// `u = (c12 a - c1 b) / s2`, `v = (s12 a - s1 b) / s2`, `T = tau3 + l3 (s3 a - s23 b) / s2`.
///
/// # Errors
/// As [`tip_force2`]: [`ArmError::NonFinite`] or [`ArmError::Singular`] when
/// `|sin q2| < SINGULAR_THRESHOLD`.
///
/// # Example
/// ```
/// use planar_arm::kinematics::tip_wrench3;
/// use planar_arm::nalgebra::Vector3;
///
/// // Equal joint torques produce a pure tip torque.
/// let (force, torque) =
///     tip_wrench3(1.0, 1.0, 0.3, &Vector3::new(0.2, 1.0, -0.4), &Vector3::repeat(2.0)).unwrap();
/// assert!(force.norm() < 1e-12 && (torque - 2.0).abs() < 1e-12);
/// ```
#[inline]
pub fn tip_wrench3(
    l1: f64,
    l2: f64,
    l3: f64,
    q: &SVector<f64, 3>,
    tau: &SVector<f64, 3>,
) -> Result<(Vector2<f64>, f64), ArmError> {
    check_lengths(&[l1, l2, l3])?;
    check_vector(q, "q")?;
    check_vector(tau, "tau")?;
    let (q1, q2, q3) = (wrap_angle(q[0]), wrap_angle(q[1]), wrap_angle(q[2]));
    let (s1, c1) = q1.sin_cos();
    let (s12, c12) = (q1 + q2).sin_cos();
    let s2 = q2.sin();
    let s3 = q3.sin();
    let s23 = (q2 + q3).sin();
    if s2.abs() < SINGULAR_THRESHOLD || l1 == 0.0 || l2 == 0.0 {
        return Err(statics_singular(l1, l2, s2));
    }
    let scale = tau.amax();
    if scale == 0.0 {
        return Ok((Vector2::zeros(), 0.0));
    }
    let (t1, t2, t3) = (tau[0] / scale, tau[1] / scale, tau[2] / scale);
    let (a, b) = ((t1 - t2) / l1, (t2 - t3) / l2);
    let force = Vector2::new((c12 * a - c1 * b) / s2, (s12 * a - s1 * b) / s2) * scale;
    let torque = (t3 + l3 * ((s3 * a - s23 * b) / s2)) * scale;
    if force.iter().any(|f| f.is_nan()) || torque.is_nan() {
        return Err(statics_singular(l1, l2, s2));
    }
    Ok((force, torque))
}

/// The work-space of a serial arm of revolute links: the closed annulus of the points the tip
/// can reach, `inner ..= outer` about joint 1.
///
/// For lengths `l_k`, `outer = sum l_k` and `inner = max(0, 2 max l_k - sum l_k)`: the tip can
/// come no closer than the longest link minus all the others.
///
/// # Example
/// ```
/// use planar_arm::kinematics::Workspace;
/// use planar_arm::nalgebra::Point2;
///
/// let w = Workspace::of_lengths(&[1.0, 0.5]);
/// assert_eq!((w.inner_radius(), w.outer_radius()), (0.5, 1.5));
/// assert!(w.contains(&Point2::new(0.0, 1.0)) && !w.contains(&Point2::new(0.2, 0.0)));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Workspace {
    inner: f64,
    outer: f64,
}

impl Workspace {
    /// The work-space of links of the given lengths, base first. Lengths count by absolute
    /// value (a link of negative length sweeps the same circle); NaN and infinite lengths are
    /// skipped. No links give the single point at the origin.
    #[must_use]
    pub fn of_lengths(lengths: &[f64]) -> Self {
        let (mut sum, mut longest) = (0.0_f64, 0.0_f64);
        for length in lengths.iter().filter(|l| l.is_finite()) {
            sum += length.abs();
            longest = longest.max(length.abs());
        }
        Self {
            // `max` also maps the NaN of an overflowing inf - inf to 0.
            inner: (2.0 * longest - sum).max(0.0),
            outer: sum,
        }
    }

    /// The inner radius, `max(0, 2 max l - sum l)`.
    #[must_use]
    pub fn inner_radius(&self) -> f64 {
        self.inner
    }

    /// The outer radius, `sum l`.
    #[must_use]
    pub fn outer_radius(&self) -> f64 {
        self.outer
    }

    /// Whether the tip can reach `point`: its distance from the base lies in
    /// `inner ..= outer`, widened on both sides by [`REACH_TOLERANCE`]` * outer` (the slack
    /// [`ik2`] allows). Points holding NaN or infinities are not contained.
    #[must_use]
    pub fn contains(&self, point: &Point2<f64>) -> bool {
        point.x.is_finite()
            && point.y.is_finite()
            && annulus_check(point.x.hypot(point.y), self.inner, self.outer).is_ok()
    }

    /// The area, `pi (outer^2 - inner^2)`.
    #[must_use]
    pub fn area(&self) -> f64 {
        annulus_area(self.inner, self.outer)
    }
}

/// `pi (outer^2 - inner^2)`, 0 for a circle (also when the sum of the radii overflows).
fn annulus_area(inner: f64, outer: f64) -> f64 {
    if outer > inner {
        PI * (outer - inner) * (outer + inner)
    } else {
        0.0
    }
}

/// The dexterous (usable) work-space of a three-link arm: the points the tip reaches with
/// every orientation of the last link.
///
/// A point `p` belongs to it when the circle of radius `l3` about `p` (the wrist positions)
/// lies inside the two-link annulus `a = |l1 - l2| ..= b = l1 + l2`, that is when
/// `|p| + l3 <= b` and `| |p| - l3 | >= a`. That region has up to two pieces:
///
/// - the annulus `l3 + a ..= b - l3`, present when `l3 <= min(l1, l2)`;
/// - the disk about the origin of radius `min(l3 - a, b - l3)`, present when `a <= l3 <= b`
///   (a single point when the radius is 0).
///
/// When `l1 == l2` the two touch and are stored merged as one disk of radius `2 l - l3`, as
/// the paper says. When `l3 > l1 + l2`, or `min(l1, l2) < l3 < |l1 - l2|`, the region is
/// empty.
///
/// # Example
/// ```
/// use planar_arm::kinematics::DexterousWorkspace;
///
/// let equal = DexterousWorkspace::of_lengths(1.0, 1.0, 0.5);
/// assert_eq!((equal.disk_radius(), equal.annulus()), (Some(1.5), None));
/// let unequal = DexterousWorkspace::of_lengths(1.0, 0.6, 0.3);
/// assert_eq!(unequal.disk_radius(), None);
/// let (inner, outer) = unequal.annulus().unwrap();
/// assert!((inner - 0.7).abs() < 1e-12 && (outer - 1.3).abs() < 1e-12);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DexterousWorkspace {
    /// Inner radius of the two-link annulus, `|l1 - l2|`.
    inner2: f64,
    /// Outer radius of the two-link annulus, `l1 + l2`.
    outer2: f64,
    /// `|l3|`.
    last: f64,
    disk: Option<f64>,
    annulus: Option<(f64, f64)>,
}

impl DexterousWorkspace {
    /// The dexterous work-space of links of lengths `l1`, `l2`, `l3` (by absolute value). Any
    /// NaN or infinite length gives the empty region.
    #[must_use]
    pub fn of_lengths(l1: f64, l2: f64, l3: f64) -> Self {
        if !(l1.is_finite() && l2.is_finite() && l3.is_finite()) {
            return Self {
                inner2: 0.0,
                outer2: 0.0,
                last: f64::INFINITY,
                disk: None,
                annulus: None,
            };
        }
        let (a1, a2, c) = (l1.abs(), l2.abs(), l3.abs());
        let (a, b) = ((a1 - a2).abs(), a1 + a2);
        let mut annulus = (c + a <= b - c).then_some((c + a, b - c));
        let mut disk = (a <= c && c <= b).then(|| (c - a).min(b - c));
        if let (Some(radius), Some((inner, outer))) = (disk, annulus) {
            if radius >= inner {
                disk = Some(outer);
                annulus = None;
            }
        }
        Self {
            inner2: a,
            outer2: b,
            last: c,
            disk,
            annulus,
        }
    }

    /// The radius of the disk about the origin, if there is one (0 for the origin alone).
    #[must_use]
    pub fn disk_radius(&self) -> Option<f64> {
        self.disk
    }

    /// The `(inner, outer)` radii of the annulus piece, if there is one that is not merged
    /// into the disk.
    #[must_use]
    pub fn annulus(&self) -> Option<(f64, f64)> {
        self.annulus
    }

    /// Whether no point is reachable with every orientation.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.disk.is_none() && self.annulus.is_none()
    }

    /// The total area of the pieces.
    #[must_use]
    pub fn area(&self) -> f64 {
        let disk = self.disk.map_or(0.0, |r| PI * r * r);
        let annulus = self.annulus.map_or(0.0, |(i, o)| annulus_area(i, o));
        disk + annulus
    }

    /// Whether `point` is reachable with every orientation of the last link: the circle of
    /// wrist positions about it lies in the two-link annulus widened by
    /// [`REACH_TOLERANCE`]` * (l1 + l2)`, the slack [`ik3`] allows. Points holding NaN or
    /// infinities are not contained.
    #[must_use]
    pub fn contains(&self, point: &Point2<f64>) -> bool {
        if !(point.x.is_finite() && point.y.is_finite()) {
            return false;
        }
        let rho = point.x.hypot(point.y);
        let slack = REACH_TOLERANCE * self.outer2;
        rho + self.last - self.outer2 <= slack && self.inner2 - (rho - self.last).abs() <= slack
    }
}

/// The manipulability `sqrt(det(J J^T))` (Yoshikawa) of the task rows of a 3 x N Jacobian
/// whose rows are tip x, tip y and the last link's angle: the product of the singular values.
///
/// - `N >= 3`: the full 3 x N Jacobian (position and orientation);
/// - `N == 2`: the two position rows, so `|det J_xy|` (`|l1 l2 sin q2|` for two links);
/// - `N == 1`: one joint cannot span the plane, so `det(J J^T)` would always be 0; the
///   measure is instead `sqrt(det(J^T J))`, the tip speed per unit joint rate `|J_xy|`;
/// - `N == 0`: 0.
///
/// Allocation-free. A Jacobian holding NaN or infinities gives 0 (it is treated as singular).
#[must_use]
pub fn manipulability<const N: usize>(jacobian: &SMatrix<f64, 3, N>) -> f64 {
    if N == 0 || !jacobian.iter().all(|x| x.is_finite()) {
        return 0.0;
    }
    // Scale the entries to at most 1 so that no product overflows.
    let scale = jacobian.amax();
    if scale == 0.0 {
        return 0.0;
    }
    let j = jacobian / scale;
    match N {
        1 => j[(0, 0)].hypot(j[(1, 0)]) * scale,
        2 => (j[(0, 0)] * j[(1, 1)] - j[(0, 1)] * j[(1, 0)]).abs() * scale * scale,
        _ => row_volume(&j) * scale * scale * scale,
    }
}

/// `sqrt(det(J J^T))` for three rows, as the volume of the parallelepiped they span: the
/// product of the norms that Gram-Schmidt (with one re-orthogonalisation) leaves. Accurate to
/// rounding even near a singularity, where `sqrt` of a computed determinant is not.
fn row_volume<const N: usize>(j: &SMatrix<f64, 3, N>) -> f64 {
    let mut basis = [SVector::<f64, N>::zeros(); 2];
    let mut volume = 1.0;
    for k in 0..3 {
        let mut v = j.row(k).transpose();
        for _ in 0..2 {
            for e in &basis[..k.min(2)] {
                v -= e * e.dot(&v);
            }
        }
        let norm = v.norm();
        if norm == 0.0 {
            return 0.0;
        }
        volume *= norm;
        if k < 2 {
            basis[k] = v / norm;
        }
    }
    volume
}

/// Whether the Jacobian is singular: [`manipulability`] is not above `threshold` (a NaN
/// threshold counts every Jacobian as singular).
#[must_use]
pub fn is_singular<const N: usize>(jacobian: &SMatrix<f64, 3, N>, threshold: f64) -> bool {
    threshold.is_nan() || manipulability(jacobian) <= threshold
}

/// What [`solve_dls`] should reach.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum IkTarget {
    /// A tip position; the orientation is free (only the Jacobian's first two rows are used).
    Position(Point2<f64>),
    /// A tip position and the absolute angle of the last link.
    Pose(Isometry2<f64>),
}

/// Settings of [`solve_dls`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DlsOptions {
    /// The most iterations (each one Jacobian and one forward-kinematics evaluation).
    pub max_iterations: usize,
    /// Converged when the error norm is at most this: metres for a position; for a pose the
    /// norm of (dx, dy, dphi), mixing metres and radians.
    pub tolerance: f64,
    /// The initial damping `lambda`. It adapts as in Levenberg-Marquardt: halved (down to a
    /// thousandth of this value) after a step that lowers the error, quadrupled after one that
    /// does not.
    pub damping: f64,
}

impl Default for DlsOptions {
    /// 200 iterations, tolerance `1e-10`, initial damping `0.05`.
    fn default() -> Self {
        Self {
            max_iterations: 200,
            tolerance: 1e-10,
            damping: 0.05,
        }
    }
}

/// The task-space error `target - pose` (orientation error wrapped to (-pi, pi], zero for a
/// position target).
#[inline]
fn task_error(target: &IkTarget, pose: &Isometry2<f64>) -> Result<Vector3<f64>, ArmError> {
    let p = pose.translation.vector;
    let rotation = pose.rotation.complex();
    if !(p.x.is_finite() && p.y.is_finite() && rotation.re.is_finite() && rotation.im.is_finite()) {
        return Err(ArmError::NonFinite { argument: "fk" });
    }
    Ok(match target {
        IkTarget::Position(t) => Vector3::new(t.x - p.x, t.y - p.y, 0.0),
        IkTarget::Pose(t) => {
            let v = t.translation.vector;
            let dphi = wrap_angle(t.rotation.angle() - pose.rotation.angle());
            Vector3::new(v.x - p.x, v.y - p.y, dphi)
        }
    })
}

/// One damped-least-squares step `J^T (J J^T + lambda^2 I)^-1 e` over the task rows.
#[inline]
fn dls_step<const N: usize>(
    jacobian: &SMatrix<f64, 3, N>,
    error: &Vector3<f64>,
    lambda: f64,
    pose: bool,
) -> Option<SVector<f64, N>> {
    let damping = lambda * lambda;
    let step = if pose {
        let a = jacobian * jacobian.transpose() + Matrix3::identity() * damping;
        jacobian.transpose() * a.cholesky()?.solve(error)
    } else {
        let rows = jacobian.fixed_rows::<2>(0);
        let a = rows * rows.transpose() + Matrix2::identity() * damping;
        rows.transpose() * a.cholesky()?.solve(&error.xy())
    };
    step.iter().all(|x| x.is_finite()).then_some(step)
}

/// Damped-least-squares (Levenberg-Marquardt) inverse kinematics for any number of links.
///
/// Starting at `seed`, repeats `dq = J^T (J J^T + lambda^2 I)^-1 e` with the task error `e`
/// (position, or position and orientation wrapped to (-pi, pi]), the step norm limited to
/// [`DLS_MAX_STEP`], and keeps a step only when it lowers `|e|`; see [`DlsOptions`] for the
/// damping schedule. `fk` gives the tip pose (position and absolute angle of the last link),
/// `jacobian` the 3 x N Jacobian with rows tip x, tip y and that angle. Returns the
/// configuration reached from the seed, not wrapped, so it stays close to the seed. Uses no
/// heap: fixed-size 2 x 2 or 3 x 3 Cholesky solves.
///
/// # Errors
/// - [`ArmError::NonFinite`] when `seed`, `target` or `options` (`tolerance`, `damping`) hold
///   NaN or infinities, or `fk` (`"fk"`) or `jacobian` (`"jacobian"`) returns them;
/// - [`ArmError::NoConvergence`] when the error is still above the tolerance after
///   `max_iterations`, or earlier when no damping up to `1e6` lowers it any more (a local
///   minimum, e.g. for an unreachable target), with the iterations spent and the final
///   residual.
///
/// # Example
/// ```
/// use planar_arm::kinematics::{solve_dls, DlsOptions, IkTarget};
/// use planar_arm::nalgebra::{Isometry2, Matrix3, Point2, Vector2, Vector3};
///
/// let l = [1.0, 0.8, 0.5];
/// let fk = |q: &Vector3<f64>| {
///     let (mut x, mut y, mut phi) = (0.0, 0.0, 0.0);
///     for k in 0..3 {
///         phi += q[k];
///         x += l[k] * phi.cos();
///         y += l[k] * phi.sin();
///     }
///     Isometry2::new(Vector2::new(x, y), phi)
/// };
/// let jacobian = |q: &Vector3<f64>| {
///     let mut j = Matrix3::zeros();
///     let mut phi = 0.0;
///     for k in 0..3 {
///         phi += q[k];
///         for i in 0..=k {
///             j[(0, i)] -= l[k] * phi.sin();
///             j[(1, i)] += l[k] * phi.cos();
///         }
///         j[(2, k)] = 1.0;
///     }
///     j
/// };
/// let target = IkTarget::Position(Point2::new(1.0, 1.0));
/// let seed = Vector3::new(0.5, 0.5, 0.5);
/// let q = solve_dls(fk, jacobian, &target, &seed, &DlsOptions::default()).unwrap();
/// let tip = fk(&q).translation.vector;
/// assert!((tip - Vector2::new(1.0, 1.0)).norm() < 1e-10);
/// ```
pub fn solve_dls<const N: usize>(
    fk: impl Fn(&SVector<f64, N>) -> Isometry2<f64>,
    jacobian: impl Fn(&SVector<f64, N>) -> SMatrix<f64, 3, N>,
    target: &IkTarget,
    seed: &SVector<f64, N>,
    options: &DlsOptions,
) -> Result<SVector<f64, N>, ArmError> {
    check_vector(seed, "seed")?;
    let target_finite = match target {
        IkTarget::Position(p) => p.x.is_finite() && p.y.is_finite(),
        IkTarget::Pose(pose) => {
            let v = pose.translation.vector;
            let c = pose.rotation.complex();
            v.x.is_finite() && v.y.is_finite() && c.re.is_finite() && c.im.is_finite()
        }
    };
    if !target_finite {
        return Err(ArmError::NonFinite { argument: "target" });
    }
    if !(options.tolerance.is_finite() && options.damping.is_finite()) {
        return Err(ArmError::NonFinite {
            argument: "options",
        });
    }
    let pose = matches!(target, IkTarget::Pose(_));
    let floor = options.damping.abs() * 1e-3;
    let mut lambda = options.damping.abs();
    let mut q = *seed;
    let mut error = task_error(target, &fk(&q))?;
    let mut residual = error.norm();
    let mut iterations = 0;
    while iterations < options.max_iterations && residual > options.tolerance {
        iterations += 1;
        let j = jacobian(&q);
        if !j.iter().all(|x| x.is_finite()) {
            return Err(ArmError::NonFinite {
                argument: "jacobian",
            });
        }
        let mut accepted = false;
        if let Some(mut step) = dls_step(&j, &error, lambda, pose) {
            let norm = step.norm();
            if norm > DLS_MAX_STEP {
                step *= DLS_MAX_STEP / norm;
            }
            let candidate = q + step;
            let candidate_error = task_error(target, &fk(&candidate))?;
            let candidate_residual = candidate_error.norm();
            if candidate_residual < residual {
                q = candidate;
                error = candidate_error;
                residual = candidate_residual;
                accepted = true;
            }
        }
        if accepted {
            lambda = (lambda * 0.5).max(floor);
        } else {
            lambda = (lambda * 4.0).max(1e-6);
            if lambda > DLS_MAX_DAMPING {
                break;
            }
        }
    }
    if residual <= options.tolerance {
        Ok(q)
    } else {
        Err(ArmError::NoConvergence {
            iterations,
            residual,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f64::consts::FRAC_PI_2;
    use proptest::prelude::*;

    /// Independent forward kinematics: tip x, tip y and the absolute angle of the last link.
    fn fk(lengths: &[f64], q: &[f64]) -> (f64, f64, f64) {
        let (mut x, mut y, mut phi) = (0.0, 0.0, 0.0);
        for (l, qk) in lengths.iter().zip(q) {
            phi += qk;
            x += l * phi.cos();
            y += l * phi.sin();
        }
        (x, y, phi)
    }

    /// Independent Jacobian: column i is the sum over k >= i of l_k (-sin phi_k, cos phi_k), 1.
    fn jacobian<const N: usize>(lengths: &[f64; N], q: &SVector<f64, N>) -> SMatrix<f64, 3, N> {
        let mut j = SMatrix::<f64, 3, N>::zeros();
        let mut phi = 0.0;
        for k in 0..N {
            phi += q[k];
            for i in 0..=k {
                j[(0, i)] -= lengths[k] * phi.sin();
                j[(1, i)] += lengths[k] * phi.cos();
            }
            j[(2, k)] = 1.0;
        }
        j
    }

    fn pose_of<const N: usize>(lengths: &[f64; N], q: &SVector<f64, N>) -> Isometry2<f64> {
        let (x, y, phi) = fk(lengths, q.as_slice());
        Isometry2::new(Vector2::new(x, y), phi)
    }

    /// `a x b = a.x b.y - a.y b.x`, the paper's planar cross product.
    fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
        a.x * b.y - a.y * b.x
    }

    /// Joint torques for tip force `f` and torque `t` from the paper's statics:
    /// tau_i = t + (r_i + ... + r_n) x f.
    fn joint_torques(lengths: &[f64], q: &[f64], f: Vector2<f64>, t: f64) -> Vec<f64> {
        let mut phi = 0.0;
        let links: Vec<Vector2<f64>> = lengths
            .iter()
            .zip(q)
            .map(|(l, qk)| {
                phi += qk;
                Vector2::new(l * phi.cos(), l * phi.sin())
            })
            .collect();
        (0..links.len())
            .map(|i| t + cross(links[i..].iter().sum(), f))
            .collect()
    }

    fn angle_gap(a: f64, b: f64) -> f64 {
        wrap_angle(a - b).abs()
    }

    fn in_range(a: f64) -> bool {
        a > -PI && a <= PI
    }

    /// Deterministic splitmix64 generator.
    struct Rng(u64);

    impl Rng {
        fn next(&mut self) -> f64 {
            self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
            let mut z = self.0;
            z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            z ^= z >> 31;
            (z >> 11) as f64 / (1u64 << 53) as f64
        }

        fn range(&mut self, lo: f64, hi: f64) -> f64 {
            lo + (hi - lo) * self.next()
        }

        fn angle(&mut self) -> f64 {
            self.range(-PI, PI)
        }
    }

    const PAIRS: [(f64, f64); 8] = [
        (1.0, 0.5),
        (0.5, 1.0),
        (0.7, 1.3),
        (1.0, 1.0),
        (2.5, 2.5),
        (0.3, 3.0),
        (1e-3, 2e-3),
        (4e3, 1e3),
    ];

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
                        radius,
                        inner: i,
                        outer: o,
                        distance,
                    }) => {
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

    const TRIPLES: [(f64, f64, f64); 6] = [
        (1.0, 0.5, 0.3),
        (1.0, 1.0, 0.4),
        (0.6, 1.2, 1.5),
        (1.0, 1.0, 1.5),
        (2.0, 0.5, 0.2),
        (0.8, 0.8, 0.0),
    ];

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
                        radius,
                        inner: i,
                        outer: o,
                        distance,
                    }) => {
                        refused += 1;
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

    #[test]
    fn non_finite_inputs_are_rejected() {
        let bad = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY];
        for b in bad {
            assert_eq!(ik2(1.0, 0.5, &Point2::new(b, 0.0)), nonfinite("target"));
            assert_eq!(ik2(1.0, 0.5, &Point2::new(0.0, b)), nonfinite("target"));
            assert_eq!(ik2(b, 0.5, &Point2::new(1.0, 0.0)), nonfinite("lengths"));
            assert_eq!(ik2(1.0, b, &Point2::new(1.0, 0.0)), nonfinite("lengths"));
            assert_eq!(ik2_equal(1.0, &Point2::new(b, b)), nonfinite("target"));
            assert_eq!(ik2_equal(b, &Point2::new(1.0, 0.0)), nonfinite("lengths"));
            let pose = Isometry2::new(Vector2::new(1.0, 0.2), 0.1);
            assert_eq!(ik3(1.0, 1.0, b, &pose), nonfinite("lengths"));
            let moved = Isometry2::new(Vector2::new(b, 0.2), 0.1);
            assert_eq!(ik3(1.0, 1.0, 0.2, &moved), nonfinite("target"));
            let turned = Isometry2::new(Vector2::new(1.0, 0.2), b);
            assert_eq!(ik3(1.0, 1.0, 0.2, &turned), nonfinite("target"));

            let q2 = Vector2::new(0.1, 1.0);
            let t2 = Vector2::new(1.0, 2.0);
            assert_eq!(
                tip_force2(1.0, 0.5, &Vector2::new(b, 1.0), &t2),
                nonfinite("q")
            );
            assert_eq!(
                tip_force2(1.0, 0.5, &q2, &Vector2::new(1.0, b)),
                nonfinite("tau")
            );
            assert_eq!(tip_force2(b, 0.5, &q2, &t2), nonfinite("lengths"));
            let q3 = Vector3::new(0.1, 1.0, 0.3);
            let t3 = Vector3::new(1.0, 2.0, 3.0);
            assert_eq!(
                tip_wrench3(1.0, 0.5, 0.2, &Vector3::new(0.0, 1.0, b), &t3),
                nonfinite("q")
            );
            assert_eq!(
                tip_wrench3(1.0, 0.5, 0.2, &q3, &Vector3::new(b, 0.0, 0.0)),
                nonfinite("tau")
            );
            assert_eq!(tip_wrench3(1.0, 0.5, b, &q3, &t3), nonfinite("lengths"));

            let p = Point2::new(b, 0.5);
            assert!(!Workspace::of_lengths(&[1.0, 1.0]).contains(&p));
            assert!(!DexterousWorkspace::of_lengths(1.0, 1.0, 0.5).contains(&p));
            assert!(DexterousWorkspace::of_lengths(1.0, b, 0.5).is_empty());
            assert!(!DexterousWorkspace::of_lengths(1.0, b, 0.5).contains(&Point2::origin()));
            let mut j = jacobian(&[1.0, 1.0, 1.0], &Vector3::new(0.1, 1.0, 0.3));
            j[(1, 2)] = b;
            assert_eq!(manipulability(&j), 0.0);
            assert!(is_singular(&j, 1e-9));

            let l = [1.0, 1.0, 1.0, 1.0];
            let seed = SVector::<f64, 4>::repeat(0.3);
            let solve = |target: IkTarget, seed: &SVector<f64, 4>, options: &DlsOptions| {
                solve_dls(
                    |q| pose_of(&l, q),
                    |q| jacobian(&l, q),
                    &target,
                    seed,
                    options,
                )
            };
            let fine = IkTarget::Position(Point2::new(2.0, 1.0));
            let opts = DlsOptions::default();
            let mut bad_seed = seed;
            bad_seed[2] = b;
            assert_eq!(solve(fine, &bad_seed, &opts), nonfinite("seed"));
            assert_eq!(
                solve(IkTarget::Position(p), &seed, &opts),
                nonfinite("target")
            );
            assert_eq!(
                solve(IkTarget::Pose(turned), &seed, &opts),
                nonfinite("target")
            );
            let bad_opts = DlsOptions { damping: b, ..opts };
            assert_eq!(solve(fine, &seed, &bad_opts), nonfinite("options"));
            let nan_fk = solve_dls(
                |_: &SVector<f64, 4>| Isometry2::new(Vector2::new(b, 0.0), 0.0),
                |q| jacobian(&l, q),
                &fine,
                &seed,
                &opts,
            );
            assert_eq!(nan_fk, nonfinite("fk"));
            let nan_jacobian = solve_dls(
                |q| pose_of(&l, q),
                |_: &SVector<f64, 4>| SMatrix::<f64, 3, 4>::repeat(b),
                &fine,
                &seed,
                &opts,
            );
            assert_eq!(nan_jacobian, nonfinite("jacobian"));
        }
    }

    fn nonfinite<T>(argument: &'static str) -> Result<T, ArmError> {
        Err(ArmError::NonFinite { argument })
    }

    fn random_force(rng: &mut Rng) -> Vector2<f64> {
        Vector2::new(rng.range(-10.0, 10.0), rng.range(-10.0, 10.0))
    }

    #[test]
    fn tip_force2_inverts_the_transposed_jacobian() {
        let mut rng = Rng(5);
        for (l1, l2) in PAIRS {
            for _ in 0..2000 {
                let q = Vector2::new(rng.angle(), rng.angle());
                if q[1].sin().abs() < 0.05 {
                    continue;
                }
                // Force -> torques (the paper's statics) -> force.
                let f = random_force(&mut rng);
                let tau = joint_torques(&[l1, l2], q.as_slice(), f, 0.0);
                let back = tip_force2(l1, l2, &q, &Vector2::new(tau[0], tau[1])).unwrap();
                assert!(
                    (back - f).norm() < 1e-9 * f.norm().max(1.0),
                    "{f} came back as {back}"
                );
                // Torques -> force -> torques, via the independent Jacobian.
                let tau = Vector2::new(rng.range(-5.0, 5.0), rng.range(-5.0, 5.0));
                let f = tip_force2(l1, l2, &q, &tau).unwrap();
                let j = jacobian(&[l1, l2], &q);
                let again = j.fixed_rows::<2>(0).transpose() * f;
                assert!((again - tau).norm() < 1e-9 * tau.norm().max(1.0));
            }
        }
    }

    #[test]
    fn tip_wrench3_inverts_the_transposed_jacobian() {
        let mut rng = Rng(6);
        for (l1, l2, l3) in TRIPLES {
            for _ in 0..2000 {
                let q = Vector3::new(rng.angle(), rng.angle(), rng.angle());
                if q[1].sin().abs() < 0.05 {
                    continue;
                }
                let f = random_force(&mut rng);
                let t = rng.range(-3.0, 3.0);
                let tau = joint_torques(&[l1, l2, l3], q.as_slice(), f, t);
                let (f_back, t_back) =
                    tip_wrench3(l1, l2, l3, &q, &Vector3::new(tau[0], tau[1], tau[2])).unwrap();
                assert!((f_back - f).norm() < 1e-9 * f.norm().max(1.0));
                assert!((t_back - t).abs() < 1e-9 * t.abs().max(1.0));
                let tau = Vector3::new(
                    rng.range(-5.0, 5.0),
                    rng.range(-5.0, 5.0),
                    rng.range(-5.0, 5.0),
                );
                let (f, t) = tip_wrench3(l1, l2, l3, &q, &tau).unwrap();
                let again = jacobian(&[l1, l2, l3], &q).transpose() * Vector3::new(f.x, f.y, t);
                assert!((again - tau).norm() < 1e-9 * tau.norm().max(1.0));
            }
        }
    }

    /// The paper's printed inverse statics, entry by entry, against the forward matrices.
    #[test]
    fn paper_statics_inverses_are_correct_as_printed() {
        let mut rng = Rng(7);
        let (l1, l2, l3) = (1.0, 0.7, 0.4);
        for _ in 0..500 {
            let q = Vector3::new(rng.angle(), rng.angle(), rng.angle());
            let det = l1 * l2 * q[1].sin();
            if det.abs() < 0.05 {
                continue;
            }
            let (s1, c1) = q[0].sin_cos();
            let (s12, c12) = (q[0] + q[1]).sin_cos();
            let (s123, c123) = (q[0] + q[1] + q[2]).sin_cos();
            let (s2, s3, s23) = (q[1].sin(), q[2].sin(), (q[1] + q[2]).sin());
            let forward = Matrix3::new(
                -(l1 * s1 + l2 * s12 + l3 * s123),
                l1 * c1 + l2 * c12 + l3 * c123,
                1.0,
                -(l2 * s12 + l3 * s123),
                l2 * c12 + l3 * c123,
                1.0,
                -(l3 * s123),
                l3 * c123,
                1.0,
            );
            assert!((forward.determinant() - det).abs() < 1e-12);
            let printed = Matrix3::new(
                l2 * c12,
                -(l1 * c1 + l2 * c12),
                l1 * c1,
                l2 * s12,
                -(l1 * s1 + l2 * s12),
                l1 * s1,
                l2 * l3 * s3,
                -(l1 * l3 * s23 + l2 * l3 * s3),
                l1 * l2 * s2 + l1 * l3 * s23,
            ) / det;
            assert!((printed * forward - Matrix3::identity()).norm() < 1e-9);
            // Two links: u = {l2 c12 T1 - (l1 c1 + l2 c12) T2} / (l1 l2 s2), v likewise.
            let forward2 = Matrix2::new(
                -(l1 * s1 + l2 * s12),
                l1 * c1 + l2 * c12,
                -(l2 * s12),
                l2 * c12,
            );
            let printed2 = Matrix2::new(
                l2 * c12,
                -(l1 * c1 + l2 * c12),
                l2 * s12,
                -(l1 * s1 + l2 * s12),
            ) / det;
            assert!((printed2 * forward2 - Matrix2::identity()).norm() < 1e-9);
        }
    }

    #[test]
    fn singular_configurations_are_rejected() {
        let (l1, l2, l3) = (1.0, 0.5, 0.25);
        for q2 in [0.0, PI, -PI, 1e-12, PI - 1e-12, TAU, 0.5e-9] {
            let expected = Err(ArmError::Singular {
                measure: l1 * l2 * wrap_angle(q2).sin(),
                threshold: SINGULAR_THRESHOLD * l1 * l2,
            });
            let tau2 = Vector2::new(1.0, -1.0);
            assert_eq!(tip_force2(l1, l2, &Vector2::new(0.3, q2), &tau2), expected);
            let tau3 = Vector3::new(1.0, -1.0, 0.5);
            let got = tip_wrench3(l1, l2, l3, &Vector3::new(0.3, q2, 1.0), &tau3);
            assert_eq!(got.map(|_| Vector2::zeros()), expected);
        }
        for q2 in [2e-9, 1e-6, PI - 1e-6] {
            assert!(tip_force2(l1, l2, &Vector2::new(0.3, q2), &Vector2::new(1.0, 0.0)).is_ok());
        }
        assert!(matches!(
            tip_force2(0.0, l2, &Vector2::new(0.3, 1.0), &Vector2::new(1.0, 0.0)),
            Err(ArmError::Singular { .. })
        ));
        // Zero torques give zero force even near (but not at) a singularity.
        assert_eq!(
            tip_force2(l1, l2, &Vector2::new(0.3, 1e-6), &Vector2::zeros()),
            Ok(Vector2::zeros())
        );
    }

    /// Every configuration on a grid of joint angles (multiples of pi / 6, which include the
    /// extreme ones) for the joints after the first.
    fn grid_radii(lengths: &[f64]) -> Vec<(f64, f64)> {
        let n = lengths.len();
        let mut tips = Vec::new();
        let count = 12usize.pow(u32::try_from(n - 1).unwrap());
        for code in 0..count {
            let mut q = vec![0.37 * code as f64];
            let mut c = code;
            for _ in 1..n {
                q.push((c % 12) as f64 * PI / 6.0);
                c /= 12;
            }
            let (x, y, _) = fk(lengths, &q);
            tips.push((x, y));
        }
        tips
    }

    #[test]
    fn workspace_matches_brute_force() {
        let mut rng = Rng(8);
        let arms: [&[f64]; 9] = [
            &[1.0],
            &[1.0, 0.5],
            &[0.5, 1.0],
            &[1.0, 1.0],
            &[3.0, 1.0, 0.5],
            &[1.0, 1.0, 1.0],
            &[0.2, 2.0, 0.5, 0.3],
            &[1.0, 2.0, 3.0, 4.0],
            &[0.4, 0.3, 5.0, 0.2, 0.1],
        ];
        for lengths in arms {
            let w = Workspace::of_lengths(lengths);
            let (inner, outer) = (w.inner_radius(), w.outer_radius());
            let tips = grid_radii(lengths);
            let (mut lo, mut hi) = (f64::INFINITY, 0.0_f64);
            for &(x, y) in &tips {
                assert!(w.contains(&Point2::new(x, y)), "{lengths:?}: ({x}, {y})");
                lo = lo.min(x.hypot(y));
                hi = hi.max(x.hypot(y));
            }
            // The radii are attained, so they are not too generous either.
            assert!(
                (lo - inner).abs() < 1e-12 && (hi - outer).abs() < 1e-12,
                "{lengths:?}"
            );
            for _ in 0..2000 {
                let q: Vec<f64> = lengths.iter().map(|_| rng.angle()).collect();
                let (x, y, _) = fk(lengths, &q);
                assert!(w.contains(&Point2::new(x, y)));
                let theta = rng.angle();
                let (s, c) = theta.sin_cos();
                let beyond = outer + rng.range(1e-6, 1.0);
                assert!(!w.contains(&Point2::new(beyond * c, beyond * s)));
                if inner > 1e-6 {
                    let short = inner - rng.range(1e-6, inner);
                    assert!(!w.contains(&Point2::new(short * c, short * s)));
                }
            }
            assert!(
                (w.area() - PI * (outer * outer - inner * inner)).abs() < 1e-12 * outer * outer
            );
        }
        assert_eq!(
            Workspace::of_lengths(&[-1.0, 0.5]),
            Workspace::of_lengths(&[1.0, 0.5])
        );
        assert_eq!(Workspace::of_lengths(&[]).outer_radius(), 0.0);
    }

    #[test]
    fn workspace_agrees_with_ik2() {
        let mut rng = Rng(9);
        for (l1, l2) in PAIRS {
            let w = Workspace::of_lengths(&[l1, l2]);
            let outer = l1 + l2;
            for k in 0..4000 {
                // Half the points within a few tolerances of a boundary circle.
                let r = match k % 4 {
                    0 => outer * (1.0 + rng.range(-3e-9, 3e-9)),
                    1 => (l1 - l2).abs() + outer * rng.range(-3e-9, 3e-9),
                    _ => outer * rng.range(0.0, 1.2),
                };
                let theta = rng.angle();
                let p = Point2::new(r * theta.cos(), r * theta.sin());
                assert_eq!(
                    w.contains(&p),
                    ik2(l1, l2, &p).is_ok(),
                    "({l1}, {l2}) at {p}"
                );
            }
        }
    }

    #[test]
    fn dexterous_pieces() {
        let pieces = |l1, l2, l3| {
            let d = DexterousWorkspace::of_lengths(l1, l2, l3);
            (d.disk_radius(), d.annulus())
        };
        // Equal links: one disk of radius 2 l - l3 (the paper).
        assert_eq!(pieces(1.0, 1.0, 0.5), (Some(1.5), None));
        // ... also when l3 > l, where the paper's l3 - |l1 - l2| = 1.5 would be wrong.
        assert_eq!(pieces(1.0, 1.0, 1.5), (Some(0.5), None));
        // l3 < |l1 - l2|: annulus only.
        assert_eq!(pieces(1.0, 0.5, 0.25), (None, Some((0.75, 1.25))));
        // |l1 - l2| < l3 <= min: disk and annulus.
        let (disk, annulus) = pieces(1.0, 0.6, 0.5);
        assert!((disk.unwrap() - 0.1).abs() < 1e-12);
        let (i, o) = annulus.unwrap();
        assert!((i - 0.9).abs() < 1e-12 && (o - 1.1).abs() < 1e-12);
        // min < l3 <= max: disk of radius l3 - |l1 - l2|.
        assert_eq!(pieces(1.0, 0.5, 0.75), (Some(0.25), None));
        // max < l3 <= l1 + l2: disk of radius l1 + l2 - l3.
        assert_eq!(pieces(1.0, 0.5, 1.25), (Some(0.25), None));
        // l3 = l1 + l2: the origin alone.
        let point = DexterousWorkspace::of_lengths(1.0, 0.5, 1.5);
        assert_eq!(point.disk_radius(), Some(0.0));
        assert!(point.contains(&Point2::origin()) && !point.contains(&Point2::new(1e-6, 0.0)));
        // Empty: min < l3 < |l1 - l2| with no room, and l3 > l1 + l2.
        assert!(DexterousWorkspace::of_lengths(10.0, 1.0, 5.0).is_empty());
        assert!(DexterousWorkspace::of_lengths(1.0, 0.5, 2.0).is_empty());
        assert_eq!(DexterousWorkspace::of_lengths(1.0, 0.5, 2.0).area(), 0.0);
        let d = DexterousWorkspace::of_lengths(1.0, 0.6, 0.5);
        assert!((d.area() - PI * (0.01 + 1.21 - 0.81)).abs() < 1e-12);
    }

    #[test]
    fn dexterous_workspace_matches_brute_force() {
        let mut rng = Rng(10);
        let triples = [
            (1.0, 0.5, 0.3),
            (1.0, 0.5, 0.2),
            (1.0, 1.0, 0.4),
            (1.0, 0.6, 0.5),
            (1.0, 0.5, 0.75),
            (1.0, 0.5, 1.25),
            (1.0, 1.0, 1.5),
            (10.0, 1.0, 5.0),
        ];
        let orientations = 240;
        for (l1, l2, l3) in triples {
            let d = DexterousWorkspace::of_lengths(l1, l2, l3);
            let all = Workspace::of_lengths(&[l1, l2, l3]);
            let (a, b) = ((l1 - l2).abs(), l1 + l2);
            let (mut inside, mut outside) = (0, 0);
            for _ in 0..1500 {
                let rho = rng.range(0.0, l1 + l2 + l3);
                // Stay clear of the region's boundary circles, which sampling might miss.
                let margin = 1e-3;
                if (rho + l3 - b).abs() < margin || ((rho - l3).abs() - a).abs() < margin {
                    continue;
                }
                let theta = rng.angle();
                let p = Point2::new(rho * theta.cos(), rho * theta.sin());
                let offset = rng.angle();
                let every = (0..orientations).all(|k| {
                    let phi = offset + f64::from(k) * TAU / f64::from(orientations);
                    ik3(l1, l2, l3, &Isometry2::new(p.coords, phi)).is_ok()
                });
                assert_eq!(d.contains(&p), every, "{l1}, {l2}, {l3} at {p}");
                let in_pieces = d.disk_radius().is_some_and(|r| rho <= r)
                    || d.annulus().is_some_and(|(i, o)| i <= rho && rho <= o);
                assert_eq!(in_pieces, every, "pieces of {l1}, {l2}, {l3} at {p}");
                if every {
                    inside += 1;
                    assert!(all.contains(&p));
                } else {
                    outside += 1;
                }
            }
            assert!(
                d.is_empty() || inside > 20,
                "{l1}, {l2}, {l3}: {inside} inside"
            );
            assert!(outside > 20);
        }
    }

    #[test]
    fn manipulability_matches_closed_forms() {
        let mut rng = Rng(11);
        for _ in 0..500 {
            let l = [
                rng.range(0.2, 2.0),
                rng.range(0.2, 2.0),
                rng.range(0.2, 2.0),
                rng.range(0.2, 2.0),
            ];
            let q = SVector::<f64, 4>::from_fn(|_, _| rng.angle());
            let expected = (l[0] * l[1] * q[1].sin()).abs();
            // Two links: |l1 l2 sin q2|.
            let j2 = jacobian(&[l[0], l[1]], &q.fixed_rows::<2>(0).into_owned());
            assert!((manipulability(&j2) - expected).abs() < 1e-12);
            // Three links, square: |det J| = |l1 l2 sin q2|, the paper's determinant.
            let j3 = jacobian(&[l[0], l[1], l[2]], &q.fixed_rows::<3>(0).into_owned());
            assert!((manipulability(&j3) - expected).abs() < 1e-9);
            // Four links: Cauchy-Binet, det(J J^T) = sum of squared 3 x 3 minors.
            let j4 = jacobian(&l, &q);
            let mut sum = 0.0;
            for skip in 0..4 {
                let cols: Vec<usize> = (0..4).filter(|&c| c != skip).collect();
                let minor = Matrix3::from_fn(|r, c| j4[(r, cols[c])]);
                sum += minor.determinant().powi(2);
            }
            assert!((manipulability(&j4) - sum.sqrt()).abs() < 1e-9);
            // One link: the tip speed |l1|.
            let j1 = jacobian(&[l[0]], &q.fixed_rows::<1>(0).into_owned());
            assert!((manipulability(&j1) - l[0]).abs() < 1e-12);
        }
        let stretched = jacobian(&[1.0, 1.0, 1.0], &Vector3::new(0.4, 0.0, 0.3));
        assert!(is_singular(&stretched, 1e-9));
        let bent = jacobian(&[1.0, 1.0, 1.0], &Vector3::new(0.4, FRAC_PI_2, 0.3));
        assert!(!is_singular(&bent, 1e-9));
        assert!(is_singular(&bent, f64::NAN));
        assert_eq!(manipulability(&SMatrix::<f64, 3, 0>::zeros()), 0.0);
        let huge = bent * 1e200;
        assert_eq!(manipulability(&huge), f64::INFINITY);
        assert!((manipulability(&(bent * 1e-100)) - 1e-300).abs() < 1e-310);
    }

    fn dls_case<const N: usize>(rng: &mut Rng) {
        let lengths: [f64; N] = core::array::from_fn(|_| rng.range(0.3, 1.2));
        let options = DlsOptions::default();
        for pose in [false, true] {
            for _ in 0..30 {
                let truth = SVector::<f64, N>::from_fn(|_, _| rng.angle());
                let seed = truth + SVector::<f64, N>::from_fn(|_, _| rng.range(-0.2, 0.2));
                let goal = pose_of(&lengths, &truth);
                let target = if pose {
                    IkTarget::Pose(goal)
                } else {
                    IkTarget::Position(Point2::from(goal.translation.vector))
                };
                let q = solve_dls(
                    |q| pose_of(&lengths, q),
                    |q| jacobian(&lengths, q),
                    &target,
                    &seed,
                    &options,
                )
                .unwrap_or_else(|e| panic!("N = {N}, pose {pose}: {e:?}"));
                let reached = pose_of(&lengths, &q);
                assert!((reached.translation.vector - goal.translation.vector).norm() <= 1e-10);
                if pose {
                    assert!(angle_gap(reached.rotation.angle(), goal.rotation.angle()) <= 1e-10);
                }
                // Reached from the seed: no farther from it than the configuration used.
                assert!(
                    (q - seed).norm() <= 1.25 * (truth - seed).norm() + 1e-9,
                    "N = {N}: |q - seed| = {}, |truth - seed| = {}",
                    (q - seed).norm(),
                    (truth - seed).norm()
                );
            }
        }
        // Beyond reach: the best is the stretched arm, short by 0.5.
        let reach: f64 = lengths.iter().sum();
        let far = IkTarget::Position(Point2::new(0.0, reach + 0.5));
        let seed = SVector::<f64, N>::from_fn(|i, _| if i == 0 { 1.2 } else { 0.1 });
        match solve_dls(
            |q| pose_of(&lengths, q),
            |q| jacobian(&lengths, q),
            &far,
            &seed,
            &options,
        ) {
            Err(ArmError::NoConvergence {
                iterations,
                residual,
            }) => {
                assert!(iterations <= options.max_iterations);
                assert!((residual - 0.5).abs() < 1e-6, "residual {residual}");
            }
            other => panic!("expected NoConvergence, got {other:?}"),
        }
    }

    #[test]
    fn dls_converges_for_four_to_eight_links() {
        let mut rng = Rng(12);
        dls_case::<4>(&mut rng);
        dls_case::<5>(&mut rng);
        dls_case::<6>(&mut rng);
        dls_case::<7>(&mut rng);
        dls_case::<8>(&mut rng);
    }

    #[test]
    fn dls_agrees_with_the_closed_forms() {
        let mut rng = Rng(13);
        let lengths = [1.0, 0.7, 0.3];
        for _ in 0..200 {
            let q = Vector3::new(rng.angle(), rng.range(0.3, 2.8), rng.angle());
            let target = pose_of(&lengths, &q);
            let [up, _] = ik3(lengths[0], lengths[1], lengths[2], &target).unwrap();
            let seed = up + Vector3::new(0.1, -0.1, 0.1);
            let solved = solve_dls(
                |q| pose_of(&lengths, q),
                |q| jacobian(&lengths, q),
                &IkTarget::Pose(target),
                &seed,
                &DlsOptions::default(),
            )
            .unwrap();
            for k in 0..3 {
                assert!(angle_gap(solved[k], up[k]) < 1e-8);
            }
        }
        // No iterations allowed: only an exact seed is accepted.
        let none = DlsOptions {
            max_iterations: 0,
            ..DlsOptions::default()
        };
        let q = Vector3::new(0.1, 0.2, 0.3);
        let at = IkTarget::Pose(pose_of(&lengths, &q));
        let run = |seed: &Vector3<f64>| {
            solve_dls(
                |q| pose_of(&lengths, q),
                |q| jacobian(&lengths, q),
                &at,
                seed,
                &none,
            )
        };
        assert_eq!(run(&q), Ok(q));
        assert!(matches!(
            run(&(q * 2.0)),
            Err(ArmError::NoConvergence { iterations: 0, .. })
        ));
    }

    #[test]
    fn test_jacobian_matches_finite_differences() {
        let mut rng = Rng(14);
        let lengths = [1.0, 0.7, 0.3, 0.9];
        for _ in 0..50 {
            let q = SVector::<f64, 4>::from_fn(|_, _| rng.angle());
            let j = jacobian(&lengths, &q);
            for i in 0..4 {
                let h = 1e-6;
                let mut qp = q;
                let mut qm = q;
                qp[i] += h;
                qm[i] -= h;
                let (xp, yp, pp) = fk(&lengths, qp.as_slice());
                let (xm, ym, pm) = fk(&lengths, qm.as_slice());
                let d = Vector3::new(xp - xm, yp - ym, pp - pm) / (2.0 * h);
                assert!((d - j.column(i)).norm() < 1e-8);
            }
        }
    }

    fn clean(result: &Result<impl Sized, ArmError>) -> bool {
        match result {
            Err(ArmError::Unreachable {
                radius,
                inner,
                outer,
                distance,
            }) => ![radius, inner, outer, distance].iter().any(|v| v.is_nan()) && *distance > 0.0,
            Err(ArmError::Singular { measure, threshold }) => {
                !measure.is_nan() && !threshold.is_nan()
            }
            Err(ArmError::NoConvergence { residual, .. }) => !residual.is_nan(),
            _ => true,
        }
    }

    fn any_f64() -> impl Strategy<Value = f64> {
        prop_oneof![
            any::<f64>(),
            -10.0..10.0,
            Just(0.0),
            Just(-0.0),
            Just(1.0),
            Just(f64::MAX),
            Just(f64::MIN_POSITIVE),
            Just(5e-324),
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(4000))]

        #[test]
        fn no_panic_and_no_nan(
            l in proptest::array::uniform3(any_f64()),
            p in proptest::array::uniform3(any_f64()),
            t in proptest::array::uniform3(any_f64()),
        ) {
            let target = Point2::new(p[0], p[1]);
            for r in [ik2(l[0], l[1], &target), ik2_equal(l[0], &target)] {
                prop_assert!(clean(&r));
                if let Ok(qs) = r {
                    prop_assert!(qs.iter().flatten().all(|a| in_range(*a)));
                }
            }
            let r = ik3(l[0], l[1], l[2], &Isometry2::new(Vector2::new(p[0], p[1]), p[2]));
            prop_assert!(clean(&r));
            if let Ok(qs) = r {
                prop_assert!(qs.iter().flatten().all(|a| in_range(*a)));
            }
            let r = tip_force2(l[0], l[1], &Vector2::new(p[0], p[1]), &Vector2::new(t[0], t[1]));
            prop_assert!(clean(&r));
            if let Ok(f) = r {
                prop_assert!(!f.iter().any(|v| v.is_nan()));
            }
            let r = tip_wrench3(l[0], l[1], l[2], &Vector3::from(p), &Vector3::from(t));
            prop_assert!(clean(&r));
            if let Ok((f, torque)) = r {
                prop_assert!(!f.iter().any(|v| v.is_nan()) && !torque.is_nan());
            }
            let w = Workspace::of_lengths(&l);
            prop_assert!(!w.inner_radius().is_nan() && !w.outer_radius().is_nan() && !w.area().is_nan());
            let _ = w.contains(&target);
            let d = DexterousWorkspace::of_lengths(l[0], l[1], l[2]);
            prop_assert!(!d.area().is_nan());
            let _ = d.contains(&target);
            let j = SMatrix::<f64, 3, 3>::from_fn(|r, c| [l, p, t][c][r]);
            prop_assert!(!manipulability(&j).is_nan());
            let j2 = SMatrix::<f64, 3, 2>::from_fn(|r, c| [l, p][c][r]);
            prop_assert!(!manipulability(&j2).is_nan());
        }

        #[test]
        fn dls_never_panics_or_returns_nan(
            p in proptest::array::uniform3(any_f64()),
            seed in proptest::array::uniform3(any_f64()),
            tolerance in any_f64(),
            damping in any_f64(),
            max_iterations in 0..60_usize,
            pose in any::<bool>(),
        ) {
            let lengths = [1.0, 0.7, 0.3];
            let target = if pose {
                IkTarget::Pose(Isometry2::new(Vector2::new(p[0], p[1]), p[2]))
            } else {
                IkTarget::Position(Point2::new(p[0], p[1]))
            };
            let options = DlsOptions { max_iterations, tolerance, damping };
            let r = solve_dls(
                |q| pose_of(&lengths, q),
                |q| jacobian(&lengths, q),
                &target,
                &Vector3::from(seed),
                &options,
            );
            prop_assert!(clean(&r));
            if let Ok(q) = r {
                prop_assert!(q.iter().all(|a| a.is_finite()));
            }
        }

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
