//! `mass_matrix_and_bias` (M and h = c + g + f in one pass) against calling `mass_matrix`,
//! `coriolis` and `gravity` separately, the computed-torque controller's per-cycle need, for
//! the paper's equal rods with gravity, N = 2..8.
//!
//! Not run in CI. One run prints the table:
//!
//! ```text
//! CARGO_TARGET_DIR=/tmp/target_bench cargo bench --bench bias
//! ```
//!
//! Each speed-up is the median over 101 rounds of the two timed back to back
//! (`support/interleaved.rs`). Before timing, the bench checks that both give the same M and
//! `c + g` to 1e-12.

use std::hint::black_box;

use planar_arm::nalgebra::SVector;
use planar_arm::prelude::*;

#[path = "support/interleaved.rs"]
mod interleaved;
use interleaved::interleaved;

macro_rules! equal_arm {
    ($name:ident, $($field:ident),+) => {
        #[derive(PlanarArm, Default, Debug)]
        #[arm(gravity = 9.81)]
        struct $name {
            $(
                #[arm(length = 1, mass = 1)]
                $field: Revolute,
            )+
        }
    };
}

equal_arm!(Equal2, a, b);
equal_arm!(Equal3, a, b, c);
equal_arm!(Equal4, a, b, c, d);
equal_arm!(Equal5, a, b, c, d, e);
equal_arm!(Equal6, a, b, c, d, e, f);
equal_arm!(Equal7, a, b, c, d, e, f, g);
equal_arm!(Equal8, a, b, c, d, e, f, g, h);

fn row<A: PlanarArm<N> + Default, const N: usize>() {
    let arm = A::default();
    #[allow(clippy::cast_precision_loss)]
    let q = SVector::<f64, N>::from_fn(|j, _| ((j + 1) as f64).mul_add(0.37, 0.1).sin() * 2.0);
    #[allow(clippy::cast_precision_loss)]
    let qd = SVector::<f64, N>::from_fn(|j, _| ((j + 1) as f64).mul_add(0.37, 1.3).sin() * 2.0);
    let (m, h) = arm.mass_matrix_and_bias(&q, &qd);
    let separate = arm.coriolis(&q, &qd) + arm.gravity(&q);
    assert!((m - arm.mass_matrix(&q)).amax() <= 1e-12 * (1.0 + m.amax()));
    assert!((h - separate).amax() <= 1e-12 * (1.0 + h.amax()));
    let (speedup, together_ns) = interleaved(
        || {
            black_box(arm.mass_matrix_and_bias(black_box(&q), black_box(&qd)));
        },
        || {
            black_box(arm.mass_matrix(black_box(&q)));
            black_box(arm.coriolis(black_box(&q), black_box(&qd)));
            black_box(arm.gravity(black_box(&q)));
        },
    );
    // The separate calls' time, from the same round medians.
    let separate_ns = together_ns * speedup;
    println!("| {N} | {together_ns:.1} | {separate_ns:.1} | {speedup:.2} |");
}

fn main() {
    println!("| N | mass_matrix_and_bias ns | mass_matrix + coriolis + gravity ns | speed-up |");
    println!("|---|---|---|---|");
    row::<Equal2, 2>();
    row::<Equal3, 3>();
    row::<Equal4, 4>();
    row::<Equal5, 5>();
    row::<Equal6, 6>();
    row::<Equal7, 7>();
    row::<Equal8, 8>();
}
