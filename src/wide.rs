//! Eight `f64` lanes, in which a reverse-mode program computes eight weighted rows at a time.
//!
//! The forward dynamics' derivatives of a spatial arm run the inverse dynamics backward from the
//! torques weighted by the rows of `-M^-1` (`programs::adjoint` in the engine), one lane per row.
//! A seven-joint arm has seven rows: one group of eight lanes. Where the processor has AVX-512
//! that group is one register ([`Avx512`]'s [`Zmm`]), and the program is half the instructions
//! of two groups of four; elsewhere it is a [`Pair`] of four-lane values, the same instructions
//! as two groups. Every implementation applies the same IEEE operation to each lane, fused
//! multiply-adds rounded once, so their results agree to the bit (`tests/dispatch.rs`).

use crate::lanes::Lanes;

/// Eight `f64` lanes and the lane-wise arithmetic of a reverse-mode program: [`Lanes`]' with
/// eight lanes.
pub trait Wide: Copy {
    /// Eight `f64`.
    type V: Copy;
    /// The lanes `c`.
    fn constant(self, c: [f64; 8]) -> Self::V;
    /// `x` in every lane.
    fn splat(self, x: f64) -> Self::V;
    /// Lane-wise `a + b`.
    fn add(self, a: Self::V, b: Self::V) -> Self::V;
    /// Lane-wise `a - b`.
    fn sub(self, a: Self::V, b: Self::V) -> Self::V;
    /// Lane-wise `a * b`.
    fn mul(self, a: Self::V, b: Self::V) -> Self::V;
    /// Lane-wise `-a` (the sign flipped).
    fn neg(self, a: Self::V) -> Self::V;
    /// Lane-wise `a * s + c`, rounded once.
    fn mul_add(self, a: Self::V, s: f64, c: Self::V) -> Self::V;
    /// Lane-wise `c - a * s`, rounded once.
    fn neg_mul_add(self, a: Self::V, s: f64, c: Self::V) -> Self::V;
    /// Lane-wise `a * s - c`, rounded once.
    fn mul_sub(self, a: Self::V, s: f64, c: Self::V) -> Self::V;
    /// The eight lanes.
    fn lanes(self, a: Self::V) -> [f64; 8];
}

/// Eight lanes as two values of four-lane `L`: the first holds lanes 0-3.
#[derive(Clone, Copy, Debug)]
pub struct Pair<L>(pub L);

/// The lanes `[0, 4)` and `[4, 8)` of `c`.
#[inline(always)]
fn halves(c: [f64; 8]) -> ([f64; 4], [f64; 4]) {
    ([c[0], c[1], c[2], c[3]], [c[4], c[5], c[6], c[7]])
}

impl<L: Lanes> Wide for Pair<L> {
    type V = (L::V, L::V);
    #[inline(always)]
    fn constant(self, c: [f64; 8]) -> Self::V {
        let (a, b) = halves(c);
        (self.0.constant(a), self.0.constant(b))
    }
    #[inline(always)]
    fn splat(self, x: f64) -> Self::V {
        (self.0.splat(x), self.0.splat(x))
    }
    #[inline(always)]
    fn add(self, a: Self::V, b: Self::V) -> Self::V {
        (self.0.add(a.0, b.0), self.0.add(a.1, b.1))
    }
    #[inline(always)]
    fn sub(self, a: Self::V, b: Self::V) -> Self::V {
        (self.0.sub(a.0, b.0), self.0.sub(a.1, b.1))
    }
    #[inline(always)]
    fn mul(self, a: Self::V, b: Self::V) -> Self::V {
        (self.0.mul(a.0, b.0), self.0.mul(a.1, b.1))
    }
    #[inline(always)]
    fn neg(self, a: Self::V) -> Self::V {
        (self.0.neg(a.0), self.0.neg(a.1))
    }
    #[inline(always)]
    fn mul_add(self, a: Self::V, s: f64, c: Self::V) -> Self::V {
        (self.0.mul_add(a.0, s, c.0), self.0.mul_add(a.1, s, c.1))
    }
    #[inline(always)]
    fn neg_mul_add(self, a: Self::V, s: f64, c: Self::V) -> Self::V {
        (
            self.0.neg_mul_add(a.0, s, c.0),
            self.0.neg_mul_add(a.1, s, c.1),
        )
    }
    #[inline(always)]
    fn mul_sub(self, a: Self::V, s: f64, c: Self::V) -> Self::V {
        (self.0.mul_sub(a.0, s, c.0), self.0.mul_sub(a.1, s, c.1))
    }
    #[inline(always)]
    fn lanes(self, a: Self::V) -> [f64; 8] {
        let (x, y) = (self.0.lanes(a.0), self.0.lanes(a.1));
        [x[0], x[1], x[2], x[3], y[0], y[1], y[2], y[3]]
    }
}

// Made only by `dispatch_wide`, in the builds that have an AVX-512 copy.
#[cfg(target_arch = "x86_64")]
#[allow(unused_imports)]
pub(crate) use avx512::{Avx512, Zmm};

#[cfg(target_arch = "x86_64")]
#[allow(unsafe_code)]
// Unused in the builds that have no AVX-512 copy (`dev`, `no_std`).
#[allow(dead_code)]
mod avx512 {
    use core::arch::x86_64::{
        __m512d, _mm512_add_pd, _mm512_castpd_si512, _mm512_castsi512_pd, _mm512_fmadd_pd,
        _mm512_fmsub_pd, _mm512_fnmadd_pd, _mm512_loadu_pd, _mm512_mul_pd, _mm512_set1_epi64,
        _mm512_set1_pd, _mm512_storeu_pd, _mm512_sub_pd, _mm512_xor_si512,
    };

    use super::Wide;
    use crate::lanes::{Avx2, Lanes};

    /// Four lanes in an AVX2 register and eight in an AVX-512 one. A value of this type is the
    /// proof that the processor runs AVX-512F (and so AVX2 and FMA): only
    /// [`dispatch_wide`](crate::dispatch::dispatch_wide) makes one, after asking it (or in a
    /// build that targets it).
    #[derive(Clone, Copy, Debug)]
    pub struct Avx512(Avx2);

    impl Avx512 {
        /// The token.
        ///
        /// # Safety
        ///
        /// The processor must support AVX-512F, AVX2 and FMA.
        #[inline(always)]
        pub(crate) unsafe fn new() -> Self {
            // SAFETY: the caller's.
            Self(unsafe { Avx2::new() })
        }
    }

    // Four lanes as `Avx2` computes them: AVX-512F has AVX2 and FMA.
    impl Lanes for Avx512 {
        const PACKED: bool = true;
        type V = <Avx2 as Lanes>::V;
        type Wide = Zmm;
        #[inline(always)]
        fn wide(self) -> Zmm {
            Zmm(())
        }
        #[inline(always)]
        fn constant(self, c: [f64; 4]) -> Self::V {
            self.0.constant(c)
        }
        #[inline(always)]
        fn splat(self, x: f64) -> Self::V {
            self.0.splat(x)
        }
        #[inline(always)]
        fn add(self, a: Self::V, b: Self::V) -> Self::V {
            self.0.add(a, b)
        }
        #[inline(always)]
        fn sub(self, a: Self::V, b: Self::V) -> Self::V {
            self.0.sub(a, b)
        }
        #[inline(always)]
        fn mul(self, a: Self::V, b: Self::V) -> Self::V {
            self.0.mul(a, b)
        }
        #[inline(always)]
        fn neg(self, a: Self::V) -> Self::V {
            self.0.neg(a)
        }
        #[inline(always)]
        fn mul_add(self, a: Self::V, s: f64, c: Self::V) -> Self::V {
            self.0.mul_add(a, s, c)
        }
        #[inline(always)]
        fn neg_mul_add(self, a: Self::V, s: f64, c: Self::V) -> Self::V {
            self.0.neg_mul_add(a, s, c)
        }
        #[inline(always)]
        fn mul_sub(self, a: Self::V, s: f64, c: Self::V) -> Self::V {
            self.0.mul_sub(a, s, c)
        }
        #[inline(always)]
        fn lanes(self, a: Self::V) -> [f64; 4] {
            self.0.lanes(a)
        }
    }

    /// Eight lanes in one AVX-512 register, made by [`Avx512::wide`](Lanes::wide).
    #[derive(Clone, Copy, Debug)]
    pub struct Zmm(());

    // SAFETY (every block below): a `Zmm` comes only from an `Avx512`, which exists only where
    // the processor has AVX-512F, and these are its instructions on values in registers.
    impl Wide for Zmm {
        type V = __m512d;
        #[inline(always)]
        fn constant(self, c: [f64; 8]) -> __m512d {
            unsafe { _mm512_loadu_pd(c.as_ptr()) }
        }
        #[inline(always)]
        fn splat(self, x: f64) -> __m512d {
            unsafe { _mm512_set1_pd(x) }
        }
        #[inline(always)]
        fn add(self, a: __m512d, b: __m512d) -> __m512d {
            unsafe { _mm512_add_pd(a, b) }
        }
        #[inline(always)]
        fn sub(self, a: __m512d, b: __m512d) -> __m512d {
            unsafe { _mm512_sub_pd(a, b) }
        }
        #[inline(always)]
        fn mul(self, a: __m512d, b: __m512d) -> __m512d {
            unsafe { _mm512_mul_pd(a, b) }
        }
        // AVX-512F has no floating-point xor (that is AVX-512DQ): the sign bit flipped as an
        // integer.
        #[inline(always)]
        fn neg(self, a: __m512d) -> __m512d {
            unsafe {
                _mm512_castsi512_pd(_mm512_xor_si512(
                    _mm512_castpd_si512(a),
                    _mm512_set1_epi64(i64::MIN),
                ))
            }
        }
        #[inline(always)]
        fn mul_add(self, a: __m512d, s: f64, c: __m512d) -> __m512d {
            unsafe { _mm512_fmadd_pd(a, _mm512_set1_pd(s), c) }
        }
        #[inline(always)]
        fn neg_mul_add(self, a: __m512d, s: f64, c: __m512d) -> __m512d {
            unsafe { _mm512_fnmadd_pd(a, _mm512_set1_pd(s), c) }
        }
        #[inline(always)]
        fn mul_sub(self, a: __m512d, s: f64, c: __m512d) -> __m512d {
            unsafe { _mm512_fmsub_pd(a, _mm512_set1_pd(s), c) }
        }
        #[inline(always)]
        fn lanes(self, a: __m512d) -> [f64; 8] {
            let mut out = [0.0; 8];
            unsafe { _mm512_storeu_pd(out.as_mut_ptr(), a) };
            out
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{Pair, Wide};
    use crate::lanes::Portable;

    const X: [f64; 8] = [1.0 / 3.0, -2.5e-300, 7.0, -0.0, 0.1, -1e300, 2.0, 0.0];
    const Y: [f64; 8] = [3.0, 1e300, -0.1, 0.0, -0.7, 1e-300, 5.5, -0.0];

    fn bits(a: [f64; 8]) -> [u64; 8] {
        a.map(f64::to_bits)
    }

    /// Every operation of `w` against the lane-wise IEEE operation, to the bit.
    fn lane_wise<W: Wide>(w: W) {
        let (x, y) = (w.constant(X), w.constant(Y));
        let each = |f: &dyn Fn(f64, f64) -> f64| -> [u64; 8] {
            bits(core::array::from_fn(|l| f(X[l], Y[l])))
        };
        assert_eq!(bits(w.lanes(w.add(x, y))), each(&|a, b| a + b));
        assert_eq!(bits(w.lanes(w.sub(x, y))), each(&|a, b| a - b));
        assert_eq!(bits(w.lanes(w.mul(x, w.splat(0.7)))), each(&|a, _| a * 0.7));
        assert_eq!(bits(w.lanes(w.neg(x))), each(&|a, _| -a));
        // Rounded once: `(1 + e)(1 - e) - 1` is `-e^2`, not 0.
        let e = 2f64.powi(-30);
        let one = w.splat(1.0);
        let a = w.splat(1.0 + e);
        assert_eq!(w.lanes(w.mul_sub(a, 1.0 - e, one)), [-e * e; 8]);
        for s in [1.0 - e, 0.7, -3.0] {
            assert_eq!(
                bits(w.lanes(w.mul_add(x, s, y))),
                each(&|a, b| a.mul_add(s, b))
            );
            assert_eq!(
                bits(w.lanes(w.neg_mul_add(x, s, y))),
                each(&|a, b| (-a).mul_add(s, b))
            );
            assert_eq!(
                bits(w.lanes(w.mul_sub(x, s, y))),
                each(&|a, b| a.mul_add(s, -b))
            );
        }
    }

    #[test]
    fn portable_pairs_are_lane_wise() {
        lane_wise(Pair(Portable));
    }

    #[cfg(target_arch = "x86_64")]
    #[test]
    #[allow(unsafe_code)]
    fn avx2_pairs_and_avx512_registers_are_lane_wise() {
        use crate::lanes::Lanes;
        if std::is_x86_feature_detected!("avx2") && std::is_x86_feature_detected!("fma") {
            // SAFETY: just asked.
            lane_wise(unsafe { crate::lanes::Avx2::new() }.wide());
        }
        if std::is_x86_feature_detected!("avx512f") {
            // SAFETY: just asked.
            lane_wise(unsafe { super::Avx512::new() }.wide());
        }
    }
}
