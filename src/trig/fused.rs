//! The batch kernel with fused multiply-adds: the operations of [`packed_kernel`] with each
//! product rounded together with the sum that follows it.
//!
//! Where the target has AVX and FMA (`-C target-cpu=native` on x86 processors since 2013, or
//! `-C target-cpu=x86-64-v3`), a [`WideF64x4`](crate::simd::WideF64x4) batch takes its sines
//! and cosines from here: the 30 floating-point operations of four angles become 19, and
//! the batch's trigonometry costs 0.76x as much (docs/performance.md). Without FMA a fused
//! step would be a library call, so other builds keep [`packed_kernel`].
//!
//! The scalar `f64` path keeps [`packed_kernel`] everywhere, so its bits stay the same on
//! every target. The fused kernel is tested below as the unfused one is: within 2 ulp of the
//! correctly rounded values (or `2^-80` absolutely where the value is that small), on six
//! million random angles up to the kernel's limit, next to multiples of `pi/2`, on tiny angles
//! and on the hard case, with a negative control. Against the unfused kernel it is within 1 ulp
//! (or `2^-80`), and bit for bit on all but 1.5e-5 of the results: the fused steps move only
//! roundings far below the last one. So a lane of a batch built with FMA differs from the
//! scalar call only where one of its sines or cosines does, by 1 ulp.
//!
//! [`packed_kernel`]: super::packed_kernel

use super::{Packed, H1, H2, H3, INV_H, TO_INT};

/// A [`Packed`] vector with a fused multiply-add: one rounding of `self * a + b`.
pub(super) trait Fused: Packed + core::ops::Neg<Output = Self> {
    fn mul_add(self, a: Self, b: Self) -> Self;
}

/// `wide`'s `mul_add` is one `vfmadd` instruction where AVX and FMA are enabled (and a
/// separate multiply and add otherwise, which is why this impl exists only there).
#[cfg(all(feature = "std", target_feature = "avx", target_feature = "fma"))]
impl Fused for wide::f64x4 {
    #[inline(always)]
    fn mul_add(self, a: Self, b: Self) -> Self {
        wide::f64x4::mul_add(self, a, b)
    }
}

/// [`packed_kernel`](super::packed_kernel) fused: the same reduction (`m`, then `t = x - m h`
/// with `h` in three parts, the first two products exact) and the same polynomials and table,
/// every `a * b + c` rounded once.
#[inline(always)]
pub(super) fn kernel<V: Fused>(x: V) -> (V, V) {
    let k = V::splat;
    let y = x.mul_add(k(INV_H), k(TO_INT));
    let m = y - k(TO_INT);
    let t = m.mul_add(k(-H1), x);
    let t = m.mul_add(k(-H2), t);
    let t = m.mul_add(k(-H3), t);
    let t2 = t * t;
    let p = t2.mul_add(t2.mul_add(k(-1.0 / 5040.0), k(1.0 / 120.0)), k(-1.0 / 6.0));
    let sin_t = (t * t2).mul_add(p, t);
    let cos_t_minus_1 = t2 * t2.mul_add(t2.mul_add(k(-1.0 / 720.0), k(1.0 / 24.0)), k(-0.5));
    let (s, c) = (V::table(y, 0), V::table(y, 64));
    let sin = s + s.mul_add(cos_t_minus_1, c * sin_t);
    let cos = c + c.mul_add(cos_t_minus_1, -(s * sin_t));
    (sin, cos)
}

#[cfg(test)]
mod tests {
    use super::super::tests::{close, ulps, Rng};
    use super::super::{sin_cos, Packed, LIMIT, SIN_TABLE};
    use super::{kernel, Fused};

    /// One lane, with the standard library's fused multiply-add (correctly rounded in software
    /// where the CPU has none): the same bits as a lane of the `wide` form.
    impl Packed for f64 {
        fn splat(v: f64) -> Self {
            v
        }
        #[allow(clippy::cast_possible_truncation)]
        fn table(y: Self, offset: usize) -> Self {
            SIN_TABLE[(y.to_bits() as usize).wrapping_add(offset) & 255]
        }
    }
    impl Fused for f64 {
        fn mul_add(self, a: Self, b: Self) -> Self {
            f64::mul_add(self, a, b)
        }
    }

    /// Every angle within the bound of the correctly rounded values, and within 1 ulp (or
    /// `2^-80` absolutely) of the unfused kernel; the shares of results bit-identical to the
    /// correctly rounded ones and to the unfused kernel's.
    fn check(xs: impl Iterator<Item = f64>, off: impl Fn(f64) -> f64) -> (f64, f64) {
        let (mut total, mut identical, mut unfused) = (0_u32, 0_u32, 0_u32);
        for x in xs {
            let (s, c) = kernel(x);
            let (s, c) = (off(s), off(c));
            let (s0, c0) = x.sin_cos();
            assert!(close(s, s0), "sin {x:e}: {s:e} vs {s0:e}");
            assert!(close(c, c0), "cos {x:e}: {c:e} vs {c0:e}");
            let [(s1, c1)] = sin_cos([x]);
            for (a, b) in [(s, s1), (c, c1)] {
                assert!(ulps(a, b) <= 1 || (a - b).abs() <= 2f64.powi(-80), "{x:e}");
                unfused += u32::from(a.to_bits() == b.to_bits());
            }
            total += 2;
            identical += u32::from(s == s0) + u32::from(c == c0);
        }
        let share = |n: u32| f64::from(n) / f64::from(total);
        (share(identical), share(unfused))
    }

    #[test]
    fn random_angles_within_two_ulp() {
        let mut rng = Rng(0x6A09_E667_F3BC_C908);
        for scale in [std::f64::consts::FRAC_PI_4, 4.0, 100.0, 1e4, 1e6, LIMIT] {
            let (share, unfused) = check((0..1_000_000).map(|_| scale * rng.unit()), |v| v);
            println!(
                "fused, |x| < {scale:e}: {:.1} % bit-identical, {:.4} % as the unfused kernel",
                100.0 * share,
                100.0 * unfused
            );
            assert!(share > 0.7, "{share}");
            // The fused steps move only roundings far below the last one: measured 1.5e-5
            // of the results differ from the unfused kernel's.
            assert!(unfused > 0.9999, "{unfused}");
        }
    }

    #[test]
    fn near_multiples_of_half_pi_tiny_angles_and_the_hard_case() {
        let mut xs = Vec::new();
        for k in (-200_000_i32..200_000).step_by(997).chain(-8..8) {
            let mut x = f64::from(k) * std::f64::consts::FRAC_PI_2;
            for _ in 0..4 {
                xs.extend([x, x.next_up(), x.next_down()]);
                x = x.next_up().next_up();
            }
        }
        xs.extend([
            1e-300, -1e-310, 5e-324, 1e-20, -1e-9, 0.0, -0.0, 1e-5, -3e-8,
        ]);
        xs.push(871_790.390_574_840_8);
        let _ = check(xs.into_iter(), |v| v);
    }

    #[test]
    #[should_panic(expected = "sin")]
    fn the_check_rejects_a_kernel_three_ulp_off() {
        // Negative control: the same check fails the kernel's results moved by 3 ulp.
        let up = |v: f64| {
            if v.abs() < 1e-6 {
                v
            } else {
                v.next_up().next_up().next_up()
            }
        };
        let mut rng = Rng(3);
        let _ = check((0..1000).map(|_| 4.0 * rng.unit()), up);
    }

    /// The `wide` form on four lanes equals four calls of the one-lane form bit for bit.
    #[cfg(all(feature = "std", target_feature = "avx", target_feature = "fma"))]
    #[test]
    fn four_lanes_equal_four_single_angles() {
        let mut rng = Rng(11);
        for _ in 0..200_000 {
            let x: [f64; 4] = core::array::from_fn(|_| 1e3 * rng.unit());
            let (s, c) = kernel(wide::f64x4::from(x));
            for (l, &xl) in x.iter().enumerate() {
                let (s1, c1) = kernel(xl);
                assert_eq!(s.to_array()[l].to_bits(), s1.to_bits(), "{xl:e}");
                assert_eq!(c.to_array()[l].to_bits(), c1.to_bits(), "{xl:e}");
            }
        }
    }
}
