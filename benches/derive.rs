//! How long the engine takes to derive an arm and emit its code, and how the result grows with
//! the number of links. Not run in CI; the table in docs/performance.md comes from
//!
//! ```text
//! CARGO_TARGET_DIR=/tmp/target_bench cargo bench --bench derive [-- MAX_N]
//! ```
//!
//! For N = 1..=MAX_N (default 12): uniform rods with random rational lengths and masses
//! (fixed seed), gravity 981/100, as bench/sympy_lagrange.py. Times are the fastest of a few
//! runs of the whole pipeline the derive runs: `ArmSpec -> Derived` (Lagrangian mechanics,
//! exact) and `generate` (straight-line programs, emitted tokens). "terms in M" counts the
//! additive terms over all N x N entries of M, SymPy's measure. The growth exponent is the
//! least-squares slope of log(time) against log(N) over N >= 4.

use std::hint::black_box;
use std::time::{Duration, Instant};

use planar_arm::symbolic::generate::{generate, Header};
use planar_arm::symbolic::mechanics::LinkSpec;
use planar_arm::symbolic::methods::Derived;
use planar_arm::symbolic::ring::ratio;
use planar_arm::symbolic::ArmSpec;
use quote::quote;

/// SymPy's times for the same derivation (bench/sympy_lagrange.py, N = 1..=5), seconds.
const SYMPY: [f64; 5] = [0.08, 0.66, 4.61, 34.28, 371.33];

fn arm(n: usize, seed: &mut u64) -> ArmSpec {
    let mut next = |lo: i64, hi: i64| {
        *seed ^= *seed << 13;
        *seed ^= *seed >> 7;
        *seed ^= *seed << 17;
        let span = u64::try_from(hi - lo + 1).unwrap_or(1);
        lo + i64::try_from(*seed % span).unwrap_or(0)
    };
    ArmSpec {
        links: (0..n)
            .map(|_| {
                let (l, m) = (next(5, 20), next(5, 40));
                LinkSpec::rod(ratio(l, 10), ratio(m, 10))
            })
            .collect(),
        gravity: planar_arm_core::down(ratio(981, 100)),
        payload: None,
    }
}

fn derive_and_emit(spec: &ArmSpec) -> (Derived, usize) {
    let header = Header::new(quote!(), quote!(Arm), quote!(), Vec::new());
    let d = Derived::new(spec);
    let tokens = generate(&d, &header).expect("representable");
    (d, count_tokens(tokens))
}

/// Tokens in a stream, counting inside groups.
fn count_tokens(tokens: proc_macro2::TokenStream) -> usize {
    tokens
        .into_iter()
        .map(|t| match t {
            proc_macro2::TokenTree::Group(g) => 1 + count_tokens(g.stream()),
            _ => 1,
        })
        .sum()
}

/// Which form each dynamics method was emitted in: expanded formulas, or an unrolled
/// recursion (Newton-Euler, composite rigid body). Forward dynamics evaluates `M`, `c` and `g`
/// as those methods do, then solves.
fn forms(d: &Derived) -> String {
    let pick = |m: planar_arm::symbolic::methods::Method, yes: &str| {
        if m.evaluation.is_empty() {
            "formulas".to_string()
        } else {
            yes.to_string()
        }
    };
    format!(
        "tau: {}, M: {}, c: {}, g: {}",
        pick(d.inverse_dynamics_method(), "RNEA"),
        pick(d.mass_matrix_method(), "CRBA"),
        pick(d.coriolis_method(), "RNEA"),
        pick(d.gravity_method(), "recursion"),
    )
}

fn slope(points: &[(f64, f64)]) -> f64 {
    #[allow(clippy::cast_precision_loss)]
    let k = points.len() as f64;
    let (sx, sy) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), &(x, y)| (a + x.ln(), b + y.ln()));
    let (mx, my) = (sx / k, sy / k);
    let (num, den) = points.iter().fold((0.0, 0.0), |(a, b), &(x, y)| {
        let dx = x.ln() - mx;
        (a + dx * (y.ln() - my), b + dx * dx)
    });
    num / den
}

fn main() {
    // `cargo bench` passes `--bench`; a bare number is the largest N.
    let max_n = std::env::args()
        .skip(1)
        .find_map(|a| a.parse::<usize>().ok())
        .unwrap_or(12);
    let mut seed = 2026_u64;
    println!(
        "| N | derive + emit (s) | SymPy (s) | terms in M | inverse dynamics ops (mul + add) | \
         mass matrix ops | forward dynamics ops (mul + add + div) | emitted tokens | evaluated as |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    let mut growth = Vec::new();
    let mut term_growth = Vec::new();
    for n in 1..=max_n {
        let spec = arm(n, &mut seed);
        let mut best = Duration::MAX;
        let mut runs = 0;
        let mut result = None;
        let started = Instant::now();
        // At least 3 runs, and more for fast ones (up to about a second in all).
        while runs < 3 || (started.elapsed() < Duration::from_secs(1) && runs < 50) {
            let t = Instant::now();
            let r = derive_and_emit(black_box(&spec));
            best = best.min(t.elapsed());
            result = Some(r);
            runs += 1;
        }
        let (d, tokens) = result.expect("ran");
        let terms: usize = d
            .dynamics
            .mass_matrix
            .iter()
            .flatten()
            .map(planar_arm::symbolic::Expr::len)
            .sum();
        let (id, mm, fd) = (
            d.inverse_dynamics_method(),
            d.mass_matrix_method(),
            d.forward_dynamics_method(),
        );
        let forms = forms(&d);
        let (id, mm, fd) = (id.op_count(), mm.op_count(), fd.op_count());
        let secs = best.as_secs_f64();
        let sympy = SYMPY
            .get(n - 1)
            .map_or_else(|| "-".to_string(), |s| format!("{s}"));
        println!(
            "| {n} | {secs:.4} | {sympy} | {terms} | {} + {} | {} + {} | {} + {} + {} | {tokens} | {forms} |",
            id.mul, id.add, mm.mul, mm.add, fd.mul, fd.add, fd.div
        );
        #[allow(clippy::cast_precision_loss)]
        if n >= 4 {
            growth.push((n as f64, secs));
            term_growth.push((n as f64, terms as f64));
        }
    }
    if growth.len() >= 2 {
        println!(
            "\ngrowth exponent (log-log slope over N >= 4): time ~ N^{:.2}, terms in M ~ N^{:.2}",
            slope(&growth),
            slope(&term_growth)
        );
    }
}
