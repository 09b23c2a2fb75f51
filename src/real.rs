//! [`Real`]: the scalars the generated dynamics evaluate in.

use core::ops::{Add, Div, Mul, Neg, Sub};

#[cfg(feature = "std")]
use simba::simd::{WideF32x4, WideF32x8, WideF64x4};

use crate::trig;

/// A scalar the generated dynamics can evaluate in: `f64`, `f32`, or a batch of states in SIMD
/// lanes (simba's `WideF64x4`, `WideF32x4`, `WideF32x8` in [`simd`](crate::simd): one state per
/// lane; with the `std` feature, as simba 0.9's batch types need the standard library).
///
/// The generated `mass_matrix`, `coriolis`, `coriolis_matrix`, `gravity`, `friction`, `bias`,
/// `mass_matrix_and_bias`, `inverse_dynamics`, `forward_dynamics`, `kinetic_energy`,
/// `potential_energy`, `jacobian` and `joint_positions` are generic over it: an `SVector<f32, N>` in gives an `SVector<f32, N>`
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
#[cfg(feature = "std")]
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
                // An index loop for the reason given at `WideF64x4`.
                let zero = $ty(wide::$wide::ZERO);
                let mut out = [(zero, zero); N];
                let mut j = 0;
                while j < N {
                    let (s, c) = trig::sin_cos_lanes::<$lanes>(q[j].0.to_array().map(f64::from));
                    out[j] = (
                        $ty(wide::$wide::from(s.map(|v| v as $lane))),
                        $ty(wide::$wide::from(c.map(|v| v as $lane))),
                    );
                    j += 1;
                }
                out
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

#[cfg(feature = "std")]
impl Real for WideF64x4 {
    #[inline(always)]
    fn from_f64(x: f64) -> Self {
        WideF64x4(wide::f64x4::splat(x))
    }
    #[inline(always)]
    fn sin_cos<const N: usize>(q: [Self; N]) -> [(Self, Self); N] {
        // An index loop, not `q.map`: where several methods shared an array length, `map` was
        // compiled as a separate function (`try_map`) returning through `memcpy`, which made
        // the batched inverse dynamics at N = 6 half as fast as the mass matrix.
        let zero = WideF64x4(wide::f64x4::ZERO);
        let mut out = [(zero, zero); N];
        let mut j = 0;
        while j < N {
            let (s, c) = trig::sin_cos_x4(q[j].0);
            out[j] = (WideF64x4(s), WideF64x4(c));
            j += 1;
        }
        out
    }
    #[inline(always)]
    fn sign(self) -> Self {
        WideF64x4(wide::f64x4::from(self.0.to_array().map(sign64)))
    }
    #[inline(always)]
    fn max(self, other: Self) -> Self {
        WideF64x4(self.0.max(other.0))
    }
}
#[cfg(feature = "std")]
batch!(WideF32x4, f32x4, f32, 4);
#[cfg(feature = "std")]
batch!(WideF32x8, f32x8, f32, 8);

#[cfg(test)]
mod tests {
    use super::Real;
    #[cfg(feature = "std")]
    use simba::simd::{WideF32x4, WideF32x8, WideF64x4};

    use crate::trig::tests::{ulps, Rng};

    /// Ulps between two `f32` of the same sign (`u32::MAX` across signs).
    fn ulps32(a: f32, b: f32) -> u32 {
        if a == b {
            return 0;
        }
        if a.is_sign_negative() != b.is_sign_negative() {
            return u32::MAX;
        }
        a.to_bits().abs_diff(b.to_bits())
    }

    /// Within 1 ulp of the correctly rounded value (`f64::sin_cos` rounded: its error is far
    /// below an `f32` ulp), or 2^-40 absolutely where the value is that small.
    #[allow(clippy::cast_possible_truncation)]
    fn check32(sin_cos: impl Fn([f32; 3]) -> [(f32, f32); 3], xs: &[f32]) -> usize {
        let mut identical = 0;
        for chunk in xs.chunks_exact(3) {
            let got = sin_cos([chunk[0], chunk[1], chunk[2]]);
            for (&x, &(s, c)) in chunk.iter().zip(&got) {
                let (s0, c0) = f64::from(x).sin_cos();
                let (s0, c0) = (s0 as f32, c0 as f32);
                let ok = |a: f32, b: f32| ulps32(a, b) <= 1 || (a - b).abs() <= 2f32.powi(-40);
                assert!(ok(s, s0), "sin {x:e}: {s:e} vs {s0:e}");
                assert!(ok(c, c0), "cos {x:e}: {c:e} vs {c0:e}");
                identical += usize::from(s == s0) + usize::from(c == c0);
            }
        }
        identical
    }

    #[allow(clippy::cast_possible_truncation)]
    fn angles32() -> Vec<f32> {
        let mut rng = Rng(0x2545_F491_4F6C_DD1D);
        let mut xs = Vec::new();
        for scale in [0.785, 4.0, 100.0, 1e4, 1e6] {
            xs.extend((0..300_000).map(|_| (scale * rng.unit()) as f32));
        }
        // Next to multiples of pi/2, where the result is small and cancellation bites.
        for k in -20_000_i32..20_000 {
            let x = (f64::from(k) * core::f64::consts::FRAC_PI_2) as f32;
            xs.extend([x, x.next_up(), x.next_down()]);
        }
        xs.extend([0.0, -0.0, 1e-30, -1e-38, 1e-45, 3e-8, -1e-4]);
        xs.resize(xs.len() / 3 * 3, 0.0);
        xs
    }

    #[test]
    fn f32_within_one_ulp_of_the_correctly_rounded_value() {
        let xs = angles32();
        let identical = check32(<f32 as Real>::sin_cos, &xs);
        #[allow(clippy::cast_precision_loss)]
        let share = identical as f64 / (2 * xs.len()) as f64;
        println!("f32: {:.2} % correctly rounded", 100.0 * share);
        assert!(share > 0.99, "{share}");
    }

    #[test]
    #[should_panic(expected = "sin")]
    fn the_f32_check_rejects_a_kernel_two_ulp_off() {
        // Negative control: the check above fails a kernel that is 2 ulp high.
        let off = |q: [f32; 3]| {
            <f32 as Real>::sin_cos(q).map(|(s, c)| {
                let up = |v: f32| if v == 0.0 { v } else { v.next_up().next_up() };
                (up(s), up(c))
            })
        };
        check32(off, &angles32());
    }

    /// Every lane of a batch equals the scalar evaluation bit for bit (the same kernel and
    /// operations lane-wise), out-of-range and NaN lanes included; where `WideF64x4` has the
    /// fused kernel (AVX and FMA), its lanes within that kernel's 4 ulp (or `2^-79`) instead.
    #[test]
    fn batch_lanes_equal_scalars_bit_for_bit() {
        let fused = cfg!(all(target_feature = "avx", target_feature = "fma"));
        let same = |a: f64, b: f64| {
            if fused {
                ulps(a, b) <= 4 || (a - b).abs() <= 2f64.powi(-79) || (a.is_nan() && b.is_nan())
            } else {
                a.to_bits() == b.to_bits()
            }
        };
        let mut rng = Rng(7);
        let specials = [1e7, f64::NAN, -3e6, f64::INFINITY];
        for round in 0..20_000 {
            let mut x: [f64; 8] = core::array::from_fn(|_| 10.0 * rng.unit());
            if round % 50 == 0 {
                x[round % 8] = specials[(round / 50) % 4];
            }
            let lanes4: [f64; 4] = [x[0], x[1], x[2], x[3]];
            let [(s, c)] = <WideF64x4 as Real>::sin_cos([WideF64x4::from(lanes4)]);
            for (i, &xi) in lanes4.iter().enumerate() {
                let [(s0, c0)] = <f64 as Real>::sin_cos([xi]);
                assert!(same(s.0.to_array()[i], s0), "{xi}");
                assert!(same(c.0.to_array()[i], c0), "{xi}");
            }
            #[allow(clippy::cast_possible_truncation)]
            let x32 = x.map(|v| v as f32);
            let [(s, c)] = <WideF32x8 as Real>::sin_cos([WideF32x8::from(x32)]);
            let x4: [f32; 4] = [x32[4], x32[5], x32[6], x32[7]];
            let [(s4, c4)] = <WideF32x4 as Real>::sin_cos([WideF32x4::from(x4)]);
            for (i, &xi) in x32.iter().enumerate() {
                let [(s0, c0)] = <f32 as Real>::sin_cos([xi]);
                assert_eq!(s.0.to_array()[i].to_bits(), s0.to_bits(), "{xi}");
                assert_eq!(c.0.to_array()[i].to_bits(), c0.to_bits(), "{xi}");
                if i >= 4 {
                    assert_eq!(s4.0.to_array()[i - 4].to_bits(), s0.to_bits());
                    assert_eq!(c4.0.to_array()[i - 4].to_bits(), c0.to_bits());
                }
            }
        }
    }

    #[test]
    fn sign_and_max_lane_by_lane() {
        let x = WideF64x4::from([-2.0, 0.0, 3.0, f64::NAN]);
        let s = x.sign().0.to_array();
        assert_eq!(&s[..3], &[-1.0, 0.0, 1.0]);
        assert!(s[3].is_nan());
        assert_eq!(<f32 as Real>::sign(-0.0), 0.0);
        let m = x.max(WideF64x4::from([0.0; 4])).0.to_array();
        assert_eq!(&m[..3], &[0.0, 0.0, 3.0]);
    }
}
