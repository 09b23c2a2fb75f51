//! [`Identification`]: the regressor and the exact base parameters of a derived arm.

use nalgebra::{SMatrix, SVector};

use crate::Dynamics;

/// Identification of an arm's inertial and friction parameters from measured torques.
///
/// The joint torques are linear in the *standard parameters* `theta` (per link the moment of
/// inertia about the joint `zz = Izz + m (cx^2 + cy^2)`, the first moments `mx = m cx` and
/// `my = m cy`, the mass `m`; the payload's; per joint armature, damping and Coulomb friction
/// where the arm has them): `inverse_dynamics(q, qd, qdd) == regressor(q, qd, qdd) * theta`.
/// Only combinations of them, the *base parameters*, can be found from torques. The derive
/// finds them exactly at compile time (rational elimination on the regressor's columns, no
/// rank threshold), and [`BASE_PARAMETERS`](Self::BASE_PARAMETERS) shows each as a formula
/// in the standard ones (`zz1 + 9/16 m2 + 9/16 m3`: Gautier and Khalil's grouping).
///
/// Derived for every arm of up to 30 links whose gravity is a literal; its masses, inertias,
/// centres of mass, payload, armature and friction may be run-time parameters, and so may its
/// lengths if it has gravity (the groupings are then polynomials in them, `zz1 + l1^2 m2`).
/// Not derived for a run-time gravity, nor for run-time lengths without gravity: some
/// groupings would then be fractions in them. Beyond 30 links the exact elimination, which
/// grows about as the fifth power of the links, would cost more compile time than the rest of
/// the derive (docs/performance.md). `P` is the number of standard parameters, `B` of base
/// parameters. docs/identification.md lists the parameters, compares the groupings with
/// Gautier and Khalil's rules and gives operation counts.
///
/// **Spatial arms** (`#[derive(SpatialArm)]`) have ten standard parameters per link, in
/// Pinocchio's order `m, mx, my, mz, xx, xy, yy, xz, yz, zz` (`m c` in the link's frame and
/// the inertia about the link frame's origin in its axes: what Pinocchio's
/// `computeJointTorqueRegressor` multiplies), then per joint `ia`, `fv`, `fc` where the arm
/// has them, then the payload's ten in the tool frame (`mp`, ..., `zzp`). Their regressor is
/// too large to multiply out, so the derive evaluates it exactly at rational points of the
/// joints' circles (`cos q = (1 - t^2) / (1 + t^2)`, `sin q = 2 t / (1 + t^2)`), where its
/// columns satisfy exactly the relations they satisfy everywhere, and eliminates on those
/// exact rows, adding points until the result no longer changes. That needs exact geometry:
/// rational lengths, axes and gravity, and angles whose cosine and sine are both rational
/// (multiples of `pi/2`), as industrial arms have (the PUMA 560: 77 standard parameters with
/// friction and a payload, 41 base, equal to the numeric rank of the regressor stacked over
/// 40 random states; `tests/spatial_identification.rs`). Mass properties may be run-time
/// parameters. Arms with run-time lengths or other angles get no `Identification`.
///
/// ```
/// use planar_arm::prelude::*;
///
/// #[derive(PlanarArm)]
/// #[arm(gravity = 9.81)]
/// struct Two {
///     #[arm(length = 0.5, mass = 2.0)]
///     upper: Revolute,
///     #[arm(length = 0.4, mass = self.m2, damping = 0.1)]
///     fore: Revolute,
///     m2: f64,
/// }
///
/// let arm = Two { upper: Revolute, fore: Revolute, m2: 1.5 };
/// // zz, mx, my of two links, two masses, one damping: 9 standard, 7 base parameters.
/// assert_eq!(<Two as Identification<2, 9, 7>>::BASE_PARAMETERS[0], "zz1 + 1/4 m2");
/// // The same names without the counts.
/// assert_eq!(Two::base_parameter_names()[0], "zz1 + 1/4 m2");
/// assert_eq!(Two::parameter_names().len(), 9);
/// let (q, qd, qdd) = (Vector2::new(0.3, -0.8), Vector2::new(1.0, 0.5), Vector2::new(-2.0, 1.0));
/// let tau = arm.inverse_dynamics(&q, &qd, &qdd);
/// assert!((arm.regressor(&q, &qd, &qdd) * arm.standard_parameters() - tau).norm() < 1e-12);
/// assert!((arm.base_regressor(&q, &qd, &qdd) * arm.base_parameters() - tau).norm() < 1e-12);
/// ```
pub trait Identification<const N: usize, const P: usize, const B: usize>: Dynamics<N> {
    /// The standard parameters' names, in column order (`zz1`, `mx1`, `my1`, ..., `m1`, ...,
    /// `ia1`, `fv1`, `fc1`).
    const PARAMETERS: [&'static str; P];
    /// Each base parameter as an exact formula in the standard parameters.
    const BASE_PARAMETERS: [&'static str; B];
    /// The regressor Y(q, qd, qdd), N x P.
    fn regressor(
        &self,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        qdd: &SVector<f64, N>,
    ) -> SMatrix<f64, N, P>;
    /// The standard parameters' values now.
    fn standard_parameters(&self) -> SVector<f64, P>;
    /// The base regressor, N x B: the regressor's columns of the base parameters.
    ///
    /// For a spatial arm, an optimised build on x86-64 runs this where the processor has AVX2
    /// and FMA as a second generated program that carries four joints per register (the same
    /// entries to rounding, not to the bit; see the method's docs for both costs).
    fn base_regressor(
        &self,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        qdd: &SVector<f64, N>,
    ) -> SMatrix<f64, N, B>;
    /// The base parameters' values now.
    fn base_parameters(&self) -> SVector<f64, B>;
    /// The body of [`base_regressor`](Self::base_regressor) where the derive runs it through
    /// `__private::dispatch` (spatial arms, whose base regressor has a packed program). An
    /// impl that dispatches `base_regressor` must override this default, which calls it.
    #[doc(hidden)]
    fn __base_regressor_kernel(
        &self,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        qdd: &SVector<f64, N>,
    ) -> SMatrix<f64, N, B> {
        self.base_regressor(q, qd, qdd)
    }
    /// The base regressor four joints at a time in `lanes` (see `src/lanes.rs`): the packed
    /// program the derive emits for spatial arms, or else the body above.
    #[doc(hidden)]
    #[inline(always)]
    fn __base_regressor_packed<L: crate::__private::Lanes>(
        &self,
        _lanes: L,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        qdd: &SVector<f64, N>,
    ) -> SMatrix<f64, N, B> {
        self.__base_regressor_kernel(q, qd, qdd)
    }
    /// [`PARAMETERS`](Self::PARAMETERS) without naming `P` and `B`: `Arm::parameter_names()`
    /// (there is one impl per arm, so the counts are inferred).
    #[must_use]
    fn parameter_names() -> &'static [&'static str]
    where
        Self: Sized,
    {
        &Self::PARAMETERS
    }
    /// [`BASE_PARAMETERS`](Self::BASE_PARAMETERS) without naming `P` and `B`:
    /// `Arm::base_parameter_names()`.
    #[must_use]
    fn base_parameter_names() -> &'static [&'static str]
    where
        Self: Sized,
    {
        &Self::BASE_PARAMETERS
    }
}
