//! The matrix equations' solvers: structured doubling for the Riccati equations (after a
//! Cayley transform for the continuous one), Bartels and Stewart for the Lyapunov and Stein
//! equations of the Newton steps.

use nalgebra::{Complex, Const, SMatrix, SVector};
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use super::eigen::EigenSize;
use super::{frobenius, relative, symmetric};
use crate::ArmError;

type Square<const S: usize> = SMatrix<f64, S, S>;

/// The relative change of the doubling iterate below which it has converged. Convergence is
/// quadratic: the iterate after a change of `1e-13` is accurate to rounding.
const STEP_TOLERANCE: f64 = 1e-13;

/// Doubling steps before giving up: step k covers the horizon `2^k`.
const MAX_DOUBLINGS: usize = 64;

/// The Cayley transform of the continuous Riccati equation `A^T P + P A - P G P + H = 0` into
/// the start `(A0, G0, H0)` of the doubling iteration with the same stabilising solution:
/// with `Ag = A - g I` and `W = Ag + G Ag^-T H`, `A0 = I + 2 g W^-1`,
/// `G0 = 2 g W^-1 G Ag^-T`, `H0 = 2 g W^-T H Ag^-1`: the blocks of the pencil
/// `(Ham + g I, Ham - g I)` of the Hamiltonian `Ham` once a left factor has brought it to the
/// doubling's standard form `([[A0, 0], [-H0, I]], [[I, G0], [0, A0^T]])`. The shift `g` is
/// twice the larger of `|A|` and `sqrt(|G| |H|)` (the size of the poles when `A` is small):
/// above `|A|`, so `Ag` is invertible with a condition number at most 3, and near the poles'
/// size, so that few doublings are needed. (Fixed shifts from 0.5 to 32 gave the same
/// residuals, within their spread, on the ill-conditioned random pairs tried.)
pub(super) fn cayley<const S: usize>(
    a: &Square<S>,
    g: &Square<S>,
    h: &Square<S>,
) -> Result<(Square<S>, Square<S>, Square<S>), ArmError> {
    let overflow = ArmError::NonFinite { argument: "result" };
    let size = frobenius(a).max((frobenius(g) * frobenius(h)).sqrt());
    let gamma = if size > 0.0 { 2.0 * size } else { 1.0 };
    let identity = SMatrix::<f64, S, S>::identity();
    let shifted_inverse = (a - identity * gamma)
        .try_inverse()
        .ok_or(overflow.clone())?;
    let w = a - identity * gamma + g * shifted_inverse.transpose() * h;
    let w_inverse = w.try_inverse().ok_or(overflow.clone())?;
    let a0 = identity + w_inverse * (2.0 * gamma);
    let g0 = symmetric(&(w_inverse * g * shifted_inverse.transpose() * (2.0 * gamma)));
    let h0 = symmetric(&(w_inverse.transpose() * h * shifted_inverse * (2.0 * gamma)));
    if [a0, g0, h0].iter().all(|m| m.iter().all(|x| x.is_finite())) {
        Ok((a0, g0, h0))
    } else {
        Err(overflow)
    }
}

/// The structure-preserving doubling iteration for `P = A^T P (I + G P)^-1 A + H`:
/// `A <- A (I + G H)^-1 A`, `G <- G + A (I + G H)^-1 G A^T`, `H <- H + A^T H (I + G H)^-1 A`.
/// `H` converges to the stabilising solution, quadratically. Returns it and the steps taken.
pub(super) fn doubling<const S: usize>(
    mut a: Square<S>,
    mut g: Square<S>,
    mut h: Square<S>,
) -> Result<(Square<S>, usize), ArmError> {
    let identity = SMatrix::<f64, S, S>::identity();
    let mut change = f64::INFINITY;
    let mut steps = 0;
    while steps < MAX_DOUBLINGS {
        steps += 1;
        // I + G H is invertible for G, H positive semidefinite (the eigenvalues of G H are
        // real and >= 0); a failure here means G or H has lost that to overflow. (An inverse
        // rather than LU solves: those need nalgebra's dimension bounds on S.)
        let Some(w_inverse) = (identity + g * h).try_inverse() else {
            break;
        };
        let (wa, wg) = (w_inverse * a, w_inverse * g);
        let h_next = symmetric(&(h + a.transpose() * h * wa));
        g = symmetric(&(g + a * wg * a.transpose()));
        a *= wa;
        if ![&a, &g, &h_next]
            .iter()
            .all(|m| m.iter().all(|x| x.is_finite()))
        {
            break;
        }
        change = relative(frobenius(&(h_next - h)), frobenius(&h_next));
        h = h_next;
        if change <= STEP_TOLERANCE {
            return Ok((h, steps));
        }
    }
    // Out of steps, or overflow: the iterate grows without bound when a mode within rounding
    // of the checks' thresholds cannot be stabilised.
    Err(ArmError::NoConvergence {
        iterations: steps,
        residual: change,
    })
}

/// The solution `X` of `Ac^T X + X Ac + C = 0` (continuous) or `Ac^T X Ac - X + C = 0`
/// (discrete) for a stable `Ac`, by Bartels and Stewart's method on the complex Schur form
/// `Ac = U T U^H`: with `Y = U^H X U`, `T^H Y + Y T = -U^H C U` (or `T^H Y T - Y = ...`) is
/// triangular and solved entry by entry, column by column.
pub(super) fn lyapunov<const S: usize>(
    ac: &Square<S>,
    c: &Square<S>,
    discrete: bool,
) -> Result<Square<S>, ArmError>
where
    Const<S>: EigenSize<S>,
{
    let (u, t) = Const::<S>::complex_schur(ac)?;
    let rhs = -(u.adjoint() * c.map(Complex::from) * u);
    let mut y = SMatrix::<Complex<f64>, S, S>::zeros();
    for j in 0..S {
        // Discrete: the part of (Y T)_kj from the columns before j.
        let mut before = SVector::<Complex<f64>, S>::zeros();
        if discrete {
            for k in 0..S {
                before[k] = (0..j).map(|l| y[(k, l)] * t[(l, j)]).sum();
            }
        }
        for i in 0..S {
            let mut sum = rhs[(i, j)];
            let denominator = if discrete {
                for k in 0..=i {
                    sum -= t[(k, i)].conj() * before[k];
                }
                for k in 0..i {
                    sum -= t[(k, i)].conj() * y[(k, j)] * t[(j, j)];
                }
                t[(i, i)].conj() * t[(j, j)] - Complex::from(1.0)
            } else {
                for k in 0..i {
                    sum -= t[(k, i)].conj() * y[(k, j)];
                }
                for k in 0..j {
                    sum -= y[(i, k)] * t[(k, j)];
                }
                t[(i, i)].conj() + t[(j, j)]
            };
            y[(i, j)] = sum / denominator;
        }
    }
    let x = (u * y * u.adjoint()).map(|z| z.re);
    if x.iter().all(|v| v.is_finite()) {
        Ok(symmetric(&x))
    } else {
        Err(ArmError::NonFinite { argument: "result" })
    }
}
