//! [`Frozen`]: an arm whose run-time parameters are held fixed while its parameter-only
//! values are reused across calls.

use nalgebra::{SMatrix, SVector};

use crate::Real;

use crate::Dynamics;

/// A view of an arm that evaluates the parameter-only part of its dynamics once, at
/// [`Dynamics::freeze`], and reuses it on every call.
///
/// An arm with run-time parameters (`mass = self.m2`, ...) computes at every call the
/// products and sums of parameters that do not depend on the state: `i3 + m3 c3^2`,
/// `m2 + m3`, the payload merged into the last link. `Frozen` computes them once. Its methods
/// give the arm's own numbers to rounding (the same formulas, sums grouped differently in
/// places) and cost about what the same arm written with literals does (docs/performance.md).
///
/// `Frozen` holds a shared borrow of the arm, so the arm cannot change while the view lives and
/// the values it holds cannot go stale: freeze again after changing a parameter.
///
/// ```compile_fail
/// # use planar_arm::prelude::*;
/// #[derive(PlanarArm)]
/// struct Picker {
///     #[arm(length = 0.4, mass = 2.0)]
///     upper: Revolute,
///     #[arm(length = 0.3, mass = self.m2)]
///     fore: Revolute,
///     m2: f64,
/// }
/// let mut arm = Picker { upper: Revolute, fore: Revolute, m2: 1.0 };
/// let frozen = arm.freeze();
/// arm.m2 = 1.5; // error: `arm` is borrowed by `frozen`
/// let _ = frozen.mass_matrix(&SVector::<f64, 2>::zeros());
/// ```
///
/// For an all-literal arm there is nothing to compute beforehand and `Frozen` calls the arm's
/// methods. Planar and spatial arms alike have `freeze` (a method of [`Dynamics`]).
///
/// # Example
///
/// ```
/// use planar_arm::prelude::*;
///
/// #[derive(PlanarArm)]
/// #[arm(gravity = 9.81, payload = self.payload)]
/// struct Picker {
///     #[arm(length = 0.4, mass = 2.0)]
///     upper: Revolute,
///     #[arm(length = 0.3, mass = 1.0)]
///     fore: Revolute,
///     payload: f64,
/// }
///
/// let mut arm = Picker { upper: Revolute, fore: Revolute, payload: 0.5 };
/// let (q, qd, qdd) = (SVector::from([0.3, -0.7]), SVector::from([0.1, 0.2]), SVector::zeros());
/// let tau = {
///     let frozen = arm.freeze();
///     // ... many calls per control cycle ...
///     frozen.inverse_dynamics(&q, &qd, &qdd)
/// };
/// assert!((tau - arm.inverse_dynamics(&q, &qd, &qdd)).norm() < 1e-12);
/// arm.payload = 0.8; // the view is gone: parameters may change, then freeze again
/// let heavier = arm.freeze().inverse_dynamics(&q, &qd, &qdd);
/// assert!(heavier[0] > tau[0]);
/// ```
pub struct Frozen<'a, A: Dynamics<N> + ?Sized, const N: usize> {
    arm: &'a A,
    block: A::__Frozen,
}

impl<A: Dynamics<N> + ?Sized, const N: usize> Clone for Frozen<'_, A, N> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<A: Dynamics<N> + ?Sized, const N: usize> Copy for Frozen<'_, A, N> {}

impl<A: Dynamics<N> + ?Sized, const N: usize> core::fmt::Debug for Frozen<'_, A, N> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Frozen")
            .field("block", &self.block)
            .finish_non_exhaustive()
    }
}

impl<'a, A: Dynamics<N> + ?Sized, const N: usize> Frozen<'a, A, N> {
    /// Evaluates the parameter-only values of `arm` now.
    #[must_use]
    pub fn new(arm: &'a A) -> Self {
        Self {
            arm,
            block: arm.__freeze(),
        }
    }

    /// The arm, for every method `Frozen` does not repeat.
    #[must_use]
    pub fn arm(&self) -> &'a A {
        self.arm
    }

    /// [`Dynamics::mass_matrix`](crate::Dynamics::mass_matrix).
    #[inline]
    #[must_use]
    pub fn mass_matrix<T: Real>(&self, q: &SVector<T, N>) -> SMatrix<T, N, N> {
        self.arm.__mass_matrix_frozen(&self.block, q)
    }

    /// [`Dynamics::bias`](crate::Dynamics::bias).
    #[inline]
    #[must_use]
    pub fn bias<T: Real>(&self, q: &SVector<T, N>, qd: &SVector<T, N>) -> SVector<T, N> {
        self.arm.__bias_frozen(&self.block, q, qd)
    }

    /// [`Dynamics::mass_matrix_and_bias`](crate::Dynamics::mass_matrix_and_bias).
    #[inline]
    #[must_use]
    pub fn mass_matrix_and_bias<T: Real>(
        &self,
        q: &SVector<T, N>,
        qd: &SVector<T, N>,
    ) -> (SMatrix<T, N, N>, SVector<T, N>) {
        self.arm.__mass_matrix_and_bias_frozen(&self.block, q, qd)
    }

    /// [`Dynamics::inverse_dynamics`](crate::Dynamics::inverse_dynamics).
    #[inline]
    #[must_use]
    pub fn inverse_dynamics<T: Real>(
        &self,
        q: &SVector<T, N>,
        qd: &SVector<T, N>,
        qdd: &SVector<T, N>,
    ) -> SVector<T, N> {
        self.arm.__inverse_dynamics_frozen(&self.block, q, qd, qdd)
    }

    /// [`Dynamics::forward_dynamics`](crate::Dynamics::forward_dynamics).
    #[inline]
    #[must_use]
    pub fn forward_dynamics<T: Real>(
        &self,
        q: &SVector<T, N>,
        qd: &SVector<T, N>,
        tau: &SVector<T, N>,
    ) -> SVector<T, N> {
        self.arm.__forward_dynamics_frozen(&self.block, q, qd, tau)
    }
}
