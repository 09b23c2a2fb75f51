//! What run-time parameters cost: inverse dynamics, mass matrix and forward dynamics of arms
//! whose masses, inertias and centres of mass are all `self.NAME` fields, against the same
//! arms written with literals (the values of `benches/dynamics.rs`'s random arms), in one run.
//!
//! Not run in CI. The ratios in docs/performance.md come from one run of
//!
//! ```text
//! CARGO_TARGET_DIR=/tmp/target_bench cargo bench --bench parameters
//! ```
//!
//! which prints the table. Each ratio is the median over 101 rounds of the two arms timed back
//! to back (20,000 calls each): on a shared machine the load drifts over seconds, and
//! criterion's one-benchmark-after-another medians swung by 30 % between runs.
//!
//! Each parameterised arm is timed twice: called directly, and through its frozen view
//! (`arm.freeze()`, which evaluates the parameter-only values once).
//!
//! Before timing, each parameterised arm is checked to give its literal twin's numbers.

use std::hint::black_box;

use planar_arm::nalgebra::SVector;
use planar_arm::prelude::*;

#[path = "support/interleaved.rs"]
mod interleaved;
use interleaved::interleaved;

// The literal arms are the dynamics bench's random arms; the parameterised ones below hold
// the same values in fields.
#[path = "support/random_arms.rs"]
#[allow(dead_code)] // the one- and eight-link arms are the dynamics bench's
mod random_arms;
use random_arms::{
    Random2 as Literal2, Random3 as Literal3, Random4 as Literal4, Random6 as Literal6,
};

#[derive(PlanarArm, Debug)]
#[arm(gravity = 9.80665)]
struct Params2 {
    #[arm(length = 6/1, mass = self.mass_a, inertia = self.inertia_a, com = self.com_a)]
    a: Revolute,
    #[arm(length = 4/1, mass = self.mass_b, inertia = self.inertia_b, com = self.com_b)]
    b: Revolute,
    mass_a: f64,
    inertia_a: f64,
    com_a: f64,
    mass_b: f64,
    inertia_b: f64,
    com_b: f64,
}

impl Default for Params2 {
    fn default() -> Self {
        Self {
            a: Revolute,
            mass_a: 3.0 / 1.0,
            inertia_a: 6.0 / 25.0,
            com_a: 12.0 / 5.0,
            b: Revolute,
            mass_b: 38.0 / 5.0,
            inertia_b: 1.0 / 25.0,
            com_b: 4.0 / 1.0,
        }
    }
}

#[derive(PlanarArm, Debug)]
#[arm(gravity = 9.80665)]
struct Params3 {
    #[arm(length = 12/5, mass = self.mass_a, inertia = self.inertia_a, com = self.com_a)]
    a: Revolute,
    #[arm(length = 23/10, mass = self.mass_b, inertia = self.inertia_b, com = self.com_b)]
    b: Revolute,
    #[arm(length = 2/1, mass = self.mass_c, inertia = self.inertia_c, com = self.com_c)]
    c: Revolute,
    mass_a: f64,
    inertia_a: f64,
    com_a: f64,
    mass_b: f64,
    inertia_b: f64,
    com_b: f64,
    mass_c: f64,
    inertia_c: f64,
    com_c: f64,
}

impl Default for Params3 {
    fn default() -> Self {
        Self {
            a: Revolute,
            mass_a: 26.0 / 5.0,
            inertia_a: 5.0 / 4.0,
            com_a: 6.0 / 25.0,
            b: Revolute,
            mass_b: 2.0 / 1.0,
            inertia_b: 1.0 / 20.0,
            com_b: 69.0 / 100.0,
            c: Revolute,
            mass_c: 3.0 / 2.0,
            inertia_c: 11.0 / 25.0,
            com_c: 3.0 / 5.0,
        }
    }
}

#[derive(PlanarArm, Debug)]
#[arm(gravity = 9.80665)]
struct Params4 {
    #[arm(length = 9/5, mass = self.mass_a, inertia = self.inertia_a, com = self.com_a)]
    a: Revolute,
    #[arm(length = 9/5, mass = self.mass_b, inertia = self.inertia_b, com = self.com_b)]
    b: Revolute,
    #[arm(length = 23/8, mass = self.mass_c, inertia = self.inertia_c, com = self.com_c)]
    c: Revolute,
    #[arm(length = 14/5, mass = self.mass_d, inertia = self.inertia_d, com = self.com_d)]
    d: Revolute,
    mass_a: f64,
    inertia_a: f64,
    com_a: f64,
    mass_b: f64,
    inertia_b: f64,
    com_b: f64,
    mass_c: f64,
    inertia_c: f64,
    com_c: f64,
    mass_d: f64,
    inertia_d: f64,
    com_d: f64,
}

impl Default for Params4 {
    fn default() -> Self {
        Self {
            a: Revolute,
            mass_a: 13.0 / 4.0,
            inertia_a: 1.0 / 40.0,
            com_a: 9.0 / 5.0,
            b: Revolute,
            mass_b: 9.0 / 2.0,
            inertia_b: 11.0 / 40.0,
            com_b: -27.0 / 50.0,
            c: Revolute,
            mass_c: 3.0 / 4.0,
            inertia_c: 3.0 / 10.0,
            com_c: 69.0 / 20.0,
            d: Revolute,
            mass_d: 16.0 / 5.0,
            inertia_d: 23.0 / 25.0,
            com_d: -14.0 / 25.0,
        }
    }
}

#[derive(PlanarArm, Debug)]
#[arm(gravity = 9.80665)]
struct Params6 {
    #[arm(length = 3/1, mass = self.mass_a, inertia = self.inertia_a, com = self.com_a)]
    a: Revolute,
    #[arm(length = 4/1, mass = self.mass_b, inertia = self.inertia_b, com = self.com_b)]
    b: Revolute,
    #[arm(length = 7/5, mass = self.mass_c, inertia = self.inertia_c, com = self.com_c)]
    c: Revolute,
    #[arm(length = 9/2, mass = self.mass_d, inertia = self.inertia_d, com = self.com_d)]
    d: Revolute,
    #[arm(length = 17/4, mass = self.mass_e, inertia = self.inertia_e, com = self.com_e)]
    e: Revolute,
    #[arm(length = 7/4, mass = self.mass_f, inertia = self.inertia_f, com = self.com_f)]
    f: Revolute,
    mass_a: f64,
    inertia_a: f64,
    com_a: f64,
    mass_b: f64,
    inertia_b: f64,
    com_b: f64,
    mass_c: f64,
    inertia_c: f64,
    com_c: f64,
    mass_d: f64,
    inertia_d: f64,
    com_d: f64,
    mass_e: f64,
    inertia_e: f64,
    com_e: f64,
    mass_f: f64,
    inertia_f: f64,
    com_f: f64,
}

impl Default for Params6 {
    fn default() -> Self {
        Self {
            a: Revolute,
            mass_a: 12.0 / 5.0,
            inertia_a: 1.0 / 50.0,
            com_a: 12.0 / 5.0,
            b: Revolute,
            mass_b: 15.0 / 2.0,
            inertia_b: 23.0 / 25.0,
            com_b: 6.0 / 5.0,
            c: Revolute,
            mass_c: 31.0 / 8.0,
            inertia_c: 17.0 / 40.0,
            com_c: 7.0 / 10.0,
            d: Revolute,
            mass_d: 39.0 / 8.0,
            inertia_d: 7.0 / 10.0,
            com_d: -9.0 / 10.0,
            e: Revolute,
            mass_e: 15.0 / 8.0,
            inertia_e: 17.0 / 40.0,
            com_e: 17.0 / 40.0,
            f: Revolute,
            mass_f: 9.0 / 1.0,
            inertia_f: 1.0 / 4.0,
            com_f: 21.0 / 20.0,
        }
    }
}

/// States that exercise every term.
fn state<const N: usize>(k: usize) -> (SVector<f64, N>, SVector<f64, N>, SVector<f64, N>) {
    #[allow(clippy::cast_precision_loss)]
    let at = |j: usize, s: f64| ((j + 1) as f64).mul_add(0.37, s + k as f64 * 0.71).sin() * 2.0;
    (
        SVector::from_fn(|j, _| at(j, 0.1)),
        SVector::from_fn(|j, _| at(j, 1.3)),
        SVector::from_fn(|j, _| at(j, 2.9)),
    )
}

fn check<L: PlanarArm<N>, P: PlanarArm<N>, const N: usize>(literal: &L, params: &P) {
    assert_eq!(literal.model(), params.model());
    for k in 0..16 {
        let (q, qd, qdd) = state::<N>(k);
        let (a, b) = (
            literal.inverse_dynamics(&q, &qd, &qdd),
            params.inverse_dynamics(&q, &qd, &qdd),
        );
        assert!((a - b).amax() <= 1e-12 * (1.0 + a.amax()), "{a} vs {b}");
        let (a, b) = (
            literal.forward_dynamics(&q, &qd, &qdd),
            params.forward_dynamics(&q, &qd, &qdd),
        );
        assert!((a - b).amax() <= 1e-10 * (1.0 + a.amax()), "{a} vs {b}");
    }
}

/// `time(b) / time(a)` for one method of the literal arm (a) and of the parameterised arm
/// called directly and through its frozen view (b).
macro_rules! ratios {
    ($literal:expr, $params:expr, $frozen:expr, |$arm:ident| $call:expr) => {{
        let direct = interleaved(
            || {
                let $arm = $literal;
                black_box($call);
            },
            || {
                let $arm = $params;
                black_box($call);
            },
        );
        let frozen = interleaved(
            || {
                let $arm = $literal;
                black_box($call);
            },
            || {
                let $arm = $frozen;
                black_box($call);
            },
        );
        (direct, frozen.0)
    }};
}

fn row<L: PlanarArm<N>, P: PlanarArm<N>, const N: usize>(literal: &L, params: &P) {
    check(literal, params);
    let frozen = black_box(params.freeze());
    let (q, qd, qdd) = state::<N>(0);
    let ((id, id_ns), id_f) = ratios!(literal, params, &frozen, |a| a.inverse_dynamics(
        black_box(&q),
        black_box(&qd),
        black_box(&qdd)
    ));
    let ((m, _), m_f) = ratios!(literal, params, &frozen, |a| a.mass_matrix(black_box(&q)));
    let ((fd, _), fd_f) = ratios!(literal, params, &frozen, |a| a.forward_dynamics(
        black_box(&q),
        black_box(&qd),
        black_box(&qdd)
    ));
    // What freezing costs, in calls of the literal arm's inverse dynamics.
    let (freeze, _) = interleaved(
        || {
            black_box(literal.inverse_dynamics(black_box(&q), black_box(&qd), black_box(&qdd)));
        },
        || {
            black_box(black_box(params).freeze());
        },
    );
    println!(
        "| {N} | {id:.2} | {m:.2} | {fd:.2} | {id_f:.2} | {m_f:.2} | {fd_f:.2} | {freeze:.2} | {id_ns:.1} |"
    );
}

fn main() {
    println!(
        "| N | ID params / literal | M params / literal | FD params / literal \
         | ID frozen / literal | M frozen / literal | FD frozen / literal \
         | freeze() / ID literal | ID literal ns |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    row(&Literal2::default(), &black_box(Params2::default()));
    row(&Literal3::default(), &black_box(Params3::default()));
    row(&Literal4::default(), &black_box(Params4::default()));
    row(&Literal6::default(), &black_box(Params6::default()));
}
