//! [`lqr`] and [`dlqr`]: the infinite-horizon linear-quadratic regulator of a continuous pair
//! `(A, B)`, as [`Linearize::linearize`](crate::Linearize::linearize) gives it, and of a
//! discrete one, as [`Linearize::discretize`](crate::Linearize::discretize) gives it.
//!
//! The algorithm and its checks are documented on [`Lqr`], the public home of the concept.

mod checks;
mod eigen;
mod equations;

use nalgebra::{Complex, Const, SMatrix, SVector};
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use crate::ArmError;
use checks::{check_modes, Weights};
pub use eigen::EigenSize;
use equations::{cayley, doubling, lyapunov};

/// The largest relative Riccati residual accepted: `sqrt(eps)`, a hundred times the `1e-10` of
/// the worst-conditioned pairs tested, far below a wrong answer's.
const RESIDUAL_TOLERANCE: f64 = 1.5e-8;

/// Newton steps at most after doubling (one is usually all it takes).
const MAX_REFINEMENTS: usize = 3;

/// A linear-quadratic regulator: the gain of the control `u = -K x` that minimises
/// `integral (x^T Q x + u^T R u) dt` ([`lqr`]) or `sum_k (x_k^T Q x_k + u_k^T R u_k)`
/// ([`dlqr`]), with its cost-to-go and closed-loop poles.
///
/// `x` and `u` are deviations from the operating point the pair was linearised at: for an arm,
/// `tau = tau* - K (x - x*)` with `x = (q, qd)`.
///
/// # The algorithm, and why
///
/// Both Riccati equations are solved by the structure-preserving doubling algorithm (SDA; E. K.
/// Chu, H. Y. Fan, W. W. Lin, *A structure-preserving doubling algorithm for continuous-time
/// algebraic Riccati equations*, Linear Algebra Appl. 396 (2005), and its discrete-time
/// companion), then polished by Newton's method:
///
/// 1. For the discrete equation the k-th doubling iterate is the optimal cost of the horizon
///    `2^k`: value iteration that doubles the horizon at each step. It starts from `P = Q`,
///    needs no stabilising gain, and converges quadratically once the horizon outlasts the
///    slowest closed-loop pole (11 steps for the two-link arm at 10 ms, at most 13 on random
///    pairs).
///    The continuous equation is first mapped to a discrete one by the Cayley transform
///    `(H + g I)(H - g I)^-1` of its Hamiltonian `H`, which sends the left half-plane into the
///    unit disc and keeps the stable invariant subspace, so the same iteration solves both.
/// 2. Doubling is not backward stable: its iterates grow with the transformed pencil's
///    non-normality, and on ill-conditioned random pairs its residual reached `2e-8`. Up to
///    three Newton steps follow (Kleinman's; Hewer's in discrete time), each a Lyapunov or
///    Stein equation in the closed loop solved by Bartels and Stewart's method on its complex
///    Schur form, kept only while they lower the residual. After them it is about `1e-16`
///    (median of 700 random pairs), below `1e-13` on well-conditioned pairs, and up to `1e-10`
///    where `P` is a million times `Q` (a nearly uncontrollable mode), near the rounding of the
///    residual itself.
///
/// The alternatives were weighed:
/// - the Schur method (Laub) and the matrix sign function work on the `2S x 2S` Hamiltonian
///   or symplectic matrix, a size stable Rust cannot name from a const generic `S`, and
///   nalgebra has no reordered Schur form to pick the stable subspace;
/// - Newton's method alone needs a stabilising gain to start from, which for an unstable `A`
///   is the problem itself; here SDA supplies it;
/// - plain value iteration (what `examples/balance.rs` did) converges linearly at the rate of
///   the slowest closed-loop pole squared: 600 to 700 steps there.
///
/// Everything works on `S x S` matrices, allocates nothing and builds without `std`. The
/// result is not trusted on the iteration's word: the doubling must converge (relative change
/// of the iterate below `1e-13`), the Riccati equation's relative residual, computed from the
/// final `P`, must be below `1.5e-8` (about `sqrt(eps)`), and the closed-loop eigenvalues must
/// be stable. The residual and the number of doublings are returned.
///
/// # When there is no solution
///
/// The stabilising solution exists, and SDA converges to it, when `(A, B)` is stabilisable and
/// `(Q, A)` detectable: every mode of `A` on or beyond the stability boundary (the imaginary
/// axis, the unit circle) must be moved by the input and weighed by the cost. Both are checked
/// before iterating, by the Popov-Belevitch-Hautus test at each such eigenvalue `s`: the mode
/// is taken as unmoved when the smallest singular value of `[A - s I, B]` (with `B` scaled to
/// the norm of `A - s I`) is below `1e-8` of that matrix's norm, and likewise for
/// `[A^T - s I, C^T]`, `C^T C = Q`. Such a pair gives [`ArmError::NotStabilizable`] naming the
/// mode. An unstable mode that `Q` does not weigh is refused even though some gain stabilises
/// it: the optimal control leaves it alone (it costs nothing), doubling from `Q` would find
/// that non-stabilising optimum, and what you want is a weight on the mode in `Q`.
///
/// # Example
/// ```
/// use planar_arm::nalgebra::{Matrix1, Matrix2, Vector2};
///
/// // A unit mass pushed by a force: x = (position, velocity).
/// let a = Matrix2::new(0.0, 1.0, 0.0, 0.0);
/// let b = Vector2::new(0.0, 1.0);
/// let lqr = planar_arm::lqr(&a, &b, &Matrix2::identity(), &Matrix1::new(1.0))?;
/// let x = Vector2::new(1.0, 0.0);
/// let u = -lqr.gain * x; // the force that brings it back
/// assert!(u[0] < 0.0);
/// // The cost of the whole return from x, here sqrt(3).
/// let cost = (x.transpose() * lqr.cost_to_go * x)[0];
/// assert!((cost - 3f64.sqrt()).abs() < 1e-12);
/// assert!(lqr.closed_loop_eigenvalues.iter().all(|s| s.re < 0.0));
/// # Ok::<(), planar_arm::ArmError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Lqr<const S: usize, const M: usize> {
    /// `K`, `M x S`: the optimal input is `u = -K x`.
    pub gain: SMatrix<f64, M, S>,
    /// `P`, symmetric positive semidefinite: the optimal cost from state `x` is `x^T P x`.
    /// The stabilising solution of the Riccati equation.
    pub cost_to_go: SMatrix<f64, S, S>,
    /// The eigenvalues of `A - B K`: in the open left half-plane ([`lqr`]) or inside the unit
    /// circle ([`dlqr`]), in no particular order.
    pub closed_loop_eigenvalues: SVector<Complex<f64>, S>,
    /// The Riccati equation's residual at `P`, relative to the sum of the norms of its terms
    /// (Frobenius norms): about `1e-16` on well-conditioned pairs, up to `1e-10` on
    /// ill-conditioned ones, never above `1.5e-8` (that is an error).
    pub residual: f64,
    /// Doubling steps taken (step k covers the horizon `2^k` of the discrete iteration); the
    /// Newton steps after them are not counted.
    pub iterations: usize,
}

/// The continuous-time LQR: the `K` of `u = -K x` that minimises
/// `integral_0^inf (x^T Q x + u^T R u) dt` subject to `xd = A x + B u`, from the stabilising
/// solution `P` of `A^T P + P A - P B R^-1 B^T P + Q = 0`; `K = R^-1 B^T P`.
///
/// `Q` must be symmetric positive semidefinite, `R` symmetric positive definite (each to a
/// relative asymmetry of `1e-10`, then symmetrised). State size `S` and input count `M` are
/// independent: one input of a two-link arm is `B * drive` with `drive` `2 x 1`.
/// `Const<S>: EigenSize<S>` holds for every fixed size; write it only in code generic over
/// `S`. See [`Lqr`] for the algorithm (structured doubling after a Cayley transform, then
/// Newton steps) and its checks.
///
/// # Errors
/// - [`ArmError::NonFinite`] for NaN or infinite input (`"a"`, `"b"`, `"q"`, `"r"`), or
///   (`"result"`) finite input so large that the iteration overflowed;
/// - [`ArmError::OutOfRange`] for an asymmetric weight, `Q` with a negative eigenvalue, `R`
///   not positive definite (the value is the offending quantity);
/// - [`ArmError::NotStabilizable`] when a mode in the closed right half-plane is not moved by
///   `B` or not weighed by `Q`;
/// - [`ArmError::NoConvergence`] when the iteration or the check of its result fails (a pair
///   within rounding of one of the above).
///
/// # Example
/// Balancing two rods upright with both joints driven:
/// ```
/// use planar_arm::nalgebra::{Matrix2, Matrix4, Vector2};
/// use planar_arm::prelude::*;
///
/// #[derive(PlanarArm, Default)]
/// #[arm(gravity = 9.81)]
/// struct Rods {
///     #[arm(length = 1, mass = 1)]
///     upper: Revolute,
///     #[arm(length = 1, mass = 1)]
///     fore: Revolute,
/// }
///
/// let arm = Rods::default();
/// let up = Vector2::new(core::f64::consts::FRAC_PI_2, 0.0);
/// let (a, b) = arm.linearize(&up, &Vector2::zeros(), &arm.gravity(&up));
/// // Upright falls: A has eigenvalues in the right half-plane.
/// assert!(a.complex_eigenvalues().iter().any(|s| s.re > 2.0));
/// let lqr = planar_arm::lqr(&a, &b, &Matrix4::identity(), &Matrix2::identity())?;
/// assert!(lqr.closed_loop_eigenvalues.iter().all(|s| s.re < 0.0));
/// assert!(lqr.residual < 1e-12);
/// // Tipped forward (q1 below pi/2), the shoulder pushes back up.
/// let tau = -lqr.gain * planar_arm::nalgebra::Vector4::new(-0.1, 0.0, 0.0, 0.0);
/// assert!(tau[0] > 0.0);
/// # Ok::<(), ArmError>(())
/// ```
pub fn lqr<const S: usize, const M: usize>(
    a: &SMatrix<f64, S, S>,
    b: &SMatrix<f64, S, M>,
    q: &SMatrix<f64, S, S>,
    r: &SMatrix<f64, M, M>,
) -> Result<Lqr<S, M>, ArmError>
where
    Const<S>: EigenSize<S>,
{
    continuous(a, b, q, r)
}

/// The discrete-time LQR: the `K` of `u_k = -K x_k` that minimises
/// `sum_{k >= 0} (x_k^T Q x_k + u_k^T R u_k)` subject to `x_{k+1} = A x_k + B u_k`, from the
/// stabilising solution `P` of `P = A^T P A - A^T P B (R + B^T P B)^-1 B^T P A + Q`;
/// `K = (R + B^T P B)^-1 B^T P A`.
///
/// For an arm, `(A, B)` is the zero-order-hold pair of
/// [`Linearize::discretize`](crate::Linearize::discretize) and the control is held for the
/// period. Requirements, bounds and errors as for [`lqr`], with the unit circle as the
/// stability boundary.
///
/// # Errors
/// As [`lqr`]: [`ArmError::NonFinite`], [`ArmError::OutOfRange`],
/// [`ArmError::NotStabilizable`] (a mode with `|z| >= 1` not moved by `B` or not weighed by
/// `Q`), [`ArmError::NoConvergence`].
///
/// # Example
/// The scalar equation has a closed form: for `x+ = 2 x + u` and unit weights,
/// `P = 2 + sqrt(5)` and the closed loop is `(3 - sqrt(5)) / 2`.
/// ```
/// use planar_arm::nalgebra::Matrix1;
///
/// let one = Matrix1::new(1.0);
/// let lqr = planar_arm::dlqr(&Matrix1::new(2.0), &one, &one, &one)?;
/// assert!((lqr.cost_to_go[0] - (2.0 + 5f64.sqrt())).abs() < 1e-14);
/// assert!((lqr.closed_loop_eigenvalues[0].re - (3.0 - 5f64.sqrt()) / 2.0).abs() < 1e-14);
///
/// // An unstable mode the input cannot reach has no stabilising gain.
/// use planar_arm::nalgebra::{Matrix2, Vector2};
/// let a = Matrix2::new(2.0, 0.0, 0.0, 0.5);
/// let b = Vector2::new(0.0, 1.0);
/// let e = planar_arm::dlqr(&a, &b, &Matrix2::identity(), &one).unwrap_err();
/// assert!(matches!(e, planar_arm::ArmError::NotStabilizable { eigenvalue: [2.0, 0.0], .. }));
/// # Ok::<(), planar_arm::ArmError>(())
/// ```
pub fn dlqr<const S: usize, const M: usize>(
    a: &SMatrix<f64, S, S>,
    b: &SMatrix<f64, S, M>,
    q: &SMatrix<f64, S, S>,
    r: &SMatrix<f64, M, M>,
) -> Result<Lqr<S, M>, ArmError>
where
    Const<S>: EigenSize<S>,
{
    discrete(a, b, q, r)
}

/// [`lqr`]'s work.
fn continuous<const S: usize, const M: usize>(
    a: &SMatrix<f64, S, S>,
    b: &SMatrix<f64, S, M>,
    q: &SMatrix<f64, S, S>,
    r: &SMatrix<f64, M, M>,
) -> Result<Lqr<S, M>, ArmError>
where
    Const<S>: EigenSize<S>,
{
    let w = Weights::new(a, b, q, r)?;
    check_modes(a, b, &w.q_root, false)?;
    let (a0, g0, h0) = cayley(a, &w.g, &w.q)?;
    let (p, iterations) = doubling(a0, g0, h0)?;
    let at = |p: SMatrix<f64, S, S>| {
        let gain = w.r.solve(&(b.transpose() * p));
        let pa = a.transpose() * p;
        let pgp = p * w.g * p;
        let residual = symmetric(&(pa + pa.transpose() - pgp + w.q));
        let relative = relative(
            frobenius(&residual),
            2.0 * frobenius(&pa) + frobenius(&pgp) + frobenius(&w.q),
        );
        Ok(Candidate {
            p,
            gain,
            closed: a - b * gain,
            residual,
            relative,
        })
    };
    // Kleinman's step: the correction D solves the Lyapunov equation
    // Ac^T D + D Ac + residual = 0.
    let newton = |c: &Candidate<S, M>| lyapunov(&c.closed, &c.residual, false);
    let c = refine(at(p)?, at, newton);
    let closed_loop_eigenvalues = Const::<S>::general(&c.closed)?;
    let stable = closed_loop_eigenvalues.iter().all(|s| s.re < 0.0);
    accept(c, closed_loop_eigenvalues, iterations, stable)
}

/// [`dlqr`]'s work.
fn discrete<const S: usize, const M: usize>(
    a: &SMatrix<f64, S, S>,
    b: &SMatrix<f64, S, M>,
    q: &SMatrix<f64, S, S>,
    r: &SMatrix<f64, M, M>,
) -> Result<Lqr<S, M>, ArmError>
where
    Const<S>: EigenSize<S>,
{
    let w = Weights::new(a, b, q, r)?;
    check_modes(a, b, &w.q_root, true)?;
    let (p, iterations) = doubling(*a, w.g, w.q)?;
    let at = |p: SMatrix<f64, S, S>| {
        let bp = b.transpose() * p;
        // R + B^T P B is positive definite for P positive semidefinite; rounding can cost a
        // P that only just is that.
        let s = (r + bp * b).cholesky().ok_or(ArmError::NoConvergence {
            iterations,
            residual: f64::INFINITY,
        })?;
        let bpa = bp * a;
        let gain = s.solve(&bpa);
        let apa = a.transpose() * p * a;
        let correction = bpa.transpose() * gain;
        let residual = symmetric(&(apa - p - correction + w.q));
        let scale = frobenius(&apa) + frobenius(&p) + frobenius(&correction) + frobenius(&w.q);
        let relative = relative(frobenius(&residual), scale);
        Ok(Candidate {
            p,
            gain,
            closed: a - b * gain,
            residual,
            relative,
        })
    };
    // Hewer's step: the correction D solves the Stein equation Ac^T D Ac - D + residual = 0.
    let newton = |c: &Candidate<S, M>| lyapunov(&c.closed, &c.residual, true);
    let c = refine(at(p)?, at, newton);
    let closed_loop_eigenvalues = Const::<S>::general(&c.closed)?;
    let stable = closed_loop_eigenvalues
        .iter()
        .all(|z| z.re.hypot(z.im) < 1.0);
    accept(c, closed_loop_eigenvalues, iterations, stable)
}

/// A solution of the Riccati equation and what it gives.
struct Candidate<const S: usize, const M: usize> {
    /// `P`.
    p: SMatrix<f64, S, S>,
    /// `K` from `P`.
    gain: SMatrix<f64, M, S>,
    /// `A - B K`.
    closed: SMatrix<f64, S, S>,
    /// The Riccati equation's left side minus its right at `P`, symmetrised.
    residual: SMatrix<f64, S, S>,
    /// Its Frobenius norm over the sum of the norms of the equation's terms.
    relative: f64,
}

/// Newton steps on the doubling's result while they lower the residual, at most
/// [`MAX_REFINEMENTS`] (see the module docs for why). `at` evaluates the equation at a `P`,
/// `newton` solves for the step from a candidate; a step that fails or does not help ends it.
fn refine<const S: usize, const M: usize>(
    mut best: Candidate<S, M>,
    at: impl Fn(SMatrix<f64, S, S>) -> Result<Candidate<S, M>, ArmError>,
    newton: impl Fn(&Candidate<S, M>) -> Result<SMatrix<f64, S, S>, ArmError>,
) -> Candidate<S, M> {
    for _ in 0..MAX_REFINEMENTS {
        if best.relative <= f64::EPSILON {
            break;
        }
        let Ok(next) = newton(&best).and_then(|d| at(symmetric(&(best.p + d)))) else {
            break;
        };
        if next.relative.partial_cmp(&best.relative) != Some(core::cmp::Ordering::Less) {
            break;
        }
        best = next;
    }
    best
}

/// The result if it passes its checks: no silent NaN, a small residual, a stable loop.
fn accept<const S: usize, const M: usize>(
    c: Candidate<S, M>,
    closed_loop_eigenvalues: SVector<Complex<f64>, S>,
    iterations: usize,
    stable: bool,
) -> Result<Lqr<S, M>, ArmError> {
    if !(c.gain.iter().all(|k| k.is_finite()) && c.relative.is_finite()) {
        return Err(ArmError::NonFinite { argument: "result" });
    }
    // A residual above tolerance, or an unstable loop despite the checks of the modes, means
    // the pair is within rounding of having no stabilising solution.
    if c.relative > RESIDUAL_TOLERANCE || !stable {
        return Err(ArmError::NoConvergence {
            iterations,
            residual: c.relative,
        });
    }
    Ok(Lqr {
        gain: c.gain,
        cost_to_go: c.p,
        closed_loop_eigenvalues,
        residual: c.relative,
        iterations,
    })
}

/// The symmetric part: products like `A^T P A` come out a few ulps from symmetric, and the
/// iteration would compound it.
fn symmetric<const N: usize>(m: &SMatrix<f64, N, N>) -> SMatrix<f64, N, N> {
    (m + m.transpose()) * 0.5
}

/// `x / scale`, `0` for `0 / 0` (a zero equation is solved exactly).
fn relative(x: f64, scale: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        x / scale
    }
}

/// The Frobenius norm, taken of the matrix scaled to a largest entry of 1 so that its squares
/// neither overflow nor underflow.
fn frobenius<const R: usize, const C: usize>(m: &SMatrix<f64, R, C>) -> f64 {
    let largest = m.amax();
    if largest > 0.0 && largest.is_finite() {
        largest * (m / largest).norm()
    } else {
        largest
    }
}
