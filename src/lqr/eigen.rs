//! nalgebra's eigensolvers behind one bound, [`EigenSize`], in place of its dimension bounds.

use nalgebra::allocator::Allocator;
use nalgebra::linalg::{Schur, SymmetricEigen};
use nalgebra::{Complex, Const, DefaultAllocator, DimDiff, DimSub, SMatrix, SVector, U1};

use crate::ArmError;

/// QR sweeps allowed to nalgebra's eigenvalue solvers (their default is no limit).
const MAX_SWEEPS: usize = 10_000;

/// The state sizes [`lqr`](crate::lqr()) and [`dlqr`](crate::dlqr) take: `Const<S>` for
/// every `S` nalgebra's eigensolvers take (1 to 127). Sealed.
///
/// Concrete sizes meet it without a word; code generic over `S` writes
/// `where Const<S>: EigenSize<S>`. It stands for nalgebra's dimension bounds
/// (`Const<S>: DimSub<U1>` and allocators for `S - 1`), which would also cost the generic
/// function its type inference: rustc resolves every allocator obligation in it against those
/// where-clauses and no longer infers ordinary matrix types.
///
/// # Example
/// ```
/// use planar_arm::nalgebra::{Const, SMatrix};
/// use planar_arm::{EigenSize, Lqr};
///
/// /// A regulator with unit weights for any state size.
/// fn unit<const S: usize, const M: usize>(
///     a: &SMatrix<f64, S, S>,
///     b: &SMatrix<f64, S, M>,
/// ) -> Result<Lqr<S, M>, planar_arm::ArmError>
/// where
///     Const<S>: EigenSize<S>,
/// {
///     planar_arm::lqr(a, b, &SMatrix::identity(), &SMatrix::identity())
/// }
///
/// let a = SMatrix::<f64, 3, 3>::new(0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0);
/// let b = SMatrix::<f64, 3, 1>::new(0.0, 0.0, 1.0);
/// assert!(unit(&a, &b)?.closed_loop_eigenvalues.iter().all(|s| s.re < 0.0));
/// # Ok::<(), planar_arm::ArmError>(())
/// ```
pub trait EigenSize<const S: usize>: sealed::Sealed {
    /// The eigenvalues of a general matrix.
    #[doc(hidden)]
    fn general(m: &Real<S>) -> Result<SVector<Complex<f64>, S>, ArmError>;
    /// The eigenvalues and eigenvectors (columns) of a symmetric matrix.
    #[doc(hidden)]
    fn symmetric(m: Real<S>) -> Result<(SVector<f64, S>, Real<S>), ArmError>;
    /// The unit eigenvector of a Hermitian matrix's smallest eigenvalue.
    #[doc(hidden)]
    fn hermitian_smallest(m: Cplx<S>) -> Result<SVector<Complex<f64>, S>, ArmError>;
    /// The complex Schur form `(U, T)`, `m = U T U^H`, `T` upper triangular.
    #[doc(hidden)]
    fn complex_schur(m: &Real<S>) -> Result<(Cplx<S>, Cplx<S>), ArmError>;
}

type Real<const S: usize> = SMatrix<f64, S, S>;
type Cplx<const S: usize> = SMatrix<Complex<f64>, S, S>;

/// nalgebra's QR iteration failed (it is given [`MAX_SWEEPS`] sweeps: its default is no limit,
/// and no input should make it spin).
const EIGEN_FAILED: ArmError = ArmError::NoConvergence {
    iterations: MAX_SWEEPS,
    residual: f64::INFINITY,
};

/// The types are spelled out: under these where-clauses rustc does not infer them.
impl<const S: usize> EigenSize<S> for Const<S>
where
    Const<S>: DimSub<U1>,
    DefaultAllocator: Allocator<DimDiff<Const<S>, U1>> + Allocator<Const<S>, DimDiff<Const<S>, U1>>,
{
    fn general(m: &Real<S>) -> Result<SVector<Complex<f64>, S>, ArmError> {
        if !m.iter().all(|x| x.is_finite()) {
            return Err(ArmError::NonFinite { argument: "result" });
        }
        Schur::<f64, Const<S>>::try_new(*m, f64::EPSILON, MAX_SWEEPS)
            .map(|schur: Schur<f64, Const<S>>| schur.complex_eigenvalues())
            .ok_or(EIGEN_FAILED)
    }

    fn symmetric(m: Real<S>) -> Result<(SVector<f64, S>, Real<S>), ArmError> {
        SymmetricEigen::<f64, Const<S>>::try_new(m, f64::EPSILON, MAX_SWEEPS)
            .map(|e: SymmetricEigen<f64, Const<S>>| (e.eigenvalues, e.eigenvectors))
            .ok_or(EIGEN_FAILED)
    }

    fn hermitian_smallest(m: Cplx<S>) -> Result<SVector<Complex<f64>, S>, ArmError> {
        let e: SymmetricEigen<Complex<f64>, Const<S>> =
            SymmetricEigen::<Complex<f64>, Const<S>>::try_new(m, f64::EPSILON, MAX_SWEEPS)
                .ok_or(EIGEN_FAILED)?;
        let smallest: usize = e.eigenvalues.imin();
        Ok(e.eigenvectors.column(smallest).into_owned())
    }

    fn complex_schur(m: &Real<S>) -> Result<(Cplx<S>, Cplx<S>), ArmError> {
        if !m.iter().all(|x| x.is_finite()) {
            return Err(ArmError::NonFinite { argument: "result" });
        }
        let m: Cplx<S> = m.map(Complex::from);
        Schur::<Complex<f64>, Const<S>>::try_new(m, f64::EPSILON, MAX_SWEEPS)
            .map(|schur: Schur<Complex<f64>, Const<S>>| schur.unpack())
            .ok_or(EIGEN_FAILED)
    }
}

mod sealed {
    /// Keeps [`EigenSize`](super::EigenSize) to the sizes it is implemented for.
    pub trait Sealed {}
    impl<const S: usize> Sealed for nalgebra::Const<S> {}
}
