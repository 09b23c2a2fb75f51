//! [`Linearize`]: the continuous- and discrete-time linearisation of an arm's dynamics for
//! LQR, MPC and iLQR.

use nalgebra::{SMatrix, SVector};

use crate::Dynamics;

/// The linearisation of `xd = f(x, u)` with state `x = (q, qd)` (2N) and input `u = tau` (N):
/// `f(x, u) = (qd, forward_dynamics(q, qd, tau))`.
///
/// Implemented for every arm of 1 to 32 links (`S = 2N`); nothing is generated for it. Built on
/// [`Dynamics::forward_dynamics_derivatives`]: exact to rounding, Coulomb friction's jump at
/// zero rate not differentiated.
///
/// Its pairs are what the regulators take: [`lqr`](crate::lqr) the continuous `(A, B)` of
/// `linearize`, [`dlqr`](crate::dlqr) the zero-order-hold `(Ad, Bd)` of `discretize` (for one
/// input of several, `B * drive` with `drive` the `N x M` selection).
///
/// ```
/// use planar_arm::prelude::*;
///
/// #[derive(PlanarArm, Default)]
/// #[arm(gravity = 9.81)]
/// struct Two {
///     #[arm(length = 1, mass = 1)]
///     a: Revolute,
///     #[arm(length = 1, mass = 1)]
///     b: Revolute,
/// }
///
/// let arm = Two::default();
/// // Upright, both links up, holding still.
/// let q = Vector2::new(core::f64::consts::FRAC_PI_2, 0.0);
/// let tau = arm.gravity(&q);
/// let (a, b) = arm.linearize(&q, &Vector2::zeros(), &tau);
/// assert_eq!(a.fixed_view::<2, 2>(0, 2), planar_arm::nalgebra::Matrix2::identity());
/// // The zero-order-hold pair for a 1 ms control period.
/// let (ad, bd) = arm.discretize(&q, &Vector2::zeros(), &tau, 1e-3);
/// assert!((ad - (a * 1e-3).exp()).amax() < 1e-12);
/// # let _ = (b, bd);
/// ```
pub trait Linearize<const N: usize, const S: usize>: Dynamics<N> {
    /// `(A, B) = (df/dx, df/du)` at `(q, qd, tau)`: `A = [[0, I], [dqdd/dq, dqdd/dqd]]`,
    /// `B = [[0], [M^-1]]`.
    fn linearize(
        &self,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        tau: &SVector<f64, N>,
    ) -> (SMatrix<f64, S, S>, SMatrix<f64, S, N>) {
        let (dq, dqd, dtau) = self.forward_dynamics_derivatives(q, qd, tau);
        let mut a = SMatrix::<f64, S, S>::zeros();
        let mut b = SMatrix::<f64, S, N>::zeros();
        for i in 0..N {
            a[(i, N + i)] = 1.0;
            for j in 0..N {
                a[(N + i, j)] = dq[(i, j)];
                a[(N + i, N + j)] = dqd[(i, j)];
                b[(N + i, j)] = dtau[(i, j)];
            }
        }
        (a, b)
    }

    /// The discrete-time pair for a control period `dt` with the torque held constant over it
    /// (zero-order hold): `Ad = exp(A dt)`, `Bd = integral_0^dt exp(A s) ds B`, from the
    /// exponential of the augmented matrix `[[A, B], [0, 0]] dt` (nalgebra's Pade
    /// approximant with scaling and squaring). `x_{k+1} - x* = Ad (x_k - x*) + Bd (u_k - u*)`
    /// to first order. With the `std` feature (nalgebra's matrix exponential needs it). NaN or
    /// infinite input (or `dt`) gives non-finite matrices, never a panic (tested).
    #[cfg(feature = "std")]
    fn discretize(
        &self,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        tau: &SVector<f64, N>,
        dt: f64,
    ) -> (SMatrix<f64, S, S>, SMatrix<f64, S, N>);
}

/// The impl for one arm size: `$s = 2 N`, `$t = 3 N` (the augmented matrix).
macro_rules! linearize {
    ($($n:literal $s:literal $t:literal),*) => {$(
        impl<A: Dynamics<$n> + ?Sized> Linearize<$n, $s> for A {
            #[cfg(feature = "std")]
            fn discretize(
                &self,
                q: &SVector<f64, $n>,
                qd: &SVector<f64, $n>,
                tau: &SVector<f64, $n>,
                dt: f64,
            ) -> (SMatrix<f64, $s, $s>, SMatrix<f64, $s, $n>) {
                let (a, b) = self.linearize(q, qd, tau);
                let mut m = SMatrix::<f64, $t, $t>::zeros();
                m.fixed_view_mut::<$s, $s>(0, 0).copy_from(&(a * dt));
                m.fixed_view_mut::<$s, $n>(0, $s).copy_from(&(b * dt));
                let e = m.exp();
                (
                    e.fixed_view::<$s, $s>(0, 0).into_owned(),
                    e.fixed_view::<$s, $n>(0, $s).into_owned(),
                )
            }
        }
    )*};
}

linearize!(
    1 2 3, 2 4 6, 3 6 9, 4 8 12, 5 10 15, 6 12 18, 7 14 21, 8 16 24, 9 18 27, 10 20 30,
    11 22 33, 12 24 36, 13 26 39, 14 28 42, 15 30 45, 16 32 48, 17 34 51, 18 36 54, 19 38 57,
    20 40 60, 21 42 63, 22 44 66, 23 46 69, 24 48 72, 25 50 75, 26 52 78, 27 54 81, 28 56 84,
    29 58 87, 30 60 90, 31 62 93, 32 64 96
);
