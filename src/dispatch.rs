//! The derivatives of the dynamics and a spatial arm's base regressor run in a copy compiled for
//! AVX2 and FMA where the processor has them (and a spatial arm's forward derivatives in a third,
//! for AVX-512, where it has that: [`dispatch_wide`]).
//!
//! `inverse_dynamics_derivatives` is thousands of straight-line operations, too long for the
//! baseline x86-64 instruction set's two-operand SSE2 forms: the PUMA 560's compiled to 7,900
//! instructions and 51 KB, a third of them register copies and stack reloads, past the
//! processor's first-level instruction cache. The same source compiled with AVX2's
//! three-operand forms is 34 KB and ran 1.9-2.8x faster (docs/performance.md). A
//! user's build passes no `target-cpu`, so the crate compiles these methods twice, as BLAS
//! libraries do, and chooses at run time: [`dispatch`] asks the processor (the standard library
//! caches the answer) and runs the AVX2 copy where it can. That copy enables FMA too, which
//! every processor with AVX2 has, for the packed programs' fused multiply-adds.
//!
//! Each copy hands the body its lanes (src/lanes.rs). Where they are AVX2 registers, a spatial
//! arm's inverse derivatives run the packed program the derive emits beside the one-direction
//! program, four directions per register: 1.6-3.6x faster again (docs/performance.md). The
//! baseline copy, `dev` builds and other processors run the one-direction program, which
//! portable lanes would only slow down (more operations, none of them in vector registers).
//!
//! Otherwise the two copies compute the same function to the bit: Rust does not contract
//! `a * b + c` into a fused multiply-add unless asked, so enabling AVX2 and FMA changes the
//! instructions and not the rounding. The packed program adds the same terms in another order
//! and asks for its fused multiply-adds (`Lanes::mul_add`, rounded once), so it agrees with the
//! one-direction program to rounding, and to the bit with itself in portable lanes, whose
//! `mul_add` is IEEE's (`tests/dispatch.rs` checks both in an optimised build).
//!
//! Only optimised builds without debug assertions (Cargo's `release` and `bench` profiles) on
//! x86-64 with `std` compile the second copy: a `dev` build would spend compile time on a copy
//! it does not optimise, and without `std` there is no run-time detection. Where the build
//! already targets AVX2 and FMA (`-C target-cpu=native`), there is one copy, with AVX2 lanes,
//! and no question asked.
//!
//! A spatial arm's `forward_dynamics_derivatives` runs through [`dispatch_wide`], which has a
//! third copy, compiled for AVX-512F, chosen where the processor has it (in a build that does
//! not already target AVX2 and FMA; one that does runs the AVX2 lanes, as [`dispatch`]): its reverse-mode
//! program computes the seven rows of a seven-joint arm in one 512-bit register (src/wide.rs),
//! half the instructions of two AVX2 groups. Only that method has the third copy, so the
//! others cost a user's build no more.
//!
//! A spatial arm's `base_regressor` runs through it too, with a packed program that carries
//! four joints per register (`programs::spatial_regressor` in the engine). Its result is large
//! (the PUMA's 1.7 KB), which is why each copy writes its result through a pointer: returned by
//! value, it was copied once more after the call, and with the one-direction program in both
//! copies the dispatched regressors were then 5-25 % slower than one baseline copy
//! (docs/performance.md). The full `regressor` has one copy: its packed body would add 2 s to
//! a release build deriving the Panda.

use crate::lanes::{Lanes, Portable};

/// A method's body, with its arm and inputs: what [`dispatch`] runs.
pub trait Kernel {
    /// What the method returns.
    type Output;
    /// Runs the body in `lanes` (see `src/lanes.rs`). Implementations are `#[inline(always)]`,
    /// so that the body is compiled into each copy of [`dispatch`]'s caller.
    fn run<L: Lanes>(self, lanes: L) -> Self::Output;
}

/// Runs `k`, in the AVX2 copy where the build has one and the processor can run it.
#[inline(always)]
pub fn dispatch<K: Kernel>(k: K) -> K::Output {
    #[cfg(all(
        target_arch = "x86_64",
        feature = "std",
        not(debug_assertions),
        not(all(target_feature = "avx2", target_feature = "fma"))
    ))]
    {
        return copies::run(k);
    }
    #[cfg(all(
        target_arch = "x86_64",
        target_feature = "avx2",
        target_feature = "fma"
    ))]
    {
        // SAFETY: the build targets AVX2 and FMA, so every processor that runs it has both.
        #[allow(unsafe_code)]
        return k.run(unsafe { crate::lanes::Avx2::new() });
    }
    #[allow(unreachable_code)]
    k.run(Portable)
}

/// Runs `k` as [`dispatch`] does, or in a third copy, compiled for AVX-512, where the build has
/// one and the processor can run it: the forward dynamics' derivatives of a spatial arm, whose
/// reverse-mode program computes eight rows in one AVX-512 register (src/wide.rs).
#[inline(always)]
pub fn dispatch_wide<K: Kernel>(k: K) -> K::Output {
    #[cfg(all(
        target_arch = "x86_64",
        feature = "std",
        not(debug_assertions),
        not(all(target_feature = "avx2", target_feature = "fma"))
    ))]
    {
        return copies::run_wide(k);
    }
    #[cfg(all(target_arch = "x86_64", target_feature = "avx512f"))]
    {
        // SAFETY: the build targets AVX-512F, so every processor that runs it has it.
        #[allow(unsafe_code)]
        return k.run(unsafe { crate::wide::Avx512::new() });
    }
    #[allow(unreachable_code)]
    dispatch(k)
}

/// The copies of a kernel (two, or three for [`dispatch_wide`]), and the choice between them.
#[cfg(all(
    target_arch = "x86_64",
    feature = "std",
    not(debug_assertions),
    not(all(target_feature = "avx2", target_feature = "fma"))
))]
#[allow(unsafe_code)]
mod copies {
    use core::mem::MaybeUninit;

    use super::Kernel;
    use crate::lanes::{Avx2, Portable};

    /// A copy of a kernel: it writes the kernel's result into `out`.
    type Copy<K> = unsafe fn(K, &mut MaybeUninit<<K as Kernel>::Output>);

    /// The copy is chosen as a function pointer and writes its result through a pointer, so
    /// that one call writes it where the caller wants it. A value returned from either of two
    /// calls was copied once more after them (the Panda's base regressor, 2.4 KB), and the
    /// copy's wide loads waited for the body's last stores: 20-25 % of the call
    /// (docs/performance.md).
    #[inline(always)]
    pub(super) fn run<K: Kernel>(k: K) -> K::Output {
        // SAFETY: `two` asks the processor.
        unsafe { call(k, two::<K>()) }
    }

    /// [`run`] with a third copy, [`avx512`], where the processor has AVX-512F.
    #[inline(always)]
    pub(super) fn run_wide<K: Kernel>(k: K) -> K::Output {
        let copy: Copy<K> = if std::is_x86_feature_detected!("avx512f")
            && std::is_x86_feature_detected!("avx2")
            && std::is_x86_feature_detected!("fma")
        {
            avx512::<K>
        } else {
            two::<K>()
        };
        // SAFETY: `avx512` is chosen only where the processor has just said that it supports
        // AVX-512F, AVX2 and FMA; `two` asks the processor.
        unsafe { call(k, copy) }
    }

    /// [`avx2`] where the processor has AVX2 and FMA, else [`baseline`].
    #[inline(always)]
    fn two<K: Kernel>() -> Copy<K> {
        if std::is_x86_feature_detected!("avx2") && std::is_x86_feature_detected!("fma") {
            avx2::<K>
        } else {
            baseline::<K>
        }
    }

    /// `copy(k)`'s result.
    ///
    /// # Safety
    ///
    /// The processor must support what `copy` was compiled for.
    #[inline(always)]
    unsafe fn call<K: Kernel>(k: K, copy: Copy<K>) -> K::Output {
        let mut out = MaybeUninit::uninit();
        // SAFETY: the caller's.
        unsafe { copy(k, &mut out) };
        // SAFETY: every copy writes `out` when it returns; a panic in the body unwinds past
        // this line.
        unsafe { out.assume_init() }
    }

    /// `k.run()` compiled with AVX-512F enabled, into `out`.
    ///
    /// # Safety
    ///
    /// The processor must support AVX-512F, AVX2 and FMA.
    #[target_feature(enable = "avx512f,avx2,fma")]
    unsafe fn avx512<K: Kernel>(k: K, out: &mut MaybeUninit<K::Output>) {
        // SAFETY: the caller has asked the processor.
        out.write(k.run(unsafe { crate::wide::Avx512::new() }));
    }

    /// `k.run()` compiled with AVX2 and FMA enabled (the body is inlined into it), into `out`.
    ///
    /// # Safety
    ///
    /// The processor must support AVX2 and FMA.
    #[target_feature(enable = "avx2,fma")]
    unsafe fn avx2<K: Kernel>(k: K, out: &mut MaybeUninit<K::Output>) {
        // SAFETY: the caller has asked the processor.
        out.write(k.run(unsafe { Avx2::new() }));
    }

    /// `k.run()` in the baseline copy, into `out`: one function per kernel, however many places
    /// call [`dispatch`](super::dispatch), so that a method's body is compiled twice and no
    /// more.
    #[inline(never)]
    fn baseline<K: Kernel>(k: K, out: &mut MaybeUninit<K::Output>) {
        out.write(k.run(Portable));
    }
}

/// A [`Kernel`] per dispatched method: the arm and the method's inputs, run by calling the
/// arm's hidden `__NAME_kernel`, which holds the generated body, or where the lanes are
/// registers `__NAME_packed`, which holds the packed one (src/lanes.rs).
macro_rules! kernels {
    ($(
        $(#[$doc:meta])*
        $name:ident<$($c:ident),*> : $bound:path
            => $method:ident, $packed:ident ($($arg:ident),*) -> $out:ty;
    )*) => {$(
        $(#[$doc])*
        pub struct $name<'a, A: ?Sized, $(const $c: usize),*> {
            /// The arm.
            pub arm: &'a A,
            $(
                /// An input of the method.
                pub $arg: &'a nalgebra::SVector<f64, N>,
            )*
        }

        impl<A: $bound + ?Sized, $(const $c: usize),*> Kernel for $name<'_, A, $($c),*> {
            type Output = $out;
            #[inline(always)]
            fn run<L: Lanes>(self, lanes: L) -> Self::Output {
                // A constant condition: the other branch is not even compiled.
                if L::PACKED {
                    self.arm.$packed(lanes, $(self.$arg),*)
                } else {
                    self.arm.$method($(self.$arg),*)
                }
            }
        }
    )*};
}

kernels! {
    /// `inverse_dynamics_derivatives`.
    InverseDynamicsDerivatives<N>: crate::Dynamics<N>
        => __inverse_dynamics_derivatives_kernel, __inverse_dynamics_derivatives_packed(q, qd, qdd)
        -> (nalgebra::SMatrix<f64, N, N>, nalgebra::SMatrix<f64, N, N>);
    /// `forward_dynamics_derivatives`: its default calls the dispatched inverse derivatives; a
    /// spatial arm's packed body runs its reverse-mode program (src/wide.rs).
    ForwardDynamicsDerivatives<N>: crate::Dynamics<N>
        => __forward_dynamics_derivatives_kernel, __forward_dynamics_derivatives_packed(q, qd, tau)
        -> (
            nalgebra::SMatrix<f64, N, N>,
            nalgebra::SMatrix<f64, N, N>,
            nalgebra::SMatrix<f64, N, N>,
        );
    /// `Identification::base_regressor` of an arm whose base regressor has a packed program.
    BaseRegressor<N, P, B>: crate::Identification<N, P, B>
        => __base_regressor_kernel, __base_regressor_packed(q, qd, qdd)
        -> nalgebra::SMatrix<f64, N, B>;
}

#[cfg(test)]
mod tests {
    use super::{dispatch, Kernel};
    use crate::lanes::Lanes;

    /// A long chain of dependent operations, to see that a kernel's result is its body's.
    struct Chain(f64);

    impl Kernel for Chain {
        type Output = f64;
        #[inline(always)]
        fn run<L: Lanes>(self, _: L) -> f64 {
            let mut x = self.0;
            for k in 0..64 {
                x = x * 1.000_000_1 + f64::from(k) * 1e-3;
            }
            x
        }
    }

    #[test]
    fn dispatch_runs_the_kernel() {
        let direct = Chain(0.75).run(crate::lanes::Portable);
        let dispatched = dispatch(Chain(0.75));
        assert_eq!(direct.to_bits(), dispatched.to_bits());
        assert!((direct - 2.766).abs() < 1e-2, "{direct}");
    }
}
