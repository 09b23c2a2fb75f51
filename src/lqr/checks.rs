//! What makes a Riccati problem solvable: finite, symmetric, definite weights, and every mode
//! on or beyond the stability boundary moved by the input and weighed by the cost.

use nalgebra::linalg::Cholesky;
use nalgebra::{Complex, Const, SMatrix};
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use super::eigen::EigenSize;
use super::{frobenius, relative, symmetric};
use crate::ArmError;

/// The relative PBH measure below which a mode counts as unmoved (or unweighed).
const PBH_TOLERANCE: f64 = 1e-8;

/// How close to the stability boundary (relative to `|A|` in continuous time, absolute for
/// `|z|` in discrete time) an eigenvalue counts as on it: rounding moves eigenvalues this far.
const BOUNDARY_TOLERANCE: f64 = 1e-9;

/// The largest relative asymmetry `|W - W^T| / |W|` accepted of a weight.
const SYMMETRY_TOLERANCE: f64 = 1e-10;

/// How negative, relative to its largest, `Q`'s smallest eigenvalue may be: `Q = C^T C`
/// computed in floating point has eigenvalues down to about `-eps |Q|`.
const SEMIDEFINITE_TOLERANCE: f64 = 1e-10;

/// The checked, symmetrised weights and what the iteration needs of them.
pub(super) struct Weights<const S: usize, const M: usize> {
    /// `Q`, symmetrised.
    pub(super) q: SMatrix<f64, S, S>,
    /// `C` with `C^T C = Q`, for the detectability test.
    pub(super) q_root: SMatrix<f64, S, S>,
    /// `R`'s Cholesky factor.
    pub(super) r: Cholesky<f64, Const<M>>,
    /// `G = B R^-1 B^T`.
    pub(super) g: SMatrix<f64, S, S>,
}

impl<const S: usize, const M: usize> Weights<S, M> {
    pub(super) fn new(
        a: &SMatrix<f64, S, S>,
        b: &SMatrix<f64, S, M>,
        q: &SMatrix<f64, S, S>,
        r: &SMatrix<f64, M, M>,
    ) -> Result<Self, ArmError>
    where
        Const<S>: EigenSize<S>,
    {
        for (argument, finite) in [
            ("a", a.iter().all(|x| x.is_finite())),
            ("b", b.iter().all(|x| x.is_finite())),
            ("q", q.iter().all(|x| x.is_finite())),
            ("r", r.iter().all(|x| x.is_finite())),
        ] {
            if !finite {
                return Err(ArmError::NonFinite { argument });
            }
        }
        let q = symmetrised(q, "relative asymmetry |Q - Q^T| / |Q|")?;
        let r = symmetrised(r, "relative asymmetry |R - R^T| / |R|")?;
        let (values, vectors) = Const::<S>::symmetric(q)?;
        let largest = values.amax();
        let smallest = values.min();
        if smallest < -SEMIDEFINITE_TOLERANCE * largest {
            return Err(ArmError::OutOfRange {
                what: "smallest eigenvalue of Q (must be >= 0)",
                link: None,
                value: smallest,
            });
        }
        let root = values.map(|l| l.max(0.0).sqrt());
        let q_root = SMatrix::from_diagonal(&root) * vectors.transpose();
        let Some(r_factor) = r.cholesky() else {
            return Err(ArmError::OutOfRange {
                what: "smallest eigenvalue of R (must be > 0)",
                link: None,
                value: smallest_eigenvalue(&r),
            });
        };
        let g = b * r_factor.solve(&b.transpose());
        Ok(Self {
            q,
            q_root,
            r: r_factor,
            g: symmetric(&g),
        })
    }
}

/// `w` symmetrised, or the error naming `what` if it is further from symmetric than rounding.
fn symmetrised<const N: usize>(
    w: &SMatrix<f64, N, N>,
    what: &'static str,
) -> Result<SMatrix<f64, N, N>, ArmError> {
    let asymmetry = relative(frobenius(&(w - w.transpose())), frobenius(w));
    if asymmetry > SYMMETRY_TOLERANCE {
        return Err(ArmError::OutOfRange {
            what,
            link: None,
            value: asymmetry,
        });
    }
    Ok(symmetric(w))
}

/// The smallest eigenvalue of a symmetric `w` by bisection on whether `w - s I` has a Cholesky
/// factor: for the message of an `R` that is not positive definite (an eigensolver would need
/// `Const<M>: EigenSize<M>` as well).
fn smallest_eigenvalue<const N: usize>(w: &SMatrix<f64, N, N>) -> f64 {
    let bound = frobenius(w);
    let (mut lo, mut hi) = (-bound, bound);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if (w - SMatrix::<f64, N, N>::identity() * mid)
            .cholesky()
            .is_some()
        {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The PBH test at every mode of `A` on or beyond the stability boundary: `B` must move it and
/// `C` (`C^T C = Q`) see it.
pub(super) fn check_modes<const S: usize, const M: usize>(
    a: &SMatrix<f64, S, S>,
    b: &SMatrix<f64, S, M>,
    q_root: &SMatrix<f64, S, S>,
    discrete: bool,
) -> Result<(), ArmError>
where
    Const<S>: EigenSize<S>,
{
    let size = frobenius(a);
    for s in Const::<S>::general(a)?.iter() {
        let unstable = if discrete {
            s.re.hypot(s.im) >= 1.0 - BOUNDARY_TOLERANCE
        } else {
            s.re >= -BOUNDARY_TOLERANCE * size
        };
        if !unstable {
            continue;
        }
        // The input test on (A, B); the cost test on (A^T, C^T) at the conjugate, whose left
        // null vectors are the right ones of [A - s I; C].
        for (missed_by, measure) in [
            ("B", pbh(a, b, *s)?),
            ("Q", pbh(&a.transpose(), &q_root.transpose(), s.conj())?),
        ] {
            if measure < PBH_TOLERANCE {
                return Err(ArmError::NotStabilizable {
                    eigenvalue: [s.re, s.im],
                    discrete,
                    missed_by,
                    measure,
                });
            }
        }
    }
    Ok(())
}

/// The relative PBH measure of the mode `s` for the pair `(A, B)`: `min |w^H [A - s I, B~]|`
/// over unit `w`, over `|[A - s I, B~]|`, `B~ = B |A - s I| / |B|` (so that the measure does
/// not depend on the input's units). Zero for a mode no input moves. The minimising `w` is the
/// eigenvector of the smallest eigenvalue of `X X^H + B~ B~^H`; the measure is then taken from
/// `w` directly, not from that eigenvalue, which would square it and lose half the digits.
fn pbh<const S: usize, const M: usize>(
    a: &SMatrix<f64, S, S>,
    b: &SMatrix<f64, S, M>,
    s: Complex<f64>,
) -> Result<f64, ArmError>
where
    Const<S>: EigenSize<S>,
{
    let x = a.map(Complex::from) - SMatrix::<Complex<f64>, S, S>::identity() * s;
    // Scaled to entries of at most 1, so that the norms below neither overflow nor underflow.
    let largest = x
        .iter()
        .fold(0.0_f64, |m, z| m.max(z.re.abs()).max(z.im.abs()));
    let x = if largest > 0.0 {
        x.map(|z| z / largest)
    } else {
        x
    };
    let b = if b.amax() > 0.0 { b / b.amax() } else { *b };
    let size = x.norm();
    let input = b.norm();
    let b = if input > 0.0 {
        b * (if size > 0.0 { size } else { 1.0 } / input)
    } else {
        b
    };
    let whole = size.hypot(b.norm());
    if whole == 0.0 {
        // A = s I and B = 0: nothing moves.
        return Ok(0.0);
    }
    let gram = x * x.adjoint() + (b * b.transpose()).map(Complex::from);
    let w = Const::<S>::hermitian_smallest(gram)?;
    let through_a = (x.adjoint() * w).norm();
    let through_b = (b.transpose().map(Complex::from) * w).norm();
    Ok(through_a.hypot(through_b) / whole)
}
