//! Items that generated code names. Not public API: no stability promise.
#![allow(missing_docs)]

pub use ::core;
pub use ::nalgebra;
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use nalgebra::{Isometry2, SMatrix, SVector, Translation2, UnitComplex};

use crate::Real;

/// The largest methods' bodies, run in an AVX2 and FMA copy where the processor has them (the
/// forward derivatives of a spatial arm also in an AVX-512 one: `dispatch_wide`).
pub use crate::dispatch::{
    dispatch, dispatch_wide, BaseRegressor, ForwardDynamicsDerivatives, InverseDynamicsDerivatives,
    Kernel,
};
/// The lanes a packed derivative body computes in (see `src/lanes.rs`).
pub use crate::lanes::{Lanes, Portable};
/// The forward dynamics' solve after `mass_matrix_and_bias` (three or more joints).
pub use crate::ldlt::{forward_solve, Floor};
/// The trait's default for the forward dynamics' derivatives, named here for the benches, and
/// what the spatial derive's override of its packed body calls: the factor of M, then the
/// reverse-mode program (`forward_derivatives_in`), whose seeds `negated_rows` reads.
pub use crate::mass_inverse::{
    forward_derivatives, forward_derivatives_in, minus_product, negated_rows, Factor,
};
/// Eight lanes, which a reverse-mode body computes in (see `src/wide.rs`).
pub use crate::wide::Wide;

#[inline(always)]
#[must_use]
pub fn unpack<T: Copy, const N: usize>(v: &SVector<T, N>) -> [T; N] {
    v.data.0[0]
}

#[inline(always)]
#[must_use]
pub fn vector<T: Real, const N: usize>(v: [T; N]) -> SVector<T, N> {
    SVector::from_array_storage(nalgebra::ArrayStorage([v]))
}

/// A matrix from its columns: nalgebra's storage as it is, so that the generated values are
/// stored where the matrix is returned. Built from rows, large matrices (the regressors') went
/// through a temporary and a copy, whose wide loads waited for the values' narrow stores
/// (docs/performance.md).
#[inline(always)]
#[must_use]
pub const fn columns<T, const R: usize, const C: usize>(columns: [[T; R]; C]) -> SMatrix<T, R, C> {
    SMatrix::from_array_storage(nalgebra::ArrayStorage(columns))
}

/// The pose from the tip position and the cosine and sine of the last link's angle (already
/// computed, so no second `sin_cos`).
#[inline(always)]
#[must_use]
pub fn pose(x: f64, y: f64, cos: f64, sin: f64) -> Isometry2<f64> {
    Isometry2::from_parts(
        Translation2::new(x, y),
        UnitComplex::from_cos_sin_unchecked(cos, sin),
    )
}

/// Polar form from `r^2` (clamped at zero against rounding) and the tip position.
#[inline(always)]
#[must_use]
pub fn polar(r2: f64, x: f64, y: f64) -> (f64, f64) {
    (r2.max(0.0).sqrt(), y.atan2(x))
}

/// A spatial pose from the generated rotation (row-major) and position. The rotation is exact to
/// rounding, so the quaternion's normalisation only absorbs that.
#[inline]
#[must_use]
pub fn isometry3(r: [[f64; 3]; 3], p: [f64; 3]) -> nalgebra::Isometry3<f64> {
    let m = nalgebra::Matrix3::from_fn(|i, j| r[i][j]);
    let rotation = nalgebra::UnitQuaternion::from_rotation_matrix(
        &nalgebra::Rotation3::from_matrix_unchecked(m),
    );
    nalgebra::Isometry3::from_parts(nalgebra::Translation3::new(p[0], p[1], p[2]), rotation)
}

/// A stored sum of exact terms (see `exact`).
#[must_use]
pub const fn terms(code: &'static [u8], names: &'static [&'static str]) -> crate::exact::Terms {
    crate::exact::Terms::from_code(code, names)
}

/// The sign for Coulomb friction: 0 at zero (unlike `f64::signum`), NaN for NaN.
#[inline(always)]
#[must_use]
pub fn sign<T: Real>(x: T) -> T {
    x.sign()
}

/// The angles' sines and cosines in the scalar `T` (for `f64`, [`crate::trig::sin_cos`]).
#[inline(always)]
#[must_use]
pub fn sin_cos<T: Real, const N: usize>(q: [T; N]) -> [(T, T); N] {
    T::sin_cos(q)
}

/// `a.max(b)` in the scalar `T`.
#[inline(always)]
#[must_use]
pub fn max<T: Real>(a: T, b: T) -> T {
    a.max(b)
}

/// An `f64` constant or parameter in the scalar `T`.
#[inline(always)]
#[must_use]
pub fn real<T: Real>(x: f64) -> T {
    T::from_f64(x)
}

/// The kinetic energy `qd^T M qd / 2` from the upper triangle of `M`, row by row as the
/// derive's quadratic form on the mass matrix's program computes it,
/// `sum_i qd_i (M_ii qd_i / 2 + sum_{j > i} M_ij qd_j)`: what an arm's `kinetic_energy` calls
/// where that form is cheaper than the expanded energy (the same operations, so the cost its
/// docs print holds). The inner loop runs over all `N` columns and skips the lower ones, a
/// constant trip count the compiler unrolls.
#[inline(always)]
#[must_use]
pub fn kinetic_energy<T: Real, const N: usize>(m: &SMatrix<T, N, N>, qd: &SVector<T, N>) -> T {
    // nalgebra stores columns: `m[j][i]` is M(i, j).
    let (m, qd) = (&m.data.0, &qd.data.0[0]);
    let half = T::from_f64(0.5);
    let mut total = T::from_f64(0.0);
    for i in 0..N {
        let mut row = half * (m[i][i] * qd[i]);
        for j in 0..N {
            if j > i {
                row = row + m[j][i] * qd[j];
            }
        }
        let row = qd[i] * row;
        total = if i == 0 { row } else { total + row };
    }
    total
}

/// The parameter-only values of an arm's hot methods, computed by its `__freeze` and held by
/// [`crate::Frozen`]. A wrapper because `[f64; K]` implements `Default` only up to 32.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Block<const K: usize>(pub [f64; K]);

impl<const K: usize> Default for Block<K> {
    #[inline]
    fn default() -> Self {
        Self([0.0; K])
    }
}

/// What a run-time parameter's field must be: the derive reads each through one accessor
/// (`param(&self.field)`), so that a field of another type is one error at its type rather than
/// one at every read.
#[diagnostic::on_unimplemented(
    message = "`{Self}` is not the primitive `f64`",
    label = "a run-time parameter (`self.NAME` in an #[arm(...)] value) must be an `f64` field",
    note = "if a type of yours named `f64` is in scope, write the field's type as `core::primitive::f64`"
)]
pub trait ParamField {
    fn value(&self) -> f64;
}

impl ParamField for f64 {
    #[inline(always)]
    fn value(&self) -> f64 {
        *self
    }
}

#[inline(always)]
pub fn param<P: ParamField>(field: &P) -> f64 {
    field.value()
}

/// What a link field's type must be: the derive cannot resolve names, so it emits
/// `link_field::<FieldType>()` and the compiler checks that the type is [`crate::Revolute`]
/// (through any alias or path), not a user type that merely shares the name.
#[diagnostic::on_unimplemented(
    message = "`{Self}` is not `planar_arm::Revolute`",
    label = "link fields must have type `planar_arm::Revolute`, or `planar_arm::Prismatic` named as such",
    note = "the derive reads a link's joint kind from its type's name: a field whose type is named anything but `Prismatic` is a hinge, so an alias of `Prismatic` must be written `Prismatic` itself",
    note = "the link's parameters go in its #[arm(...)]; a field of another type is a run-time parameter or data and takes no #[arm(...)]"
)]
pub trait LinkField {}

impl LinkField for crate::Revolute {}

#[inline(always)]
pub const fn link_field<T: LinkField>() {}

/// As [`LinkField`], for a field the derive read as prismatic (its type's last segment is
/// `Prismatic`).
#[diagnostic::on_unimplemented(
    message = "`{Self}` is not `planar_arm::Prismatic`",
    label = "a field whose type is named `Prismatic` must have type `planar_arm::Prismatic`",
    note = "the derive reads a link's joint kind from its type's name: `Revolute` or `Prismatic`"
)]
pub trait PrismaticField {}

impl PrismaticField for crate::Prismatic {}

#[inline(always)]
pub const fn prismatic_field<T: PrismaticField>() {}

/// Inverse statics from the generated Jacobian, for two- and three-link arms with prismatic
/// joints (the revolute ones have the paper's closed forms): the tip wrench `w` with
/// `J^T w = tau`, `J` the task rows (position for two links, position and angle for three).
/// Singular when `|det J|` is below `SINGULAR_THRESHOLD` times the product of its columns'
/// norms (Hadamard's bound on it), reported as `measure = det J`.
macro_rules! by_jacobian {
    ($name:ident, $n:literal) => {
        pub fn $name(
            jacobian: &SMatrix<f64, 3, $n>,
            q: &SVector<f64, $n>,
            tau: &SVector<f64, $n>,
        ) -> Result<SVector<f64, $n>, crate::ArmError> {
            use crate::ArmError;
            if !q.iter().all(|x| x.is_finite()) {
                return Err(ArmError::NonFinite { argument: "q" });
            }
            if !tau.iter().all(|x| x.is_finite()) {
                return Err(ArmError::NonFinite { argument: "tau" });
            }
            let j: SMatrix<f64, $n, $n> = SMatrix::from_fn(|r, c| jacobian[(r, c)]);
            let det = j.determinant();
            let bound: f64 = j.column_iter().map(|c| c.norm()).product();
            let threshold = crate::kinematics::SINGULAR_THRESHOLD * bound;
            let singular = ArmError::Singular {
                measure: det,
                threshold,
            };
            // Also NaN: a non-finite Jacobian from finite but huge q.
            if det.is_nan() || det.abs() < threshold || bound == 0.0 {
                return Err(singular);
            }
            let w = j.transpose().lu().solve(tau).ok_or(singular)?;
            if w.iter().all(|x| x.is_finite()) {
                Ok(w)
            } else {
                Err(ArmError::NonFinite { argument: "result" })
            }
        }
    };
}

by_jacobian!(tip_force_by_jacobian, 2);
by_jacobian!(tip_wrench_by_jacobian, 3);
