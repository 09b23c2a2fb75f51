//! Inverse statics: the tip force (two links) or wrench (three or more links) that the joint
//! torques hold in balance.
//!
//! Every function here takes the sine and cosine of each raw joint angle and composes the
//! absolute angles by the angle-sum formulas, never wrapping or summing angles first, so the
//! results are as accurate at `q = 1e15` as at `q = 1`.

use nalgebra::{SVector, Vector2};
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use super::{check_lengths, check_vector, jacobian_of};
use crate::{ArmError, Joint, Link};

/// Singularity threshold of the inverse statics: the configuration counts as singular when
/// `|l1 l2 sin q2| < SINGULAR_THRESHOLD * |l1 l2|`, that is when `|sin q2| < SINGULAR_THRESHOLD`
/// (or a length is zero). The error then reports `measure = l1 l2 sin q2` and
/// `threshold = SINGULAR_THRESHOLD * |l1 l2|`.
pub const SINGULAR_THRESHOLD: f64 = 1e-9;

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
/// `u = (c12 (tau1 - tau2) / l1 - c1 tau2 / l2) / s2` and likewise for `v`, with `c12`, `s12`
/// composed from the sines and cosines of `q1` and `q2` (accurate for any finite angle).
///
/// # Errors
/// [`ArmError::NonFinite`] (`"lengths"`, `"q"`, `"tau"`) for NaN or infinite arguments, and
/// `"result"` when finite arguments give a force beyond `f64::MAX`;
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
    let (s1, c1) = q[0].sin_cos();
    let (s2, c2) = q[1].sin_cos();
    let (s12, c12) = angle_sum((s1, c1), (s2, c2));
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
    finite_result(force.iter().copied())?;
    Ok(force)
}

/// `(sin, cos)` of `a + b` from those of `a` and `b`. Summing the angles first would round
/// the sum (by up to 0.06 rad at `|q| = 1e15`); the sine and cosine of each raw angle are
/// accurate for any finite angle (the standard library and `libm` reduce arguments exactly).
#[inline]
pub(super) fn angle_sum((sa, ca): (f64, f64), (sb, cb): (f64, f64)) -> (f64, f64) {
    (sa * cb + ca * sb, ca * cb - sa * sb)
}

/// `Err(NonFinite { argument: "result" })` when finite input overflowed to an infinity.
#[inline]
fn finite_result(values: impl IntoIterator<Item = f64>) -> Result<(), ArmError> {
    if values.into_iter().all(f64::is_finite) {
        Ok(())
    } else {
        Err(ArmError::NonFinite { argument: "result" })
    }
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
/// As [`tip_force2`]: [`ArmError::NonFinite`] (also `"result"` for an overflowing wrench) or
/// [`ArmError::Singular`] when `|sin q2| < SINGULAR_THRESHOLD`.
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
    let (s1, c1) = q[0].sin_cos();
    let (s2, c2) = q[1].sin_cos();
    let (s3, c3) = q[2].sin_cos();
    let (s12, c12) = angle_sum((s1, c1), (s2, c2));
    let (s23, _) = angle_sum((s2, c2), (s3, c3));
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
    finite_result(force.iter().copied().chain([torque]))?;
    Ok((force, torque))
}

/// Relative tolerance of [`RedundantTipWrench::tip_wrench`]: torques count as balanced by a tip
/// wrench when the part of them outside the range of `J^T` has norm at most
/// `UNBALANCED_TOLERANCE * |tau|`. Rounding alone leaves about `1e-16 |tau|` for a
/// well-conditioned configuration and up to about `1e-7 |tau|` at [`SINGULAR_THRESHOLD`].
pub const UNBALANCED_TOLERANCE: f64 = 1e-6;

/// The answer of inverse statics for any number of links ([`inverse_statics`]): the tip
/// wrench that best balances the joint torques, and the torques it leaves unbalanced.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StaticWrench<const N: usize> {
    /// The force the tip exerts, N, in the base frame.
    pub force: Vector2<f64>,
    /// The torque the tip exerts, N m (zero for one and two links, see [`inverse_statics`]).
    pub torque: f64,
    /// `tau - J^T (force, torque)`: the joint torques no tip wrench balances, zero up to
    /// rounding for three links or fewer and for torques that come from a tip wrench. Its norm
    /// is the least-squares residual.
    pub residual: SVector<f64, N>,
}

/// Inverse statics of an arm of `N` revolute links of lengths `lengths` (for prismatic
/// joints, see [`inverse_statics_of`]): the tip force
/// `F = (u, v)` and torque `T` that the joint torques `tau` balance, `J^T (F, T) = tau`, in the
/// least-squares sense.
///
/// - Three links: the unique solution, as [`tip_wrench3`] (to rounding).
/// - More than three links: `J^T` is `N x 3`, so `N` equations bind three unknowns and only
///   torques in a three-dimensional subspace come from a tip wrench. The result is the wrench
///   whose torques `J^T w` come closest to `tau` (Euclidean norm, which is what an estimate of
///   the external wrench from measured torques wants), with `residual = tau - J^T w`: the
///   torques that would move the joints without moving the tip. [`RedundantTipWrench`]'s
///   `tip_wrench` refuses a residual above [`UNBALANCED_TOLERANCE`] instead.
/// - One and two links: fewer equations than unknowns. As the paper does for two links, the
///   tip exerts no torque (`T = 0`); two links then give [`tip_force2`]'s force, one link the
///   force perpendicular to it.
///
/// # Singularity
/// For `N >= 3`, `J^T` loses rank exactly when all joints lie on one line (the columns of `J`
/// are `(-(y_tip - y_i), x_tip - x_i, 1)`, the tip does not matter). The measure is
/// `sqrt(det(J J^T))` (the [`manipulability`](super::manipulability), `|l1 l2 sin q2|` for three
/// links), the threshold `SINGULAR_THRESHOLD * sum_{i < j < N} |l_i l_j|` over the links but the
/// last (`SINGULAR_THRESHOLD |l1 l2|` for three links, the rule of [`tip_wrench3`]).
///
/// Accurate for any finite angle: the absolute angles are composed from the sine and cosine of
/// each joint angle, never summed. Computed without normal equations (a Gram-Schmidt QR of
/// `J^T` about the joints' centroid, fixed size, no heap), so near a singularity the error grows
/// with the condition number of `J^T`, not its square.
///
/// # Errors
/// [`ArmError::NonFinite`] (`"lengths"`, `"q"`, `"tau"`) for NaN or infinite arguments, and
/// `"result"` when the wrench overflows; [`ArmError::Singular`] as above (for one and two
/// links: a zero length, or for two links `|sin q2| < SINGULAR_THRESHOLD`).
///
/// # Example
/// ```
/// use planar_arm::kinematics::inverse_statics;
/// use planar_arm::nalgebra::{SVector, Vector2};
///
/// // Four unit links: joints at (0, 0), (1, 0), (1, 1), (0, 1), the tip back at the base.
/// let half_pi = std::f64::consts::FRAC_PI_2;
/// let q = SVector::<f64, 4>::new(0.0, half_pi, half_pi, half_pi);
/// // The tip pushes along +x with 2 N and exerts 0.5 N m: tau_i = T + (tip - joint_i) x F.
/// let tau = SVector::<f64, 4>::new(0.5, 0.5, 2.5, 2.5);
/// let w = inverse_statics(&[1.0; 4], &q, &tau).unwrap();
/// assert!((w.force - Vector2::new(2.0, 0.0)).norm() < 1e-12 && (w.torque - 0.5).abs() < 1e-12);
/// assert!(w.residual.norm() < 1e-12);
/// // Torques that only fold the arm: nothing at the tip balances them.
/// let fold = SVector::<f64, 4>::new(1.0, -1.0, 1.0, -1.0);
/// let w = inverse_statics(&[1.0; 4], &q, &fold).unwrap();
/// assert!(w.residual.norm() > 0.5);
/// ```
pub fn inverse_statics<const N: usize>(
    lengths: &[f64; N],
    q: &SVector<f64, N>,
    tau: &SVector<f64, N>,
) -> Result<StaticWrench<N>, ArmError> {
    check_lengths(lengths)?;
    check_vector(q, "q")?;
    check_vector(tau, "tau")?;
    let none = SVector::<f64, N>::zeros();
    match N {
        0 => Ok(StaticWrench {
            force: Vector2::zeros(),
            torque: 0.0,
            residual: none,
        }),
        1 => {
            let (s, c) = q[0].sin_cos();
            let l = lengths[0];
            if l == 0.0 {
                return Err(ArmError::Singular {
                    measure: 0.0,
                    threshold: 0.0,
                });
            }
            // tau = l (c, s) x F; the shortest such F is perpendicular to the link.
            let force = Vector2::new(-s, c) * (tau[0] / l);
            finite_result(force.iter().copied())?;
            Ok(StaticWrench {
                force,
                torque: 0.0,
                residual: none,
            })
        }
        2 => {
            let force = tip_force2(
                lengths[0],
                lengths[1],
                &Vector2::new(q[0], q[1]),
                &Vector2::new(tau[0], tau[1]),
            )?;
            Ok(StaticWrench {
                force,
                torque: 0.0,
                residual: none,
            })
        }
        _ => redundant_statics(lengths, q, tau),
    }
}

/// [`inverse_statics`] for `N >= 3`.
fn redundant_statics<const N: usize>(
    lengths: &[f64; N],
    q: &SVector<f64, N>,
    tau: &SVector<f64, N>,
) -> Result<StaticWrench<N>, ArmError> {
    // Work in units of the longest link and of the largest torque, so nothing below overflows.
    let reach = lengths.iter().fold(0.0_f64, |m, l| m.max(l.abs()));
    if reach == 0.0 {
        return Err(ArmError::Singular {
            measure: 0.0,
            threshold: 0.0,
        });
    }
    let mut pair_scale = 0.0;
    let mut before = 0.0;
    for l in &lengths[..N - 1] {
        pair_scale += before * (l.abs() / reach);
        before += l.abs() / reach;
    }
    // Left to right, so that a zero factor wins over an infinite `reach * reach`.
    let threshold = SINGULAR_THRESHOLD * pair_scale * reach * reach;
    let singular = |measure: f64| ArmError::Singular { measure, threshold };
    if SINGULAR_THRESHOLD * pair_scale == 0.0 {
        // At most one of the links before the last has a length: the joints occupy at most two
        // points, always on a line.
        return Err(singular(0.0));
    }
    // Joint positions p_i (p_0 at the base) and the tip, the absolute angles composed exactly.
    let mut joints = [Vector2::<f64>::zeros(); N];
    let (mut s, mut c) = (0.0, 1.0);
    let mut at = Vector2::zeros();
    for k in 0..N {
        joints[k] = at;
        (s, c) = angle_sum((s, c), q[k].sin_cos());
        at += Vector2::new(c, s) * (lengths[k] / reach);
    }
    let tip = at;
    // tau_i = T + d_i x F with d_i = tip - p_i. The column of ones (T) is fitted by centring:
    // about the centroid p, tau_i - mean(tau) = (p - p_i) x F, and T = mean(tau) - (tip - p) x F.
    let count = N as f64;
    let centroid = joints.iter().sum::<Vector2<f64>>() / count;
    let scale = tau.amax();
    let t = if scale > 0.0 { tau / scale } else { *tau };
    let t_mean = t.sum() / count;
    // (p - p_i) x F = -(p - p_i).y u + (p - p_i).x v: the columns of the 2-unknown problem.
    let col_u = SVector::<f64, N>::from_fn(|i, _| -(centroid.y - joints[i].y));
    let col_v = SVector::<f64, N>::from_fn(|i, _| centroid.x - joints[i].x);
    // Modified Gram-Schmidt with the right-hand side as a third column (backward stable).
    let r11 = col_u.norm();
    if r11 == 0.0 {
        return Err(singular(0.0));
    }
    let q1 = col_u / r11;
    let r12 = q1.dot(&col_v);
    let rest = col_v - q1 * r12;
    let r22 = rest.norm();
    // Compared in units of the longest link, where neither side can overflow or underflow.
    let relative = count.sqrt() * r11 * r22;
    let measure = relative * reach * reach;
    if relative.is_nan() || relative < SINGULAR_THRESHOLD * pair_scale || r22 == 0.0 {
        return Err(singular(measure));
    }
    let q2 = rest / r22;
    let mut y = t.add_scalar(-t_mean);
    let b1 = q1.dot(&y);
    y -= q1 * b1;
    let b2 = q2.dot(&y);
    y -= q2 * b2;
    let v = b2 / r22;
    let u = (b1 - r12 * v) / r11;
    let lever = tip - centroid;
    let torque = t_mean - (lever.x * v - lever.y * u);
    let force = Vector2::new(u, v) * (scale / reach);
    let torque = torque * scale;
    let residual = y * scale;
    if force.iter().chain([torque].iter()).any(|x| x.is_nan()) {
        return Err(singular(measure));
    }
    finite_result(force.iter().chain(residual.iter()).copied().chain([torque]))?;
    Ok(StaticWrench {
        force: if scale > 0.0 { force } else { Vector2::zeros() },
        torque: if scale > 0.0 { torque } else { 0.0 },
        residual: if scale > 0.0 {
            residual
        } else {
            SVector::zeros()
        },
    })
}

/// [`inverse_statics`] for an arm of any mix of revolute and prismatic joints, from its links:
/// the tip wrench `(F, T)` with `J^T (F, T) = tau` in the least-squares sense, and the part of
/// `tau` it leaves unbalanced.
///
/// A revolute joint's generalised force is a torque, `tau_i = T + (tip - o_i) x F` (N m); a
/// prismatic joint's is a force, `tau_i = F . u_{i-1}`, the tip force along the direction it
/// slides (N). For revolute links this is [`inverse_statics`] of their lengths, to the bit.
/// With a prismatic joint:
///
/// The equations are made dimensionless first: a hinge's row of `J^T` and its torque are
/// divided by the arm's reach `L = sum |l_i| + sum over slides |q_i|` (the longest lever any
/// joint has), and the tip torque is solved for as `T / L`; a slide's row stays as it is.
///
/// - three or more joints: the least-squares wrench of those equations (so a hinge's
///   unbalanced torque counts as that torque over `L`, a force like a slide's), by a
///   Gram-Schmidt QR (no normal equations, no heap); `residual` is in each joint's own unit
///   (N m or N). Singular when the scaled `J^T`, whose entries are at most about 1, has
///   `measure = sqrt(det)` of its Gram matrix below `threshold = SINGULAR_THRESHOLD`; an arm
///   of sliders alone never feels a tip torque and is always singular;
/// - two joints: no tip torque (`T = 0`, as the paper takes it for two links) and the force
///   that balances both, singular when the scaled 2 x 2 determinant is below
///   `SINGULAR_THRESHOLD` (for the polar arm: the tip at the base);
/// - one prismatic joint: the force along the slide.
///
/// # Errors
/// [`ArmError::NonFinite`] (`"lengths"`, `"q"`, `"tau"`, or `"result"` on overflow);
/// [`ArmError::Singular`] as above.
///
/// # Example
/// ```
/// use planar_arm::kinematics::inverse_statics_of;
/// use planar_arm::nalgebra::Vector2;
/// use planar_arm::{Joint, Link};
///
/// // The polar arm pointing along +y, the slide 0.3 m out: the tip 1 m from the base.
/// let polar = [Link::rod(0.2, 1.0), Link::rod(0.5, 1.0).with_joint(Joint::Prismatic)];
/// let q = Vector2::new(std::f64::consts::FRAC_PI_2, 0.3);
/// // 2 N m at the hinge and 5 N on the slide: a force of 2 N across the arm, 5 N along it.
/// let w = inverse_statics_of(&polar, &q, &Vector2::new(2.0, 5.0)).unwrap();
/// assert!((w.force - Vector2::new(-2.0, 5.0)).norm() < 1e-12 && w.torque == 0.0);
/// ```
pub fn inverse_statics_of<const N: usize>(
    links: &[Link; N],
    q: &SVector<f64, N>,
    tau: &SVector<f64, N>,
) -> Result<StaticWrench<N>, ArmError> {
    let lengths = links.map(|l| l.length);
    if links.iter().all(|l| l.joint == Joint::Revolute) {
        return inverse_statics(&lengths, q, tau);
    }
    check_lengths(&lengths)?;
    check_vector(q, "q")?;
    check_vector(tau, "tau")?;
    let j = jacobian_of(links, q);
    finite_result(j.iter().copied())?;
    // The largest lever any joint can have: the links and the slides.
    let reach: f64 = links
        .iter()
        .zip(q.iter())
        .map(|(l, qi)| {
            l.length.abs()
                + if l.joint == Joint::Prismatic {
                    qi.abs()
                } else {
                    0.0
                }
        })
        .sum();
    let singular = |measure: f64| ArmError::Singular {
        measure: if measure.is_nan() { 0.0 } else { measure },
        threshold: SINGULAR_THRESHOLD,
    };
    if reach == 0.0 {
        return Err(singular(0.0));
    }
    // Dimensionless rows: a hinge's (-(dy), dx, 1) divided by the reach (its torque by it too,
    // the tip torque taken per unit reach), a slide's (ux, uy, 0) as it is.
    let revolute = |i: usize| links[i].joint == Joint::Revolute;
    let row_scale = |i: usize| if revolute(i) { 1.0 / reach } else { 1.0 };
    let scale = tau.amax();
    let t = SVector::<f64, N>::from_fn(|i, _| {
        let ti = if scale > 0.0 { tau[i] / scale } else { tau[i] };
        ti * row_scale(i)
    });
    let entry = |i: usize, k: usize| {
        if k < 2 {
            j[(k, i)] * row_scale(i)
        } else {
            j[(2, i)]
        }
    };
    let none = SVector::<f64, N>::zeros();
    let (force, torque, residual) = match N {
        0 => (Vector2::zeros(), 0.0, none),
        1 => (Vector2::new(j[(0, 0)], j[(1, 0)]) * t[0], 0.0, none),
        2 => {
            let (a, b, c, d) = (entry(0, 0), entry(0, 1), entry(1, 0), entry(1, 1));
            let det = a * d - b * c;
            if det.is_nan() || det.abs() < SINGULAR_THRESHOLD {
                return Err(singular(det));
            }
            // (a, b) . F = t0, (c, d) . F = t1.
            let force = Vector2::new(d * t[0] - b * t[1], a * t[1] - c * t[0]) / det;
            (force, 0.0, none)
        }
        _ => {
            let columns: [SVector<f64, N>; 3] =
                core::array::from_fn(|k| SVector::from_fn(|i, _| entry(i, k)));
            let r11 = columns[0].norm();
            let q1 = columns[0] / r11;
            let r12 = q1.dot(&columns[1]);
            let r13 = q1.dot(&columns[2]);
            let a2 = columns[1] - q1 * r12;
            let r22 = a2.norm();
            let q2 = a2 / r22;
            let a3 = columns[2] - q1 * r13;
            let r23 = q2.dot(&a3);
            let a3 = a3 - q2 * r23;
            let r33 = a3.norm();
            let q3 = a3 / r33;
            let measure = r11 * r22 * r33;
            if measure.is_nan() || measure < SINGULAR_THRESHOLD {
                return Err(singular(measure));
            }
            let mut y = t;
            let b1 = q1.dot(&y);
            y -= q1 * b1;
            let b2 = q2.dot(&y);
            y -= q2 * b2;
            let b3 = q3.dot(&y);
            y -= q3 * b3;
            let torque = b3 / r33 * reach;
            let fy = (b2 - r23 * (b3 / r33)) / r22;
            let fx = (b1 - r12 * fy - r13 * (b3 / r33)) / r11;
            let residual = SVector::<f64, N>::from_fn(|i, _| y[i] / row_scale(i));
            (Vector2::new(fx, fy), torque, residual)
        }
    };
    let (force, torque, residual) = (force * scale, torque * scale, residual * scale);
    if force.iter().chain([torque].iter()).any(|x| x.is_nan()) {
        return Err(ArmError::Singular {
            measure: 0.0,
            threshold: 0.0,
        });
    }
    finite_result(force.iter().chain(residual.iter()).copied().chain([torque]))?;
    Ok(StaticWrench {
        force,
        torque,
        residual,
    })
}

/// Inverse statics for every arm, from its run-time link lengths: implemented for every
/// [`PlanarArm<N>`](crate::PlanarArm).
pub trait InverseStatics<const N: usize> {
    /// The least-squares tip wrench with the torques it leaves unbalanced:
    /// [`inverse_statics_of`] the arm's [`links`](crate::PlanarArm::links) (so run-time
    /// lengths are read at the call, and prismatic joints, whose generalised force is a force
    /// in newtons, count as such); for revolute links, [`inverse_statics`] of their lengths.
    ///
    /// # Errors
    /// As [`inverse_statics_of`].
    ///
    /// # Example
    /// ```
    /// use planar_arm::kinematics::InverseStatics;
    /// use planar_arm::prelude::*;
    ///
    /// #[derive(PlanarArm)]
    /// struct Four {
    ///     #[arm(length = 1, mass = 1)] a: Revolute,
    ///     #[arm(length = 1, mass = 1)] b: Revolute,
    ///     #[arm(length = 0.5, mass = 1)] c: Revolute,
    ///     #[arm(length = 0.5, mass = 1)] d: Revolute,
    /// }
    /// let arm = Four { a: Revolute, b: Revolute, c: Revolute, d: Revolute };
    /// let q = SVector::<f64, 4>::new(0.3, 0.9, -0.4, 1.1);
    /// let tau = arm.joint_torques(&q, &Vector2::new(1.0, -2.0), 0.25);
    /// let w = arm.inverse_statics(&q, &tau).unwrap();
    /// assert!((w.force - Vector2::new(1.0, -2.0)).norm() < 1e-12 && (w.torque - 0.25).abs() < 1e-12);
    /// assert!(w.residual.norm() < 1e-12);
    /// ```
    fn inverse_statics(
        &self,
        q: &SVector<f64, N>,
        tau: &SVector<f64, N>,
    ) -> Result<StaticWrench<N>, ArmError>;
}

impl<A: crate::PlanarArm<N> + ?Sized, const N: usize> InverseStatics<N> for A {
    fn inverse_statics(
        &self,
        q: &SVector<f64, N>,
        tau: &SVector<f64, N>,
    ) -> Result<StaticWrench<N>, ArmError> {
        inverse_statics_of(&self.links(), q, tau)
    }
}

/// `tip_wrench` for arms of 4 to 64 links, as [`TipWrench`] has it for three: the force and
/// torque the tip exerts, from the joint torques.
///
/// It is a separate trait, implemented for each `PlanarArm<N>` with `4 <= N <= 64` (not for
/// three links, whose derived [`TipWrench`] it would make ambiguous), so `arm.tip_wrench(&q,
/// &tau)` reads the same for every arm of three or more links.
pub trait RedundantTipWrench<const N: usize> {
    /// The force `F` and torque `T` with `J^T (F, T) = tau`.
    ///
    /// With more joints than the three components of a wrench, only torques in the range of
    /// `J^T` come from a tip wrench: this returns [`inverse_statics_of`]'s least-squares wrench
    /// (for an arm with prismatic joints, whose generalised forces are forces, in newtons)
    /// when the torques it leaves unbalanced have norm at most
    /// `UNBALANCED_TOLERANCE * |tau|` (rounding), and an error otherwise. For the best wrench
    /// whatever the residual (torques measured with noise), use
    /// [`InverseStatics::inverse_statics`].
    ///
    /// # Errors
    /// [`ArmError::Unbalanced`] as above; otherwise as [`inverse_statics`]
    /// ([`ArmError::Singular`] when all joints lie on one line, [`ArmError::NonFinite`]).
    ///
    /// # Example
    /// ```
    /// use planar_arm::kinematics::RedundantTipWrench;
    /// use planar_arm::prelude::*;
    ///
    /// #[derive(PlanarArm)]
    /// struct Four {
    ///     #[arm(length = 1, mass = 1)] a: Revolute,
    ///     #[arm(length = 1, mass = 1)] b: Revolute,
    ///     #[arm(length = 0.5, mass = 1)] c: Revolute,
    ///     #[arm(length = 0.5, mass = 1)] d: Revolute,
    /// }
    /// let arm = Four { a: Revolute, b: Revolute, c: Revolute, d: Revolute };
    /// let q = SVector::<f64, 4>::new(0.3, 0.9, -0.4, 1.1);
    /// let tau = arm.joint_torques(&q, &Vector2::new(1.0, -2.0), 0.25);
    /// let (force, torque) = arm.tip_wrench(&q, &tau).unwrap();
    /// assert!((force - Vector2::new(1.0, -2.0)).norm() < 1e-12 && (torque - 0.25).abs() < 1e-12);
    /// // Folding torques are balanced by no tip wrench.
    /// let fold = SVector::<f64, 4>::new(1.0, -1.0, 1.0, -1.0);
    /// assert!(matches!(arm.tip_wrench(&q, &fold), Err(ArmError::Unbalanced { .. })));
    /// // Stretched straight, the joints lie on a line.
    /// let straight = SVector::<f64, 4>::zeros();
    /// assert!(matches!(arm.tip_wrench(&straight, &tau), Err(ArmError::Singular { .. })));
    /// ```
    fn tip_wrench(
        &self,
        q: &SVector<f64, N>,
        tau: &SVector<f64, N>,
    ) -> Result<(Vector2<f64>, f64), ArmError>;
}

/// [`RedundantTipWrench::tip_wrench`] for links.
fn balanced_wrench<const N: usize>(
    links: &[Link; N],
    q: &SVector<f64, N>,
    tau: &SVector<f64, N>,
) -> Result<(Vector2<f64>, f64), ArmError> {
    let w = inverse_statics_of(links, q, tau)?;
    let (residual, tolerance) = (w.residual.norm(), UNBALANCED_TOLERANCE * tau.norm());
    if residual > tolerance {
        return Err(ArmError::Unbalanced {
            residual,
            tolerance,
        });
    }
    Ok((w.force, w.torque))
}

macro_rules! redundant_tip_wrench {
    ($($n:literal)*) => {$(
        impl<A: crate::PlanarArm<$n> + ?Sized> RedundantTipWrench<$n> for A {
            fn tip_wrench(
                &self,
                q: &SVector<f64, $n>,
                tau: &SVector<f64, $n>,
            ) -> Result<(Vector2<f64>, f64), ArmError> {
                balanced_wrench(&self.links(), q, tau)
            }
        }
    )*};
}

redundant_tip_wrench!(
    4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27 28 29 30 31 32 33 34 35
    36 37 38 39 40 41 42 43 44 45 46 47 48 49 50 51 52 53 54 55 56 57 58 59 60 61 62 63 64
);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::test_support::{fk_joints, jacobian, Rng, PAIRS, TRIPLES};
    use core::f64::consts::{PI, TAU};
    use nalgebra::{Matrix2, Matrix3, Vector3};

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

    /// `J^T (F, T)` with `J` from central differences of the independent forward kinematics.
    fn generalised_forces<const N: usize>(
        kinds: &[Joint; N],
        lengths: &[f64; N],
        q: &SVector<f64, N>,
        w: Vector3<f64>,
    ) -> SVector<f64, N> {
        SVector::from_fn(|i, _| {
            let h = 1e-6;
            let (mut qp, mut qm) = (*q, *q);
            qp[i] += h;
            qm[i] -= h;
            let (xp, yp, pp) = fk_joints(kinds, lengths, qp.as_slice());
            let (xm, ym, pm) = fk_joints(kinds, lengths, qm.as_slice());
            Vector3::new(xp - xm, yp - ym, pp - pm).dot(&w) / (2.0 * h)
        })
    }

    fn mixed_case<const N: usize>(kinds: [Joint; N], lengths: [f64; N], rng: &mut Rng) {
        let links: [Link; N] =
            core::array::from_fn(|i| Link::rod(lengths[i], 1.0).with_joint(kinds[i]));
        let mut solved = 0;
        for _ in 0..500 {
            let q = SVector::<f64, N>::from_fn(|_, _| rng.range(-2.0, 2.0));
            let f = random_force(rng);
            let t = if N >= 3 { rng.range(-3.0, 3.0) } else { 0.0 };
            let tau = generalised_forces(&kinds, &lengths, &q, Vector3::new(f.x, f.y, t));
            match inverse_statics_of(&links, &q, &tau) {
                Ok(w) => {
                    solved += 1;
                    let scale = tau.norm().max(1.0);
                    let again = generalised_forces(
                        &kinds,
                        &lengths,
                        &q,
                        Vector3::new(w.force.x, w.force.y, w.torque),
                    );
                    assert!((again - tau).norm() < 1e-6 * scale);
                    // One slide determines only the force along it.
                    let expected = if N == 1 { Vector2::new(f.x, 0.0) } else { f };
                    assert!(
                        (w.force - expected).norm() < 1e-6 * scale,
                        "{kinds:?}: {f} came back as {}",
                        w.force
                    );
                    assert!((w.torque - t).abs() < 1e-6 * scale);
                    assert!(w.residual.norm() < 1e-6 * scale);
                    if N > 3 {
                        // Torques from no wrench: the residual is what J^T w cannot explain.
                        let noise = SVector::<f64, N>::from_fn(|_, _| rng.range(-1.0, 1.0));
                        let w = inverse_statics_of(&links, &q, &noise).unwrap();
                        let j = jacobian_of(&links, &q);
                        // Orthogonal to the range of J^T in the metric of the scaled rows:
                        // a hinge's by the reach squared.
                        let reach: f64 = (0..N)
                            .map(|i| {
                                lengths[i].abs()
                                    + if kinds[i] == Joint::Prismatic {
                                        q[i].abs()
                                    } else {
                                        0.0
                                    }
                            })
                            .sum();
                        let weighted = SVector::<f64, N>::from_fn(|i, _| {
                            w.residual[i]
                                / if kinds[i] == Joint::Revolute {
                                    reach * reach
                                } else {
                                    1.0
                                }
                        });
                        assert!((j * weighted).norm() < 1e-9, "residual not orthogonal");
                        let explained =
                            j.transpose() * Vector3::new(w.force.x, w.force.y, w.torque);
                        assert!((explained + w.residual - noise).norm() < 1e-9);
                    }
                }
                Err(ArmError::Singular { .. }) => {}
                Err(e) => panic!("{e:?}"),
            }
        }
        assert!(solved > 450, "{kinds:?}: {solved} of 500");
    }

    #[test]
    fn inverse_statics_of_any_mix_inverts_the_transposed_jacobian() {
        let mut rng = Rng(30);
        let (r, p) = (Joint::Revolute, Joint::Prismatic);
        mixed_case([p], [0.5], &mut rng);
        mixed_case([r, p], [0.2, 0.5], &mut rng);
        mixed_case([p, r], [0.3, 0.5], &mut rng);
        mixed_case([p, r, r], [0.2, 0.6, 0.3], &mut rng);
        mixed_case([r, p, r], [0.4, 0.5, 0.3], &mut rng);
        mixed_case([r, p, r, p], [0.4, 1.0, 0.3, 0.2], &mut rng);
        mixed_case([p, r, r, r, r], [0.2, 0.5, 0.4, 0.3, 0.2], &mut rng);
        // Revolute links: exactly inverse_statics.
        let links = [
            Link::rod(1.0, 1.0),
            Link::rod(0.5, 1.0),
            Link::rod(0.25, 1.0),
            Link::rod(0.5, 1.0),
        ];
        let q = SVector::<f64, 4>::new(0.3, 0.9, -0.4, 1.1);
        let tau = SVector::<f64, 4>::new(1.0, -0.5, 0.25, 2.0);
        assert_eq!(
            inverse_statics_of(&links, &q, &tau),
            inverse_statics(&[1.0, 0.5, 0.25, 0.5], &q, &tau)
        );
        // The polar arm with its tip at the base: no force balances the hinge.
        let polar = [Link::rod(0.2, 1.0), Link::rod(0.5, 1.0).with_joint(p)];
        assert!(matches!(
            inverse_statics_of(&polar, &Vector2::new(0.3, -0.7), &Vector2::new(1.0, 1.0)),
            Err(ArmError::Singular { .. })
        ));
        // Sliders alone feel no tip torque.
        let sliders = [
            Link::rod(0.2, 1.0).with_joint(p),
            Link::rod(0.2, 1.0).with_joint(p),
            Link::rod(0.2, 1.0).with_joint(p),
        ];
        assert!(matches!(
            inverse_statics_of(
                &sliders,
                &Vector3::new(0.1, 0.2, 0.3),
                &Vector3::new(1.0, 1.0, 1.0)
            ),
            Err(ArmError::Singular { .. })
        ));
        assert_eq!(
            inverse_statics_of(&polar, &Vector2::new(f64::NAN, 0.0), &Vector2::zeros()),
            Err(ArmError::NonFinite { argument: "q" })
        );
    }

    #[test]
    fn singular_configurations_are_rejected() {
        let (l1, l2, l3) = (1.0, 0.5, 0.25);
        for q2 in [0.0, PI, -PI, 1e-12, PI - 1e-12, TAU, 0.5e-9] {
            let expected = Err(ArmError::Singular {
                measure: l1 * l2 * f64::sin(q2),
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
}
