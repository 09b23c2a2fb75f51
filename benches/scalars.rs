//! The generated dynamics in other scalars, per state: `f32` against `f64`, and a batch of
//! states in SIMD lanes (4 `f64` in `WideF64x4`, 8 `f32` in `WideF32x8`) against as many scalar
//! calls, for the arms with random parameters of the dynamics bench.
//!
//! Not run in CI. One run prints the tables of docs/performance.md:
//!
//! ```text
//! CARGO_TARGET_DIR=/tmp/target_bench cargo bench --bench scalars
//! RUSTFLAGS="-C target-cpu=native" CARGO_TARGET_DIR=/tmp/target_native cargo bench --bench scalars
//! ```
//!
//! Each ratio is the median over 101 rounds of the two timed back to back
//! (`support/interleaved.rs`); ns are per state.

use std::hint::black_box;

use planar_arm::nalgebra::SVector;
use planar_arm::prelude::*;
use planar_arm::simd::{WideF32x8, WideF64x4};

#[path = "support/interleaved.rs"]
mod interleaved;
use interleaved::interleaved;

#[path = "support/random_arms.rs"]
#[allow(dead_code)] // the one- and eight-link arms are the dynamics bench's
mod random_arms;
use random_arms::{Random2, Random3, Random4, Random6};

#[allow(clippy::cast_precision_loss, clippy::cast_possible_truncation)]
fn row<A: PlanarArm<N> + Default, const N: usize>() {
    let arm = A::default();
    let state = |phase: f64, lane: usize| {
        SVector::<f64, N>::from_fn(|j, _| {
            ((j + 1) as f64)
                .mul_add(0.37, phase + 0.11 * lane as f64)
                .sin()
                * 2.0
        })
    };
    let (q, qd, qdd) = (state(0.1, 0), state(1.3, 0), state(2.9, 0));
    let (q32, qd32, qdd32) = (
        q.map(|x| x as f32),
        qd.map(|x| x as f32),
        qdd.map(|x| x as f32),
    );
    let tau = arm.inverse_dynamics(&q, &qd, &qdd);
    let tau32 = tau.map(|x| x as f32);

    // f32 against f64, per state.
    let (id32, id_ns) = interleaved(
        || {
            black_box(arm.inverse_dynamics(black_box(&q), black_box(&qd), black_box(&qdd)));
        },
        || {
            black_box(arm.inverse_dynamics(black_box(&q32), black_box(&qd32), black_box(&qdd32)));
        },
    );
    let (m32, m_ns) = interleaved(
        || {
            black_box(arm.mass_matrix(black_box(&q)));
        },
        || {
            black_box(arm.mass_matrix(black_box(&q32)));
        },
    );
    let (fd32, fd_ns) = interleaved(
        || {
            black_box(arm.forward_dynamics(black_box(&q), black_box(&qd), black_box(&tau)));
        },
        || {
            black_box(arm.forward_dynamics(black_box(&q32), black_box(&qd32), black_box(&tau32)));
        },
    );

    // Four f64 states: four scalar calls against one call on WideF64x4.
    let states: Vec<_> = (0..8)
        .map(|l| (state(0.1, l), state(1.3, l), state(2.9, l)))
        .collect();
    let pack4 = |k: usize| -> SVector<WideF64x4, N> {
        SVector::from_fn(|j, _| {
            WideF64x4::from(core::array::from_fn::<f64, 4, _>(|l| match k {
                0 => states[l].0[j],
                1 => states[l].1[j],
                _ => states[l].2[j],
            }))
        })
    };
    let (qb, qdb, qddb) = (pack4(0), pack4(1), pack4(2));
    let (id4, id4_ns) = interleaved(
        || {
            for s in &states[..4] {
                black_box(arm.inverse_dynamics(black_box(&s.0), black_box(&s.1), black_box(&s.2)));
            }
        },
        || {
            black_box(arm.inverse_dynamics(black_box(&qb), black_box(&qdb), black_box(&qddb)));
        },
    );
    let (mm4, _) = interleaved(
        || {
            for s in &states[..4] {
                black_box(arm.mass_matrix(black_box(&s.0)));
            }
        },
        || {
            black_box(arm.mass_matrix(black_box(&qb)));
        },
    );
    // Eight f32 states against one call on WideF32x8.
    let states32: Vec<_> = states
        .iter()
        .map(|(a, b, c)| {
            (
                a.map(|x| x as f32),
                b.map(|x| x as f32),
                c.map(|x| x as f32),
            )
        })
        .collect();
    let pack8 = |k: usize| -> SVector<WideF32x8, N> {
        SVector::from_fn(|j, _| {
            WideF32x8::from(core::array::from_fn::<f32, 8, _>(|l| match k {
                0 => states32[l].0[j],
                1 => states32[l].1[j],
                _ => states32[l].2[j],
            }))
        })
    };
    let (qb8, qdb8, qddb8) = (pack8(0), pack8(1), pack8(2));
    let (id8, _) = interleaved(
        || {
            for s in &states32 {
                black_box(arm.inverse_dynamics(black_box(&s.0), black_box(&s.1), black_box(&s.2)));
            }
        },
        || {
            black_box(arm.inverse_dynamics(black_box(&qb8), black_box(&qdb8), black_box(&qddb8)));
        },
    );
    let (mm8, _) = interleaved(
        || {
            for s in &states32 {
                black_box(arm.mass_matrix(black_box(&s.0)));
            }
        },
        || {
            black_box(arm.mass_matrix(black_box(&qb8)));
        },
    );
    // Throughput gain = time of the scalar calls / time of the batch call = 1 / ratio; the
    // batch's time per call is that ratio times the four scalar calls' median time.
    println!(
        "| {N} | {id_ns:.1} | {id32:.2} | {m_ns:.1} | {m32:.2} | {fd_ns:.1} | {fd32:.2} | {:.2}x | {:.2}x | {:.2}x | {:.2}x | {:.2e} | {:.2e} |",
        1.0 / id4,
        1.0 / mm4,
        1.0 / id8,
        1.0 / mm8,
        1e9 / id_ns,
        4e9 / (id4 * id4_ns),
    );
}

fn main() {
    println!("| N | f64 ID ns | f32/f64 ID time | f64 M ns | f32/f64 M time | f64 FD ns | f32/f64 FD time | 4 x f64 batch ID gain | batch M gain | 8 x f32 batch ID gain | batch M gain | f64 ID states/s | 4 x f64 batch ID states/s |");
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    row::<Random2, 2>();
    row::<Random3, 3>();
    row::<Random4, 4>();
    row::<Random6, 6>();
}
