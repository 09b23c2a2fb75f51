//! Inverse statics in the least-squares sense, for any number of links and any mix of joints:
//! the tip wrench that best balances the joint torques, and the torques it leaves unbalanced.
//!
//! Apart from the closed forms because with more than three joints (or a prismatic one) the
//! wrench no longer follows from a fixed 3 x 3 inverse: it is fitted by a Gram-Schmidt QR of
//! `J^T`, and the residual and its tolerance ([`UNBALANCED_TOLERANCE`]) are part of the answer.

use nalgebra::{SVector, Vector2};
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use super::{angle_sum, finite_result, tip_force2, SINGULAR_THRESHOLD};
#[cfg(doc)]
use super::{tip_wrench3, TipWrench};
use crate::kinematics::{check_lengths, check_vector, jacobian_of};
use crate::{ArmError, Joint, Link};

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
/// `sqrt(det(J J^T))` (the [`manipulability`](crate::kinematics::manipulability), `|l1 l2 sin q2|`
/// for three links), the threshold `SINGULAR_THRESHOLD * sum_{i < j < N} |l_i l_j|` over the links
/// but the last (`SINGULAR_THRESHOLD |l1 l2|` for three links, the rule of [`tip_wrench3`]).
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
    /// let w = arm.tip_wrench(&q, &tau).unwrap();
    /// assert!((w.force - Vector2::new(1.0, -2.0)).norm() < 1e-12 && (w.torque - 0.25).abs() < 1e-12);
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
    ) -> Result<StaticWrench<N>, ArmError>;
}

/// [`RedundantTipWrench::tip_wrench`] for links.
fn balanced_wrench<const N: usize>(
    links: &[Link; N],
    q: &SVector<f64, N>,
    tau: &SVector<f64, N>,
) -> Result<StaticWrench<N>, ArmError> {
    let w = inverse_statics_of(links, q, tau)?;
    let (residual, tolerance) = (w.residual.norm(), UNBALANCED_TOLERANCE * tau.norm());
    if residual > tolerance {
        return Err(ArmError::Unbalanced {
            residual,
            tolerance,
        });
    }
    Ok(w)
}

macro_rules! redundant_tip_wrench {
    ($($n:literal)*) => {$(
        impl<A: crate::PlanarArm<$n> + ?Sized> RedundantTipWrench<$n> for A {
            fn tip_wrench(
                &self,
                q: &SVector<f64, $n>,
                tau: &SVector<f64, $n>,
            ) -> Result<StaticWrench<$n>, ArmError> {
                balanced_wrench(&self.links(), q, tau)
            }
        }
    )*};
}

redundant_tip_wrench!(
    4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27 28 29 30 31 32 33 34 35
    36 37 38 39 40 41 42 43 44 45 46 47 48 49 50 51 52 53 54 55 56 57 58 59 60 61 62 63 64
);
