//! Four `f64` lanes, in which the emitted derivatives compute four directions at a time.
//!
//! A packed derivative program (the engine's `programs::packed`) holds the tangents of each
//! value along four directions in one [`Lanes::V`]. Its body is generic over the lanes, and
//! [`dispatch`](crate::dispatch::dispatch) picks them: [`Avx2`], one 256-bit register per value,
//! in the copy compiled for AVX2 and FMA, and [`Portable`], an array of four, everywhere else
//! (and `dispatch_wide` `wide::Avx512`, which computes four lanes as `Avx2` does). They apply the same IEEE operation to each lane, fused multiply-adds rounded once in
//! both, so their results agree to the bit (`tests/dispatch.rs`).

#[cfg(not(feature = "std"))]
use num_traits::Float as _;

/// Four `f64` lanes and the lane-wise arithmetic a packed derivative program needs. The value
/// of the implementing type is a token: the AVX2 lanes exist only where the processor has AVX2
/// and FMA.
pub trait Lanes: Copy {
    /// Whether the derivatives run their packed program in these lanes. Where they are not
    /// registers ([`Portable`]) the four-lane program is slower than the one-direction-at-a-time
    /// one it replaces, so that one runs instead.
    const PACKED: bool;
    /// Four `f64`.
    type V: Copy;
    /// Eight lanes of the same processor, for reverse-mode programs (src/wide.rs).
    type Wide: crate::wide::Wide;
    /// The eight lanes.
    fn wide(self) -> Self::Wide;
    /// The lanes `c`.
    fn constant(self, c: [f64; 4]) -> Self::V;
    /// `x` in every lane.
    fn splat(self, x: f64) -> Self::V;
    /// Lane-wise `a + b`.
    fn add(self, a: Self::V, b: Self::V) -> Self::V;
    /// Lane-wise `a - b`.
    fn sub(self, a: Self::V, b: Self::V) -> Self::V;
    /// Lane-wise `a * b`.
    fn mul(self, a: Self::V, b: Self::V) -> Self::V;
    /// Lane-wise `-a` (the sign flipped, as `f64`'s negation).
    fn neg(self, a: Self::V) -> Self::V;
    /// Lane-wise `a * s + c`, rounded once (a fused multiply-add).
    fn mul_add(self, a: Self::V, s: f64, c: Self::V) -> Self::V;
    /// Lane-wise `c - a * s`, rounded once.
    fn neg_mul_add(self, a: Self::V, s: f64, c: Self::V) -> Self::V;
    /// Lane-wise `a * s - c`, rounded once.
    fn mul_sub(self, a: Self::V, s: f64, c: Self::V) -> Self::V;
    /// The four lanes.
    fn lanes(self, a: Self::V) -> [f64; 4];
}

/// Lanes as an array of four, for any processor.
#[derive(Clone, Copy, Debug, Default)]
pub struct Portable;

impl Lanes for Portable {
    const PACKED: bool = false;
    type V = [f64; 4];
    type Wide = crate::wide::Pair<Self>;
    #[inline(always)]
    fn wide(self) -> Self::Wide {
        crate::wide::Pair(self)
    }
    #[inline(always)]
    fn constant(self, c: [f64; 4]) -> [f64; 4] {
        c
    }
    #[inline(always)]
    fn splat(self, x: f64) -> [f64; 4] {
        [x; 4]
    }
    #[inline(always)]
    fn add(self, a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
        [a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3]]
    }
    #[inline(always)]
    fn sub(self, a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
        [a[0] - b[0], a[1] - b[1], a[2] - b[2], a[3] - b[3]]
    }
    #[inline(always)]
    fn mul(self, a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
        [a[0] * b[0], a[1] * b[1], a[2] * b[2], a[3] * b[3]]
    }
    #[inline(always)]
    fn neg(self, a: [f64; 4]) -> [f64; 4] {
        [-a[0], -a[1], -a[2], -a[3]]
    }
    // `mul_add` is IEEE's fused multiply-add, rounded once like the FMA instructions (in
    // software where the build does not target FMA: these lanes run the packed programs only in
    // tests).
    #[inline(always)]
    fn mul_add(self, a: [f64; 4], s: f64, c: [f64; 4]) -> [f64; 4] {
        core::array::from_fn(|l| a[l].mul_add(s, c[l]))
    }
    #[inline(always)]
    fn neg_mul_add(self, a: [f64; 4], s: f64, c: [f64; 4]) -> [f64; 4] {
        core::array::from_fn(|l| (-a[l]).mul_add(s, c[l]))
    }
    #[inline(always)]
    fn mul_sub(self, a: [f64; 4], s: f64, c: [f64; 4]) -> [f64; 4] {
        core::array::from_fn(|l| a[l].mul_add(s, -c[l]))
    }
    #[inline(always)]
    fn lanes(self, a: [f64; 4]) -> [f64; 4] {
        a
    }
}

// Made only by `dispatch`, in the builds that have an AVX2 copy.
#[cfg(target_arch = "x86_64")]
#[allow(unused_imports)]
pub(crate) use avx2::Avx2;

#[cfg(target_arch = "x86_64")]
#[allow(unsafe_code)]
// Unused in the builds that have no AVX2 copy (`dev`, `no_std`).
#[allow(dead_code)]
mod avx2 {
    use core::arch::x86_64::{
        __m256d, _mm256_add_pd, _mm256_fmadd_pd, _mm256_fmsub_pd, _mm256_fnmadd_pd, _mm256_mul_pd,
        _mm256_set1_pd, _mm256_setr_pd, _mm256_storeu_pd, _mm256_sub_pd, _mm256_xor_pd,
    };

    use super::Lanes;

    /// Lanes in one AVX2 register. A value of this type is the proof that the processor runs
    /// AVX2 and FMA (the processors with AVX2 have FMA too; the dispatch asks for both): only
    /// [`dispatch`](crate::dispatch::dispatch) makes one, after asking it (or in a build that
    /// targets both).
    #[derive(Clone, Copy, Debug)]
    pub struct Avx2(());

    impl Avx2 {
        /// The token.
        ///
        /// # Safety
        ///
        /// The processor must support AVX2 and FMA.
        #[inline(always)]
        pub(crate) unsafe fn new() -> Self {
            Self(())
        }
    }

    // SAFETY (every block below): an `Avx2` exists only where the processor has AVX2 and FMA,
    // and these are their instructions on values in registers.
    impl Lanes for Avx2 {
        const PACKED: bool = true;
        type V = __m256d;
        type Wide = crate::wide::Pair<Self>;
        #[inline(always)]
        fn wide(self) -> Self::Wide {
            crate::wide::Pair(self)
        }
        #[inline(always)]
        fn constant(self, c: [f64; 4]) -> __m256d {
            unsafe { _mm256_setr_pd(c[0], c[1], c[2], c[3]) }
        }
        #[inline(always)]
        fn splat(self, x: f64) -> __m256d {
            unsafe { _mm256_set1_pd(x) }
        }
        #[inline(always)]
        fn add(self, a: __m256d, b: __m256d) -> __m256d {
            unsafe { _mm256_add_pd(a, b) }
        }
        #[inline(always)]
        fn sub(self, a: __m256d, b: __m256d) -> __m256d {
            unsafe { _mm256_sub_pd(a, b) }
        }
        #[inline(always)]
        fn mul(self, a: __m256d, b: __m256d) -> __m256d {
            unsafe { _mm256_mul_pd(a, b) }
        }
        #[inline(always)]
        fn neg(self, a: __m256d) -> __m256d {
            unsafe { _mm256_xor_pd(a, _mm256_set1_pd(-0.0)) }
        }
        #[inline(always)]
        fn mul_add(self, a: __m256d, s: f64, c: __m256d) -> __m256d {
            unsafe { _mm256_fmadd_pd(a, _mm256_set1_pd(s), c) }
        }
        #[inline(always)]
        fn neg_mul_add(self, a: __m256d, s: f64, c: __m256d) -> __m256d {
            unsafe { _mm256_fnmadd_pd(a, _mm256_set1_pd(s), c) }
        }
        #[inline(always)]
        fn mul_sub(self, a: __m256d, s: f64, c: __m256d) -> __m256d {
            unsafe { _mm256_fmsub_pd(a, _mm256_set1_pd(s), c) }
        }
        #[inline(always)]
        fn lanes(self, a: __m256d) -> [f64; 4] {
            let mut out = [0.0; 4];
            unsafe { _mm256_storeu_pd(out.as_mut_ptr(), a) };
            out
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{Lanes, Portable};

    #[test]
    fn portable_lanes_are_lane_wise() {
        let l = Portable;
        let a = l.constant([1.0, -2.0, 0.5, 0.0]);
        let b = l.splat(3.0);
        assert_eq!(l.lanes(l.add(a, b)), [4.0, 1.0, 3.5, 3.0]);
        assert_eq!(l.lanes(l.sub(a, b)), [-2.0, -5.0, -2.5, -3.0]);
        assert_eq!(l.lanes(l.mul(a, b)), [3.0, -6.0, 1.5, 0.0]);
        let n = l.lanes(l.neg(a));
        assert_eq!(n[..3], [-1.0, 2.0, -0.5]);
        assert!(n[3] == 0.0 && n[3].is_sign_negative());
    }

    /// `(1 + e)(1 - e) = 1 - e^2` is not an `f64` for `e = 2^-30`: rounded before the
    /// addition of -1 it is 1 and the sum 0; fused, the sum is -e^2 exactly.
    #[test]
    fn portable_multiply_adds_round_once() {
        let l = Portable;
        let e = 2f64.powi(-30);
        let (a, one) = (l.splat(1.0 + e), l.splat(1.0));
        assert_eq!(
            l.lanes(l.add(l.mul(a, l.splat(1.0 - e)), l.neg(one))),
            [0.0; 4]
        );
        assert_eq!(l.lanes(l.mul_add(a, 1.0 - e, l.neg(one))), [-e * e; 4]);
        assert_eq!(l.lanes(l.mul_sub(a, 1.0 - e, one)), [-e * e; 4]);
        assert_eq!(l.lanes(l.neg_mul_add(a, 1.0 - e, one)), [e * e; 4]);
    }

    #[cfg(target_arch = "x86_64")]
    #[test]
    #[allow(unsafe_code)]
    fn avx2_lanes_match_portable_to_the_bit() {
        if !(std::is_x86_feature_detected!("avx2") && std::is_x86_feature_detected!("fma")) {
            return;
        }
        // SAFETY: just asked.
        let v = unsafe { super::Avx2::new() };
        let p = Portable;
        let (x, y) = ([1.0 / 3.0, -2.5e-300, 7.0, -0.0], [3.0, 1e300, -0.1, 0.0]);
        let bits = |a: [f64; 4]| a.map(f64::to_bits);
        let (vx, vy, px, py) = (v.constant(x), v.constant(y), p.constant(x), p.constant(y));
        assert_eq!(bits(v.lanes(v.add(vx, vy))), bits(p.lanes(p.add(px, py))));
        assert_eq!(bits(v.lanes(v.sub(vx, vy))), bits(p.lanes(p.sub(px, py))));
        assert_eq!(
            bits(v.lanes(v.mul(vx, v.splat(0.7)))),
            bits(p.lanes(p.mul(px, p.splat(0.7))))
        );
        assert_eq!(bits(v.lanes(v.neg(vx))), bits(p.lanes(p.neg(px))));
        let e = 2f64.powi(-30);
        let (va, pa) = (v.splat(1.0 + e), p.splat(1.0 + e));
        for s in [1.0 - e, 0.7, -3.0] {
            assert_eq!(
                bits(v.lanes(v.mul_add(va, s, vx))),
                bits(p.lanes(p.mul_add(pa, s, px)))
            );
            assert_eq!(
                bits(v.lanes(v.neg_mul_add(va, s, vy))),
                bits(p.lanes(p.neg_mul_add(pa, s, py)))
            );
            assert_eq!(
                bits(v.lanes(v.mul_sub(va, s, vx))),
                bits(p.lanes(p.mul_sub(pa, s, px)))
            );
        }
    }
}
