//! Four `f64` lanes, in which the emitted derivatives compute four directions at a time.
//!
//! A packed derivative program (the engine's `programs::packed`) holds the tangents of each
//! value along four directions in one [`Lanes::V`]. Its body is generic over the lanes, and
//! [`dispatch`](crate::dispatch::dispatch) picks them: [`Avx2`], one 256-bit register per value,
//! in the copy compiled for AVX2, and [`Portable`], an array of four, everywhere else. The two
//! apply the same IEEE operation to each lane, so their results agree to the bit
//! (`tests/dispatch.rs`).

/// Four `f64` lanes and the lane-wise arithmetic a packed derivative program needs. The value
/// of the implementing type is a token: the AVX2 lanes exist only where the processor has AVX2.
pub trait Lanes: Copy {
    /// Whether the derivatives run their packed program in these lanes. Where they are not
    /// registers ([`Portable`]) the four-lane program is slower than the one-direction-at-a-time
    /// one it replaces, so that one runs instead.
    const PACKED: bool;
    /// Four `f64`.
    type V: Copy;
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
    /// The four lanes.
    fn lanes(self, a: Self::V) -> [f64; 4];
}

/// Lanes as an array of four, for any processor.
#[derive(Clone, Copy, Debug, Default)]
pub struct Portable;

impl Lanes for Portable {
    const PACKED: bool = false;
    type V = [f64; 4];
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
        __m256d, _mm256_add_pd, _mm256_mul_pd, _mm256_set1_pd, _mm256_setr_pd, _mm256_storeu_pd,
        _mm256_sub_pd, _mm256_xor_pd,
    };

    use super::Lanes;

    /// Lanes in one AVX2 register. A value of this type is the proof that the processor runs
    /// AVX2: only [`dispatch`](crate::dispatch::dispatch) makes one, after asking it (or in a
    /// build that targets AVX2).
    #[derive(Clone, Copy, Debug)]
    pub struct Avx2(());

    impl Avx2 {
        /// The token.
        ///
        /// # Safety
        ///
        /// The processor must support AVX2.
        #[inline(always)]
        pub(crate) unsafe fn new() -> Self {
            Self(())
        }
    }

    // SAFETY (every block below): an `Avx2` exists only where the processor has AVX2, and
    // these are its instructions on values in registers.
    impl Lanes for Avx2 {
        const PACKED: bool = true;
        type V = __m256d;
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

    #[cfg(target_arch = "x86_64")]
    #[test]
    #[allow(unsafe_code)]
    fn avx2_lanes_match_portable_to_the_bit() {
        if !std::is_x86_feature_detected!("avx2") {
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
    }
}
