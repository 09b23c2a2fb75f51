//! [`Real`]: the scalars the generated dynamics evaluate in.

use core::ops::{Add, Div, Mul, Neg, Sub};

use simba::simd::{WideF32x4, WideF32x8, WideF64x4};

use crate::trig;

/// A scalar the generated dynamics can evaluate in: `f64`, `f32`, or a batch of states in SIMD
/// lanes (simba's [`WideF64x4`], [`WideF32x4`], [`WideF32x8`]: one state per lane).
///
/// The generated `mass_matrix`, `coriolis`, `coriolis_matrix`, `gravity`, `friction`, `bias`,
/// `mass_matrix_and_bias`, `inverse_dynamics`, `forward_dynamics`, `kinetic_energy` and
/// `potential_energy` are generic over it: an `SVector<f32, N>` in gives an `SVector<f32, N>`
/// out, an `SVector<WideF64x4, N>` evaluates four states at once. The arm's exact constants
/// and its run-time parameters (`f64` fields) enter through [`from_f64`](Self::from_f64):
/// rounded to `f32`, or the same value in every lane.
///
/// The operations are those of a field plus what the code needs besides; implement it for your
/// own number type (a dual number, an interval) to evaluate the same code in it.
///
/// ```
/// use planar_arm::prelude::*;
/// use planar_arm::simd::{SimdValue, WideF64x4};
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
/// // f32 in, f32 out.
/// let q = Vector2::new(0.3_f32, -0.7);
/// let tau: Vector2<f32> = arm.inverse_dynamics(&q, &q, &q);
/// // Four states per call, one per lane.
/// let lanes = |a: [f64; 4]| WideF64x4::from(a);
/// let qb = Vector2::new(lanes([0.1, 0.2, 0.3, 0.4]), lanes([-0.5, 0.0, 0.5, 1.0]));
/// let taub = arm.inverse_dynamics(&qb, &qb, &qb);
/// let third = Vector2::new(0.3, 0.5);
/// let scalar = arm.inverse_dynamics(&third, &third, &third);
/// assert!((taub[0].extract(2) - scalar[0]).abs() < 1e-12);
/// # let _ = tau;
/// ```
pub trait Real:
    nalgebra::Scalar
    + Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// An `f64` constant or parameter in this scalar (rounded to `f32`; in every lane).
    fn from_f64(x: f64) -> Self;
    /// `(sin q_j, cos q_j)` for every angle, all at once.
    fn sin_cos<const N: usize>(q: [Self; N]) -> [(Self, Self); N];
    /// -1, 0 or 1 (0 at zero, so a joint at rest feels no Coulomb friction); NaN stays NaN.
    #[must_use]
    fn sign(self) -> Self;
    /// The larger of the two (the other where one is NaN).
    #[must_use]
    fn max(self, other: Self) -> Self;
}

/// The scalar `sign`: -1, 0 or 1, NaN stays NaN.
#[inline(always)]
fn sign64(x: f64) -> f64 {
    if x > 0.0 {
        1.0
    } else if x < 0.0 {
        -1.0
    } else {
        x * 0.0
    }
}

impl Real for f64 {
    #[inline(always)]
    fn from_f64(x: f64) -> Self {
        x
    }
    #[inline(always)]
    fn sin_cos<const N: usize>(q: [Self; N]) -> [(Self, Self); N] {
        trig::sin_cos(q)
    }
    #[inline(always)]
    fn sign(self) -> Self {
        sign64(self)
    }
    #[inline(always)]
    fn max(self, other: Self) -> Self {
        f64::max(self, other)
    }
}

impl Real for f32 {
    #[allow(clippy::cast_possible_truncation)] // rounding to f32 is the point
    #[inline(always)]
    fn from_f64(x: f64) -> Self {
        x as f32
    }
    /// The `f64` kernel, rounded: within 1 ulp of the correctly rounded `f32` result.
    #[allow(clippy::cast_possible_truncation)]
    #[inline(always)]
    fn sin_cos<const N: usize>(q: [Self; N]) -> [(Self, Self); N] {
        trig::sin_cos(q.map(f64::from)).map(|(s, c)| (s as f32, c as f32))
    }
    #[allow(clippy::cast_possible_truncation)]
    #[inline(always)]
    fn sign(self) -> Self {
        sign64(f64::from(self)) as f32
    }
    #[inline(always)]
    fn max(self, other: Self) -> Self {
        f32::max(self, other)
    }
}

/// `Real` for a simba batch type over `wide`: lane-wise through arrays, the trigonometry one
/// kernel call per joint over all lanes.
macro_rules! batch {
    ($ty:ident, $wide:ident, $lane:ty, $lanes:literal) => {
        impl Real for $ty {
            #[allow(clippy::cast_possible_truncation)]
            #[inline(always)]
            fn from_f64(x: f64) -> Self {
                $ty(wide::$wide::splat(x as $lane))
            }
            #[allow(clippy::cast_possible_truncation)]
            #[inline(always)]
            fn sin_cos<const N: usize>(q: [Self; N]) -> [(Self, Self); N] {
                q.map(|x| {
                    let (s, c) = trig::sin_cos_lanes::<$lanes>(x.0.to_array().map(f64::from));
                    (
                        $ty(wide::$wide::from(s.map(|v| v as $lane))),
                        $ty(wide::$wide::from(c.map(|v| v as $lane))),
                    )
                })
            }
            #[allow(clippy::cast_possible_truncation)]
            #[inline(always)]
            fn sign(self) -> Self {
                $ty(wide::$wide::from(
                    self.0.to_array().map(|v| sign64(f64::from(v)) as $lane),
                ))
            }
            #[inline(always)]
            fn max(self, other: Self) -> Self {
                $ty(self.0.max(other.0))
            }
        }
    };
}

batch!(WideF64x4, f64x4, f64, 4);
batch!(WideF32x4, f32x4, f32, 4);
batch!(WideF32x8, f32x8, f32, 8);
