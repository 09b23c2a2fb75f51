//! The joint angles' sines and cosines, all at once.
//!
//! Every generated method starts by evaluating `(sin q_j, cos q_j)` for the joints it needs,
//! and for a two- to four-link arm that trigonometry is most of the run time: a call to the C
//! library's `sincos` costs as much as the rest of the inverse dynamics. The generated code
//! knows all its angles up front, so it hands them to [`sin_cos`] in one array, which
//! evaluates them four at a time: a branch-free table-and-polynomial kernel on the `wide`
//! crate's `f64x4` (two SSE2 registers on a default `x86_64` build, one AVX register where AVX
//! is enabled, plain arrays on targets without SIMD). It is safe, portable Rust, and since
//! Rust neither contracts nor reorders floating-point operations, every target with IEEE
//! double arithmetic gets the same bits, whichever lane an angle lands in (the `WideF64x4` batch
//! scalar excepted where the target has AVX and FMA: its kernel fuses each multiply-add,
//! `trig/fused.rs`, and differs from this one by 1 ulp in about 1.5e-5 of values). On the benchmark
//! machine (`docs/performance.md`, 2026-12-03) it costs 0.5-0.7x as much as `f64::sin_cos` for
//! one angle and down to a fifth per angle for eight.
//!
//! # Algorithm
//!
//! For each angle `x`: `m = round(x / h)` with `h = pi/128` (by adding and subtracting
//! `1.5 * 2^52`, whose low bits then hold `m` in two's complement), then the Cody-Waite
//! reduction `t = ((x - m H1) - m H2) - m H3` with `h = H1 + H2 + H3` split so that `H1` and
//! `H2` have 26 significant bits (so `m H1` and `m H2` are exact for `|m| <= 2^27`, and
//! `x - m H1` is exact by Sterbenz's lemma), leaving `|t| <= pi/256`. On that small interval
//! short Taylor polynomials suffice: `sin t - t` to `t^7` and `cos t - 1` to `t^6` (truncation
//! below `2^-69` of `sin t` and `2^-66` of `cos t`). With `(S, C) = (sin m h, cos m h)` from a 256-entry table
//! (2 KiB, correctly rounded, written by `scripts/sin_table.py` and checked by a test here):
//!
//! ```text
//! sin x = S + (S (cos t - 1) + C sin t)
//! cos x = C + (C (cos t - 1) - S sin t)
//! ```
//!
//! The large table value is added last, so the result is rounded about once. No branch, and
//! about 30 floating-point operations and two loads per angle, against the 50 or so of a
//! table-free kernel on `|t| <= pi/4` (degree-13 polynomials), which measured 1.1-1.5x slower.
//!
//! # Accuracy and range
//!
//! Tested in this module against `f64::sin_cos` (which is correctly rounded in practice) on
//! 3.6 million deterministic pseudo-random angles up to `|x| = 1.6e6` (the documented range of
//! every generated method is `1e6`), on angles next to multiples of `pi/2` and on tiny and
//! subnormal ones: each value is within **2 ulp** of the standard library's, or within
//! `2^-80` (8e-25) of it in absolute terms. The second clause is needed near the zeros of sine
//! and cosine of large angles: there the reduction's own error, below `|x| 2^-105` (the
//! precision of `h`), is many ulp of the tiny result (`cos(871790.3905748408)`, about
//! `-4e-16`, is off by 4e-27: 81,639 ulp, but under the absolute bound). Only the absolute
//! error reaches a torque. Most results are bit-identical (the test prints the shares).
//! The sign of a zero is not kept: `sin(-0.0)` is `+0.0`.
//!
//! Beyond `|x| = 2^20 pi/2` (about `1.6e6`), and for NaN and infinities, the angle goes to
//! `f64::sin_cos` instead (per angle, so the others in the array are unaffected): the result is
//! then exactly the standard library's, and a NaN or infinite angle gives NaN.

#[cfg(not(feature = "std"))]
use num_traits::Float as _;
/// `128 / pi`.
const INV_H: f64 = f64::from_bits(0x4044_5F30_6DC9_C883);
/// The first 26 bits of `h = pi/128`.
const H1: f64 = f64::from_bits(0x3F99_21FB_5000_0000);
/// The next 26 bits of `h`.
const H2: f64 = f64::from_bits(0x3DF1_10B4_6000_0000);
/// `h - H1 - H2`, rounded: `h` to 105 bits in all.
const H3: f64 = f64::from_bits(0x3C31_A626_3314_5C07);
/// `1.5 * 2^52`: adding and subtracting it rounds to an integer (ties to even).
const TO_INT: f64 = 6_755_399_441_055_744.0;
/// `2^20 pi/2`, below the `2^27 h` where the reduction stops being exact.
const LIMIT: f64 = 1_647_099.0;

/// `(sin q_j, cos q_j)` for every angle of `q`, evaluated four at a time (see the
/// [module](self) docs for the algorithm and its accuracy).
///
/// ```
/// let [(s1, c1), (s2, c2)] = planar_arm::trig::sin_cos([0.5, -2.0]);
/// let close = |a: f64, b: f64| (a - b).abs() <= 2.0 * f64::EPSILON;
/// assert!(close(s1, 0.5_f64.sin()) && close(c1, 0.5_f64.cos()));
/// assert!(close(s2, (-2.0_f64).sin()) && close(c2, (-2.0_f64).cos()));
/// ```
///
/// In a build with debug assertions (Cargo's `dev` profile) the same kernel runs out of line,
/// in one non-generic function compiled with this crate, so that a user's crate does not
/// compile the kernel again for each array length its methods use; same operations, same bits.
#[inline(always)]
#[must_use]
pub fn sin_cos<const N: usize>(q: [f64; N]) -> [(f64, f64); N] {
    #[cfg(not(debug_assertions))]
    {
        packed(q)
    }
    #[cfg(debug_assertions)]
    {
        let mut out = [(0.0, 0.0); N];
        out_of_line(&q, &mut out);
        out
    }
}

/// [`sin_cos`] inlined into its caller, as optimised builds run it: out of line, the results
/// go through memory, 1.5x slower at N = 2.
///
/// Four angles per `wide::f64x4` (two SSE2 registers with the default `x86_64` flags, one AVX
/// register with AVX), three left over in one with a dummy fourth lane, two in an `f64x2`, a
/// last one alone. Spelled out in `wide`'s types, not left to the compiler's vectoriser: the
/// pairs of the array form were packed into one register in some callers and not in others
/// (compiled as scalar code when `sin_cos` was called directly), and against that form this is
/// 1.0-1.3x faster for M, inverse and forward dynamics and M with the bias at N = 2..8, with
/// default flags and with AVX2, the same bits (docs/performance.md).
///
/// Not in a `dev` build: there nothing is inlined anyway, and every user crate would compile
/// this function's kernels again for each `N` its generated methods use (at six links half the
/// LLVM IR of a crate that calls four of them, and 0.08 s of its 0.74 s clean rebuild,
/// docs/performance.md). [`out_of_line`] does the same operations on each angle, so both give
/// the same bits (tested).
#[cfg_attr(debug_assertions, allow(dead_code))]
#[inline(always)]
fn packed<const N: usize>(q: [f64; N]) -> [(f64, f64); N] {
    use wide::{f64x2, f64x4};
    let mut out = [(0.0, 0.0); N];
    let mut j = 0;
    while j + 3 <= N {
        let fourth = if j + 3 < N { q[j + 3] } else { 0.0 };
        let (s, c) = packed_kernel(f64x4::from([q[j], q[j + 1], q[j + 2], fourth]));
        let (s, c) = (s.to_array(), c.to_array());
        let mut l = 0;
        while l < 4 && j + l < N {
            out[j + l] = (s[l], c[l]);
            l += 1;
        }
        j += 4;
    }
    if j + 2 == N {
        let (s, c) = packed_kernel(f64x2::from([q[j], q[j + 1]]));
        let (s, c) = (s.to_array(), c.to_array());
        out[j] = (s[0], c[0]);
        out[j + 1] = (s[1], c[1]);
    } else if j + 1 == N {
        [out[j]] = kernel([q[j]]);
    }
    // One test for the whole array keeps the common path free of per-angle branches (a
    // per-angle test alone made the kernel 1.4x slower at N = 2..4).
    if !in_range(&q) {
        out = outside_the_range_of(q, out);
    }
    out
}

/// [`outside_the_range`] by value: a reference to `out` taken on the cold path would keep
/// `out` in memory on the hot one too, where writing each `(sin, cos)` pair from two vectors
/// and reading the array back as a whole stalled on store forwarding (two angles called
/// directly: 2.7x slower in the dynamics bench).
#[cfg_attr(debug_assertions, allow(dead_code))]
#[cold]
#[inline(never)]
fn outside_the_range_of<const N: usize>(q: [f64; N], mut out: [(f64, f64); N]) -> [(f64, f64); N] {
    outside_the_range(&q, &mut out);
    out
}

/// [`packed`] over slices (`out` as long as `q`), compiled once, in this crate, one angle at
/// a time: a `dev` build runs it unoptimised, so packing would buy nothing there, and each
/// lane of every form of the kernel does the same operations.
#[cfg_attr(not(debug_assertions), allow(dead_code))]
#[inline(never)]
fn out_of_line(q: &[f64], out: &mut [(f64, f64)]) {
    for (&x, o) in q.iter().zip(out.iter_mut()) {
        [*o] = kernel([x]);
    }
    if !in_range(q) {
        outside_the_range(q, out);
    }
}

/// Whether every angle is within the kernel's range (false for NaN).
#[inline(always)]
fn in_range(q: &[f64]) -> bool {
    let mut all = true;
    for x in q {
        all &= x.abs() <= LIMIT;
    }
    all
}

/// `(sin x_i, cos x_i)` for the `L` lanes of a batch in the array form of the kernel (the
/// `f32` batches: at eight lanes it measured faster than two calls of [`sin_cos_x4`]).
#[cfg(feature = "std")]
#[inline(always)]
#[must_use]
pub(crate) fn sin_cos_lanes<const L: usize>(x: [f64; L]) -> ([f64; L], [f64; L]) {
    let mut out = kernel(x);
    if !in_range(&x) {
        outside_the_range(&x, &mut out);
    }
    (out.map(|(s, _)| s), out.map(|(_, c)| c))
}

/// `(sin x_i, cos x_i)` for the four lanes of `wide`'s `f64x4`, for the batch scalars of
/// [`Real`](crate::Real): [`packed_kernel`] (so bit for bit the results of [`sin_cos`]), or
/// where the target has AVX and FMA its fused form ([`fused`]: within 4 ulp of [`sin_cos`]),
/// lanes out of range to `f64::sin_cos`. Not the array form of the kernel, which at four lanes
/// measured no faster than two calls at two lanes (83 against 86 ns for 4 x 6 angles with
/// AVX2; this form 52 ns).
#[cfg(feature = "std")]
#[inline(always)]
#[must_use]
pub(crate) fn sin_cos_x4(x: wide::f64x4) -> (wide::f64x4, wide::f64x4) {
    use wide::{f64x4, CmpLe};
    #[cfg(all(target_feature = "avx", target_feature = "fma"))]
    let (sin, cos) = fused::kernel(x);
    #[cfg(not(all(target_feature = "avx", target_feature = "fma")))]
    let (sin, cos) = packed_kernel(x);
    if x.abs().cmp_le(f64x4::splat(LIMIT)).all() {
        return (sin, cos);
    }
    let lanes = x.to_array();
    let mut out: [(f64, f64); 4] = core::array::from_fn(|i| (sin.to_array()[i], cos.to_array()[i]));
    outside_the_range(&lanes, &mut out);
    (
        f64x4::from(out.map(|(s, _)| s)),
        f64x4::from(out.map(|(_, c)| c)),
    )
}

#[cfg(any(
    test,
    all(feature = "std", target_feature = "avx", target_feature = "fma")
))]
mod fused;

/// A `wide` vector of `f64` lanes, for [`packed_kernel`].
trait Packed:
    Copy + core::ops::Add<Output = Self> + core::ops::Sub<Output = Self> + core::ops::Mul<Output = Self>
{
    fn splat(v: f64) -> Self;
    /// `SIN_TABLE[(k + offset) mod 256]` in each lane, `k` the low bits of the lane's `y` (see
    /// [`kernel`]); the one step that goes lane by lane.
    fn table(y: Self, offset: usize) -> Self;
}

macro_rules! impl_packed {
    ($($v:ident),*) => {$(
        impl Packed for wide::$v {
            #[inline(always)]
            fn splat(v: f64) -> Self {
                wide::$v::splat(v)
            }
            #[allow(clippy::cast_possible_truncation)]
            #[inline(always)]
            fn table(y: Self, offset: usize) -> Self {
                wide::$v::from(
                    y.to_array().map(|v| SIN_TABLE[(v.to_bits() as usize).wrapping_add(offset) & 255]),
                )
            }
        }
    )*};
}
impl_packed!(f64x2, f64x4);

/// [`kernel`] on whole `wide` registers: the same operations on every lane, so the same bits.
#[inline(always)]
fn packed_kernel<V: Packed>(x: V) -> (V, V) {
    let k = V::splat;
    let y = x * k(INV_H) + k(TO_INT);
    let m = y - k(TO_INT);
    let t = ((x - m * k(H1)) - m * k(H2)) - m * k(H3);
    let t2 = t * t;
    let p = k(-1.0 / 6.0) + t2 * (k(1.0 / 120.0) - t2 * k(1.0 / 5040.0));
    let sin_t = t + (t * t2) * p;
    let cos_t_minus_1 = t2 * (k(-0.5) + t2 * (k(1.0 / 24.0) - t2 * k(1.0 / 720.0)));
    let (s, c) = (V::table(y, 0), V::table(y, 64));
    let sin = s + (s * cos_t_minus_1 + c * sin_t);
    let cos = c + (c * cos_t_minus_1 - s * sin_t);
    (sin, cos)
}

/// The standard library's `sin_cos` for the angles the kernel does not cover.
#[cold]
#[inline(never)]
fn outside_the_range(q: &[f64], out: &mut [(f64, f64)]) {
    use core::cmp::Ordering::{Equal, Less};
    for (x, sc) in q.iter().zip(out) {
        // NaN compares as not in range: those go to the standard library too.
        let in_range = matches!(x.abs().partial_cmp(&LIMIT), Some(Less | Equal));
        if !in_range {
            *sc = x.sin_cos();
        }
    }
}

/// The kernel over `[f64; L]`, lane by lane: for a lone angle, and for the lanes of the `f32`
/// batches, where the compiler's SLP vectoriser packs it well (at eight lanes measured faster
/// than two calls of [`sin_cos_x4`]).
#[inline(always)]
fn kernel<const L: usize>(x: [f64; L]) -> [(f64, f64); L] {
    let y = lanes::<L>(|i| x[i] * INV_H + TO_INT);
    let m = lanes::<L>(|i| y[i] - TO_INT);
    let t = lanes::<L>(|i| ((x[i] - m[i] * H1) - m[i] * H2) - m[i] * H3);
    let t2 = lanes::<L>(|i| t[i] * t[i]);
    let sin_t = lanes::<L>(|i| {
        let p = -1.0 / 6.0 + t2[i] * (1.0 / 120.0 - t2[i] * (1.0 / 5040.0));
        t[i] + (t[i] * t2[i]) * p
    });
    let cos_t_minus_1 =
        lanes::<L>(|i| t2[i] * (-0.5 + t2[i] * (1.0 / 24.0 - t2[i] * (1.0 / 720.0))));
    // `m mod 256` from the low bits of `y = m + 1.5 * 2^52` (two's complement, so negative `m`
    // wrap correctly; `y` is that sum exactly, an integer below 2^53, so it is read rather
    // than `TO_INT` added back to `m`); `cos m h` is `sin (m + 64) h`. NaN and out-of-range
    // lanes index garbage but in bounds, and are replaced by the caller.
    #[allow(clippy::cast_possible_truncation)]
    let k = |i: usize| y[i].to_bits() as usize;
    let s = lanes::<L>(|i| SIN_TABLE[k(i) & 255]);
    let c = lanes::<L>(|i| SIN_TABLE[k(i).wrapping_add(64) & 255]);
    let sin = lanes::<L>(|i| s[i] + (s[i] * cos_t_minus_1[i] + c[i] * sin_t[i]));
    let cos = lanes::<L>(|i| c[i] + (c[i] * cos_t_minus_1[i] - s[i] * sin_t[i]));
    core::array::from_fn(|i| (sin[i], cos[i]))
}

#[inline(always)]
fn lanes<const L: usize>(f: impl Fn(usize) -> f64) -> [f64; L] {
    core::array::from_fn(f)
}

/// `sin(k pi/128)`, `k = 0..255`, correctly rounded (`scripts/sin_table.py`).
#[rustfmt::skip]
#[allow(clippy::approx_constant)] // sin(pi/4) is 1/sqrt(2), and written as the script prints it.
static SIN_TABLE: [f64; 256] = [
    0.0,
    0.024541228522912288,
    0.049067674327418015,
    0.07356456359966743,
    0.0980171403295606,
    0.1224106751992162,
    0.14673047445536175,
    0.17096188876030122,
    0.19509032201612828,
    0.2191012401568698,
    0.2429801799032639,
    0.26671275747489837,
    0.2902846772544624,
    0.31368174039889146,
    0.33688985339222005,
    0.35989503653498817,
    0.3826834323650898,
    0.40524131400498986,
    0.4275550934302821,
    0.4496113296546066,
    0.47139673682599764,
    0.49289819222978404,
    0.5141027441932218,
    0.5349976198870973,
    0.5555702330196022,
    0.5758081914178453,
    0.5956993044924334,
    0.6152315905806268,
    0.6343932841636455,
    0.6531728429537768,
    0.6715589548470184,
    0.6895405447370669,
    0.7071067811865476,
    0.7242470829514669,
    0.7409511253549591,
    0.7572088465064846,
    0.773010453362737,
    0.7883464276266062,
    0.8032075314806449,
    0.8175848131515837,
    0.8314696123025452,
    0.8448535652497071,
    0.8577286100002721,
    0.8700869911087115,
    0.881921264348355,
    0.8932243011955153,
    0.9039892931234433,
    0.9142097557035307,
    0.9238795325112867,
    0.9329927988347388,
    0.9415440651830208,
    0.9495281805930367,
    0.9569403357322088,
    0.9637760657954398,
    0.970031253194544,
    0.9757021300385286,
    0.9807852804032304,
    0.9852776423889412,
    0.989176509964781,
    0.99247953459871,
    0.9951847266721969,
    0.9972904566786902,
    0.9987954562051724,
    0.9996988186962042,
    1.0,
    0.9996988186962042,
    0.9987954562051724,
    0.9972904566786902,
    0.9951847266721969,
    0.99247953459871,
    0.989176509964781,
    0.9852776423889412,
    0.9807852804032304,
    0.9757021300385286,
    0.970031253194544,
    0.9637760657954398,
    0.9569403357322088,
    0.9495281805930367,
    0.9415440651830208,
    0.9329927988347388,
    0.9238795325112867,
    0.9142097557035307,
    0.9039892931234433,
    0.8932243011955153,
    0.881921264348355,
    0.8700869911087115,
    0.8577286100002721,
    0.8448535652497071,
    0.8314696123025452,
    0.8175848131515837,
    0.8032075314806449,
    0.7883464276266062,
    0.773010453362737,
    0.7572088465064846,
    0.7409511253549591,
    0.7242470829514669,
    0.7071067811865476,
    0.6895405447370669,
    0.6715589548470184,
    0.6531728429537768,
    0.6343932841636455,
    0.6152315905806268,
    0.5956993044924334,
    0.5758081914178453,
    0.5555702330196022,
    0.5349976198870973,
    0.5141027441932218,
    0.49289819222978404,
    0.47139673682599764,
    0.4496113296546066,
    0.4275550934302821,
    0.40524131400498986,
    0.3826834323650898,
    0.35989503653498817,
    0.33688985339222005,
    0.31368174039889146,
    0.2902846772544624,
    0.26671275747489837,
    0.2429801799032639,
    0.2191012401568698,
    0.19509032201612828,
    0.17096188876030122,
    0.14673047445536175,
    0.1224106751992162,
    0.0980171403295606,
    0.07356456359966743,
    0.049067674327418015,
    0.024541228522912288,
    0.0,
    -0.024541228522912288,
    -0.049067674327418015,
    -0.07356456359966743,
    -0.0980171403295606,
    -0.1224106751992162,
    -0.14673047445536175,
    -0.17096188876030122,
    -0.19509032201612828,
    -0.2191012401568698,
    -0.2429801799032639,
    -0.26671275747489837,
    -0.2902846772544624,
    -0.31368174039889146,
    -0.33688985339222005,
    -0.35989503653498817,
    -0.3826834323650898,
    -0.40524131400498986,
    -0.4275550934302821,
    -0.4496113296546066,
    -0.47139673682599764,
    -0.49289819222978404,
    -0.5141027441932218,
    -0.5349976198870973,
    -0.5555702330196022,
    -0.5758081914178453,
    -0.5956993044924334,
    -0.6152315905806268,
    -0.6343932841636455,
    -0.6531728429537768,
    -0.6715589548470184,
    -0.6895405447370669,
    -0.7071067811865476,
    -0.7242470829514669,
    -0.7409511253549591,
    -0.7572088465064846,
    -0.773010453362737,
    -0.7883464276266062,
    -0.8032075314806449,
    -0.8175848131515837,
    -0.8314696123025452,
    -0.8448535652497071,
    -0.8577286100002721,
    -0.8700869911087115,
    -0.881921264348355,
    -0.8932243011955153,
    -0.9039892931234433,
    -0.9142097557035307,
    -0.9238795325112867,
    -0.9329927988347388,
    -0.9415440651830208,
    -0.9495281805930367,
    -0.9569403357322088,
    -0.9637760657954398,
    -0.970031253194544,
    -0.9757021300385286,
    -0.9807852804032304,
    -0.9852776423889412,
    -0.989176509964781,
    -0.99247953459871,
    -0.9951847266721969,
    -0.9972904566786902,
    -0.9987954562051724,
    -0.9996988186962042,
    -1.0,
    -0.9996988186962042,
    -0.9987954562051724,
    -0.9972904566786902,
    -0.9951847266721969,
    -0.99247953459871,
    -0.989176509964781,
    -0.9852776423889412,
    -0.9807852804032304,
    -0.9757021300385286,
    -0.970031253194544,
    -0.9637760657954398,
    -0.9569403357322088,
    -0.9495281805930367,
    -0.9415440651830208,
    -0.9329927988347388,
    -0.9238795325112867,
    -0.9142097557035307,
    -0.9039892931234433,
    -0.8932243011955153,
    -0.881921264348355,
    -0.8700869911087115,
    -0.8577286100002721,
    -0.8448535652497071,
    -0.8314696123025452,
    -0.8175848131515837,
    -0.8032075314806449,
    -0.7883464276266062,
    -0.773010453362737,
    -0.7572088465064846,
    -0.7409511253549591,
    -0.7242470829514669,
    -0.7071067811865476,
    -0.6895405447370669,
    -0.6715589548470184,
    -0.6531728429537768,
    -0.6343932841636455,
    -0.6152315905806268,
    -0.5956993044924334,
    -0.5758081914178453,
    -0.5555702330196022,
    -0.5349976198870973,
    -0.5141027441932218,
    -0.49289819222978404,
    -0.47139673682599764,
    -0.4496113296546066,
    -0.4275550934302821,
    -0.40524131400498986,
    -0.3826834323650898,
    -0.35989503653498817,
    -0.33688985339222005,
    -0.31368174039889146,
    -0.2902846772544624,
    -0.26671275747489837,
    -0.2429801799032639,
    -0.2191012401568698,
    -0.19509032201612828,
    -0.17096188876030122,
    -0.14673047445536175,
    -0.1224106751992162,
    -0.0980171403295606,
    -0.07356456359966743,
    -0.049067674327418015,
    -0.024541228522912288,
];

#[cfg(test)]
pub(crate) mod tests {
    use super::{out_of_line, packed, sin_cos, LIMIT, SIN_TABLE};

    /// Distance in units in the last place (same-sign results; otherwise `u64::MAX`).
    pub(crate) fn ulps(a: f64, b: f64) -> u64 {
        if a == b {
            return 0;
        }
        if a.is_sign_negative() != b.is_sign_negative() {
            return u64::MAX;
        }
        a.to_bits().abs_diff(b.to_bits())
    }

    /// Within 2 ulp, or within 2^-80 absolutely where the result is that small.
    pub(super) fn close(got: f64, want: f64) -> bool {
        ulps(got, want) <= 2 || (got - want).abs() <= 2f64.powi(-80)
    }

    pub(crate) struct Rng(pub(crate) u64);
    impl Rng {
        pub(crate) fn unit(&mut self) -> f64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            #[allow(clippy::cast_precision_loss)]
            let u = (self.0 >> 11) as f64 / (1u64 << 53) as f64;
            2.0 * u - 1.0
        }
    }

    fn check(xs: impl Iterator<Item = f64>) -> (usize, usize) {
        let (mut total, mut identical) = (0, 0);
        let xs: Vec<f64> = xs.collect();
        for chunk in xs.chunks_exact(3) {
            let got = sin_cos([chunk[0], chunk[1], chunk[2]]);
            for (&x, &(s, c)) in chunk.iter().zip(&got) {
                let (s0, c0) = x.sin_cos();
                assert!(close(s, s0), "sin {x:e}: {s:e} vs {s0:e}");
                assert!(close(c, c0), "cos {x:e}: {c:e} vs {c0:e}");
                total += 2;
                identical += usize::from(s.to_bits() == s0.to_bits());
                identical += usize::from(c.to_bits() == c0.to_bits());
            }
        }
        (total, identical)
    }

    #[test]
    fn random_angles_within_two_ulp() {
        let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
        for scale in [std::f64::consts::FRAC_PI_4, 4.0, 100.0, 1e4, 1e6, LIMIT] {
            let (total, identical) = check((0..600_000).map(|_| scale * rng.unit()));
            #[allow(clippy::cast_precision_loss)]
            let share = identical as f64 / total as f64;
            println!("|x| < {scale:e}: {:.1} % bit-identical", 100.0 * share);
            // A kernel that were merely close everywhere would share almost no bits exactly.
            assert!(share > 0.7, "{share}");
        }
    }

    #[test]
    fn near_multiples_of_half_pi_and_tiny_angles() {
        let mut near = Vec::new();
        for k in (-200_000_i32..200_000).step_by(997).chain(-8..8) {
            let centre = f64::from(k) * std::f64::consts::FRAC_PI_2;
            let mut x = centre;
            for _ in 0..4 {
                near.extend([x, x.next_up(), x.next_down()]);
                x = x.next_up().next_up();
            }
        }
        near.resize(near.len() / 3 * 3, 0.0);
        check(near.into_iter());
        let tiny = [
            1e-300, -1e-310, 5e-324, 1e-20, -1e-9, 0.0, -0.0, 1e-5, -3e-8,
        ];
        check(tiny.into_iter());
        let [(s, c)] = sin_cos([-0.0]);
        assert!(s == 0.0 && c == 1.0);
    }

    #[test]
    fn near_a_zero_of_a_large_angle_the_bound_is_absolute() {
        // The angle a user found: many ulp from the correctly rounded cosine, which is tiny,
        // but within the documented absolute bound.
        let x = 871_790.390_574_840_8_f64;
        let [(_, c)] = sin_cos([x]);
        let want = x.cos();
        assert!(want.abs() < 1e-15, "{want:e}");
        assert!(ulps(c, want) > 2, "no longer a hard case: {c:e} {want:e}");
        assert!((c - want).abs() <= 2f64.powi(-80), "{:e}", (c - want).abs());
    }

    /// `(p, e)` with `p + e = a b` exactly (Dekker's product, no fused multiply-add needed).
    fn two_product(a: f64, b: f64) -> (f64, f64) {
        let split = |v: f64| {
            let t = 134_217_729.0 * v; // 2^27 + 1
            let hi = t - (t - v);
            (hi, v - hi)
        };
        let ((ah, al), (bh, bl)) = (split(a), split(b));
        let p = a * b;
        (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
    }

    /// The table against `sin(a + d) ~ sin a + d cos a`, where `a + d` is `k pi/128` carried
    /// in two doubles (`k PI` exactly, plus `k` times the part of pi that `PI` misses):
    /// independent of the script that wrote the table.
    #[test]
    fn table_entries_are_sines_of_exact_multiples_of_pi() {
        const PI_LO: f64 = 1.224_646_799_147_353_2e-16;
        for (k, &entry) in SIN_TABLE.iter().enumerate() {
            let k = f64::from(u32::try_from(k).unwrap());
            let (p, e) = two_product(k, std::f64::consts::PI);
            let (a, d) = (p / 128.0, (e + k * PI_LO) / 128.0);
            let want = a.sin() + d * a.cos();
            let ulp = f64::EPSILON * want.abs().max(f64::MIN_POSITIVE);
            assert!((entry - want).abs() <= ulp, "{k}: {entry:e} {want:e}");
        }
    }

    #[test]
    fn outside_the_range_the_standard_library_answers() {
        let xs = [LIMIT * 1.0001, -1e10, 1e300, f64::MAX];
        let got = sin_cos(xs);
        for (x, (s, c)) in xs.into_iter().zip(got) {
            let (s0, c0) = x.sin_cos();
            assert_eq!((s.to_bits(), c.to_bits()), (s0.to_bits(), c0.to_bits()));
        }
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let [(s, c), (s1, c1)] = sin_cos([bad, 1.0]);
            assert!(s.is_nan() && c.is_nan());
            // The other angle of the array is computed as usual.
            assert_eq!((s1, c1), sin_cos([1.0])[0]);
        }
    }

    #[test]
    fn each_angle_is_independent_of_its_neighbours_and_of_n() {
        let xs = [0.3, -1.7, 2.9, 1e5, -4.4];
        let five = sin_cos(xs);
        for (j, &x) in xs.iter().enumerate() {
            assert_eq!(five[j], sin_cos([x])[0]);
            assert_eq!(five[j], sin_cos([f64::NAN, x])[1]);
        }
    }

    /// The inlined form optimised builds run and the out-of-line form of `dev` builds give
    /// the same bits, whatever the length, range or NaN.
    #[test]
    fn the_inlined_and_out_of_line_forms_agree_bit_for_bit() {
        fn both<const N: usize>(q: [f64; N]) {
            let mut slow = [(0.0, 0.0); N];
            out_of_line(&q, &mut slow);
            let fast = packed(q);
            for ((a, b), x) in fast.iter().zip(&slow).zip(q) {
                assert_eq!(
                    (a.0.to_bits(), a.1.to_bits()),
                    (b.0.to_bits(), b.1.to_bits()),
                    "{x:e}"
                );
            }
        }
        let mut rng = Rng(0x2545_F491_4F6C_DD1D);
        let mut x = || {
            let u = rng.unit();
            match ((u + 1.0) * 1e6) as u64 % 50 {
                0 => f64::NAN,
                1 => 3.0 * LIMIT * u,
                _ => 10.0 * u,
            }
        };
        for _ in 0..20_000 {
            both([x()]);
            both([x(), x()]);
            both([x(), x(), x()]);
            both([x(), x(), x(), x()]);
            both([x(), x(), x(), x(), x()]);
            both([x(), x(), x(), x(), x(), x()]);
            both([x(), x(), x(), x(), x(), x(), x()]);
            both([x(), x(), x(), x(), x(), x(), x(), x()]);
        }
    }
}
