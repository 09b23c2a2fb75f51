//! The generated regressor and base regressor against the numeric regressors of the reference,
//! per call, for the arms with random parameters of the dynamics bench:
//! `reference::regressor_local` (Pinocchio's `computeJointTorqueRegressor` algorithm, local
//! frames, joint by joint) and `reference::regressor` (world frame, each body's wrench moved
//! to every joint at once: less arithmetic).
//!
//! Not run in CI. One run prints the table of docs/identification.md:
//!
//! ```text
//! CARGO_TARGET_DIR=/tmp/target_bench cargo bench --bench identification
//! ```
//!
//! Each speed-up is the median over 101 rounds of the two timed back to back
//! (`support/interleaved.rs`). Before timing, the bench checks that the generated regressor
//! equals the numeric one column by column, and `Y_b theta_b` the torques, to 1e-12.

use std::hint::black_box;

use planar_arm::nalgebra::SVector;
use planar_arm::prelude::*;
use planar_arm::reference;

#[path = "support/interleaved.rs"]
mod interleaved;
use interleaved::interleaved;

#[path = "support/random_arms.rs"]
mod random_arms;
use random_arms::{Random1, Random2, Random3, Random4, Random6, Random8};

fn row<A, const N: usize, const P: usize, const B: usize>()
where
    A: Identification<N, P, B> + PlanarArm<N> + Default,
{
    let arm = A::default();
    let model = arm.model();
    #[allow(clippy::cast_precision_loss)]
    let wave = |phase: f64| {
        SVector::<f64, N>::from_fn(|j, _| ((j + 1) as f64).mul_add(0.37, phase).sin() * 2.0)
    };
    let (q, qd, qdd) = (wave(0.1), wave(1.3), wave(2.9));
    let numeric = reference::regressor(&model, &q, &qd, &qdd);
    let y = arm.regressor(&q, &qd, &qdd);
    for (k, name) in A::PARAMETERS.iter().enumerate() {
        let col = numeric.column(name).expect("a standard parameter");
        assert!(
            (y.column(k) - col).amax() <= 1e-12 * (1.0 + col.amax()),
            "{name}"
        );
    }
    let tau = arm.inverse_dynamics(&q, &qd, &qdd);
    let yb = arm.base_regressor(&q, &qd, &qdd);
    assert!((yb * arm.base_parameters() - tau).amax() <= 1e-12 * (1.0 + tau.amax()));

    let world = || {
        black_box(reference::regressor(
            black_box(&model),
            black_box(&q),
            black_box(&qd),
            black_box(&qdd),
        ));
    };
    let local = || {
        black_box(reference::regressor_local(
            black_box(&model),
            black_box(&q),
            black_box(&qd),
            black_box(&qdd),
        ));
    };
    let full = || {
        black_box(arm.regressor(black_box(&q), black_box(&qd), black_box(&qdd)));
    };
    let base = || {
        black_box(arm.base_regressor(black_box(&q), black_box(&qd), black_box(&qdd)));
    };
    let (full_local, full_ns) = interleaved(full, local);
    let (full_world, _) = interleaved(full, world);
    let (base_local, base_ns) = interleaved(base, local);
    let (base_world, _) = interleaved(base, world);
    println!(
        "| {N} | {P} | {B} | {base_ns:.1} | {full_ns:.1} | {:.1} | {base_local:.2}x | {full_local:.2}x | {:.1} | {base_world:.2}x | {full_world:.2}x |",
        base_local * base_ns,
        base_world * base_ns,
    );
}

fn main() {
    println!(
        "| N | P | B | base regressor ns | regressor ns | local-frame numeric ns | local / base | local / regressor | world-frame numeric ns | world / base | world / regressor |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|");
    row::<Random1, 1, 4, 3>();
    row::<Random2, 2, 8, 6>();
    row::<Random3, 3, 12, 9>();
    row::<Random4, 4, 16, 12>();
    row::<Random6, 6, 24, 18>();
    row::<Random8, 8, 32, 24>();
}
