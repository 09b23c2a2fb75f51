//! Arms with prismatic joints against the numeric reference and against all-revolute arms of
//! the same links: generated `inverse_dynamics`, `mass_matrix`, `forward_dynamics` and
//! `mass_matrix_and_bias` against `reference::inverse_dynamics` (RNEA), `mass_matrix` (CRBA),
//! `forward_dynamics` (ABA) and CRBA + `bias_forces`, N = 2, 3, 4, 6, 8
//! (`support/prismatic_arms.rs`: RP, PRR, RPRP, RPRPRP, RPRPRPRP with off-axis centres of mass).
//!
//! Not run in CI. One run prints the tables of docs/performance.md, "Prismatic joints":
//!
//! ```text
//! CARGO_TARGET_DIR=/tmp/target_bench cargo bench --bench prismatic
//! ```
//!
//! Every ratio is the median over 101 rounds of its two sides timed back to back
//! (`support/interleaved.rs`), so that the load of a shared machine cancels; ns are the
//! medians of the same rounds. Before timing, each arm is checked against the reference at 100
//! random states (to 1e-9 relative).
//!
//! `cargo bench --bench prismatic -- --values` prints the generated results at the Pinocchio
//! benchmark's states instead, for `bench/pinocchio/run.sh` to compare with Pinocchio's.

use std::hint::black_box;

use planar_arm::nalgebra::{SMatrix, SVector};
use planar_arm::prelude::*;
use planar_arm::reference;
use planar_arm::symbolic::mechanics::{ArmSpec, JointKind, LinkSpec};
use planar_arm::symbolic::methods::{Derived, Method};
use planar_arm::symbolic::ring::{ratio, Rational};

#[path = "support/interleaved.rs"]
mod interleaved;
use interleaved::interleaved;

#[path = "support/prismatic_arms.rs"]
mod prismatic_arms;
use prismatic_arms::{
    AllRevolute2, AllRevolute3, AllRevolute4, AllRevolute6, AllRevolute8, Mixed2, Mixed3, Mixed4,
    Mixed6, Mixed8,
};

/// The timed methods, in the tables' order.
const OPS: [&str; 4] = ["ID", "M", "FD", "M+h"];
const ID: usize = 0;
const M: usize = 1;
const FD: usize = 2;
const MH: usize = 3;

/// A deterministic pseudo-random vector in `[-range, range]` (the xorshift of
/// `benches/dynamics.rs` and `bench/pinocchio/peers.cpp`).
fn state<const N: usize>(seed: u64, range: f64) -> SVector<f64, N> {
    let mut s = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15).wrapping_add(1);
    SVector::from_fn(|_, _| {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        #[allow(clippy::cast_precision_loss)]
        let u = (s >> 11) as f64 / (1u64 << 53) as f64;
        (2.0 * u - 1.0) * range
    })
}

/// Largest entry-wise difference relative to the larger operand's max-norm (at least 1).
fn rel_err<const R: usize, const C: usize>(a: &SMatrix<f64, R, C>, b: &SMatrix<f64, R, C>) -> f64 {
    (a - b).amax() / a.amax().max(b.amax()).max(1.0)
}

/// One arm at the timed state, with what each side of a comparison calls.
struct Case<A, const N: usize> {
    arm: A,
    model: Model<N>,
    q: SVector<f64, N>,
    qd: SVector<f64, N>,
    qdd: SVector<f64, N>,
    tau: SVector<f64, N>,
}

impl<A: PlanarArm<N> + Default, const N: usize> Case<A, N> {
    fn new() -> Self {
        let arm = A::default();
        let model = arm.model();
        let (q, qd, qdd) = (state(101, 3.0), state(102, 2.0), state(103, 2.0));
        let tau = arm.inverse_dynamics(&q, &qd, &qdd);
        Self {
            arm,
            model,
            q,
            qd,
            qdd,
            tau,
        }
    }

    /// The generated method `OPS[OP]`, inputs through `black_box`, result kept.
    #[inline(always)]
    fn generated<const OP: usize>(&self) {
        let arm = &self.arm;
        match OP {
            ID => {
                black_box(arm.inverse_dynamics(
                    black_box(&self.q),
                    black_box(&self.qd),
                    black_box(&self.qdd),
                ));
            }
            M => {
                black_box(arm.mass_matrix(black_box(&self.q)));
            }
            FD => {
                black_box(arm.forward_dynamics(
                    black_box(&self.q),
                    black_box(&self.qd),
                    black_box(&self.tau),
                ));
            }
            _ => {
                black_box(arm.mass_matrix_and_bias(black_box(&self.q), black_box(&self.qd)));
            }
        }
    }

    /// The reference's counterpart of `OPS[OP]`; it reads the links at run time, as a user's
    /// numeric code would.
    #[inline(always)]
    fn reference<const OP: usize>(&self) {
        let model = black_box(&self.model);
        match OP {
            ID => {
                black_box(reference::inverse_dynamics(
                    model,
                    black_box(&self.q),
                    black_box(&self.qd),
                    black_box(&self.qdd),
                ));
            }
            M => {
                black_box(reference::mass_matrix(model, black_box(&self.q)));
            }
            FD => {
                black_box(reference::forward_dynamics(
                    model,
                    black_box(&self.q),
                    black_box(&self.qd),
                    black_box(&self.tau),
                ));
            }
            _ => {
                let q = black_box(&self.q);
                black_box(reference::mass_matrix(model, q));
                black_box(reference::bias_forces(model, q, black_box(&self.qd)));
            }
        }
    }
}

/// Largest relative difference, generated against reference, over the four methods at 100
/// random states; panics above 1e-9.
fn agreement<A: PlanarArm<N> + Default, const N: usize>(name: &str) -> f64 {
    let arm = A::default();
    let model = arm.model();
    let mut worst = 0.0_f64;
    for k in 0..100 {
        let q = state::<N>(3 * k + 1, 3.0);
        let qd = state::<N>(3 * k + 2, 2.0);
        let qdd = state::<N>(3 * k + 3, 2.0);
        let tau = arm.inverse_dynamics(&q, &qd, &qdd);
        let (m, h) = arm.mass_matrix_and_bias(&q, &qd);
        let m_ref = reference::mass_matrix(&model, &q);
        worst = worst
            .max(rel_err(
                &tau,
                &reference::inverse_dynamics(&model, &q, &qd, &qdd),
            ))
            .max(rel_err(&arm.mass_matrix(&q), &m_ref))
            .max(rel_err(
                &arm.forward_dynamics(&q, &qd, &tau),
                &reference::forward_dynamics(&model, &q, &qd, &tau),
            ))
            .max(rel_err(&m, &m_ref))
            .max(rel_err(&h, &reference::bias_forces(&model, &q, &qd)));
    }
    assert!(worst < 1e-9, "{name}: generated vs reference {worst:e}");
    worst
}

/// `(b's time / a's time, a's ns, b's ns)` from one interleaved measurement.
fn pair(a: impl FnMut(), b: impl FnMut()) -> (f64, f64, f64) {
    let (b_over_a, a_ns) = interleaved(a, b);
    (b_over_a, a_ns, a_ns * b_over_a)
}

/// Each method generated against the reference: `(reference / generated, generated ns,
/// reference ns)`.
fn against_reference<A: PlanarArm<N> + Default, const N: usize>(
    c: &Case<A, N>,
) -> [(f64, f64, f64); 4] {
    [
        pair(|| c.generated::<ID>(), || c.reference::<ID>()),
        pair(|| c.generated::<M>(), || c.reference::<M>()),
        pair(|| c.generated::<FD>(), || c.reference::<FD>()),
        pair(|| c.generated::<MH>(), || c.reference::<MH>()),
    ]
}

/// Mixed arm's time over the all-revolute arm's, each method, generated and reference.
fn mixed_over_revolute<P, R, const N: usize>(
    mixed: &Case<P, N>,
    revolute: &Case<R, N>,
) -> ([f64; 4], [f64; 4])
where
    P: PlanarArm<N> + Default,
    R: PlanarArm<N> + Default,
{
    let generated = [
        pair(|| revolute.generated::<ID>(), || mixed.generated::<ID>()).0,
        pair(|| revolute.generated::<M>(), || mixed.generated::<M>()).0,
        pair(|| revolute.generated::<FD>(), || mixed.generated::<FD>()).0,
        pair(|| revolute.generated::<MH>(), || mixed.generated::<MH>()).0,
    ];
    let reference = [
        pair(|| revolute.reference::<ID>(), || mixed.reference::<ID>()).0,
        pair(|| revolute.reference::<M>(), || mixed.reference::<M>()).0,
        pair(|| revolute.reference::<FD>(), || mixed.reference::<FD>()).0,
        pair(|| revolute.reference::<MH>(), || mixed.reference::<MH>()).0,
    ];
    (generated, reference)
}

/// The rational with the smallest denominator whose `f64` is `x` (the derive's exact value of
/// a parameter written as a small fraction or a short decimal), by continued fractions.
fn exact(x: f64) -> Rational {
    let (mut h, mut h_prev, mut k, mut k_prev) = (1_i64, 0_i64, 0_i64, 1_i64);
    let mut r = x;
    for _ in 0..40 {
        let a = r.floor();
        #[allow(clippy::cast_possible_truncation)]
        let ai = a as i64;
        (h, h_prev) = (ai * h + h_prev, h);
        (k, k_prev) = (ai * k + k_prev, k);
        #[allow(clippy::cast_precision_loss)]
        if h as f64 / k as f64 == x {
            return ratio(h, k);
        }
        r = 1.0 / (r - a);
    }
    panic!("{x} is no small fraction");
}

/// The derive's input for the arm, rebuilt from its links, to read the emitted programs'
/// operation counts.
fn spec<const N: usize>(model: &Model<N>) -> ArmSpec {
    assert!(
        model.payload.mass == 0.0,
        "the benchmarked arms have no payload"
    );
    ArmSpec {
        links: model
            .links
            .iter()
            .map(|l| LinkSpec {
                length: exact(l.length),
                mass: exact(l.mass),
                inertia: exact(l.inertia),
                com: (exact(l.com.x), exact(l.com.y)),
                armature: exact(l.armature),
                damping: exact(l.damping),
                frictionloss: exact(l.frictionloss),
                stiffness: exact(l.stiffness),
                springref: exact(l.springref),
                joint: match l.joint {
                    Joint::Revolute => JointKind::Revolute,
                    Joint::Prismatic => JointKind::Prismatic,
                },
                range: None,
                // The benchmarked arms are plain.
                offset: None,
                reversed: false,
            })
            .collect(),
        gravity: (exact(model.gravity.x), exact(model.gravity.y)),
        payload: None,
    }
}

/// The joint kinds, base first: `RP` for the polar arm.
fn joints<const N: usize>(model: &Model<N>) -> String {
    model
        .links
        .iter()
        .map(|l| match l.joint {
            Joint::Revolute => 'R',
            Joint::Prismatic => 'P',
        })
        .collect()
}

/// `mul + add` of a method's program, its number of angles' `sin_cos` pairs, and how it
/// evaluates (`recursion` if it runs one, else `formulas`).
fn cost(m: &Method, recursion: &str) -> String {
    let c = m.op_count();
    let form = if m.evaluation.is_empty() {
        "formulas"
    } else {
        recursion
    };
    format!("{} + {}, {} sc ({form})", c.mul, c.add, c.sin_cos)
}

/// The operation counts of the four emitted methods, `[ID, M, FD, M+h]`, and of M's recursive
/// candidate (the composite-rigid-body algorithm for an all-revolute arm, a Newton-Euler pass
/// per unit acceleration for a mixed one), which the emission weighs against the formulas.
fn costs<const N: usize>(model: &Model<N>) -> [String; 5] {
    let d = Derived::new(&spec(model));
    let recursion = if model.links.iter().all(|l| l.joint == Joint::Revolute) {
        "CRBA"
    } else {
        "unit accelerations"
    };
    [
        cost(&d.inverse_dynamics_method(), "RNEA"),
        cost(&d.mass_matrix_method(), recursion),
        cost(&d.forward_dynamics_method(), "solve"),
        cost(&d.mass_matrix_and_bias_method(), "recursions"),
        cost(&d.mass_matrix_composite_method(), recursion),
    ]
}

/// Everything one `N` contributes to the tables.
struct Rows {
    lines: [String; 2],
    ratios: String,
    ops: [String; 2],
    agreement: String,
}

fn measure<P, R, const N: usize>() -> Rows
where
    P: PlanarArm<N> + Default,
    R: PlanarArm<N> + Default,
{
    let (mixed, revolute) = (Case::<P, N>::new(), Case::<R, N>::new());
    let names = [joints(&mixed.model), joints(&revolute.model)];
    let agree = [agreement::<P, N>(&names[0]), agreement::<R, N>(&names[1])];
    // The same links but for the joint kinds.
    for (a, b) in mixed.model.links.iter().zip(&revolute.model.links) {
        assert_eq!(*a, b.with_joint(a.joint));
    }
    let rows = [against_reference(&mixed), against_reference(&revolute)];
    let (generated, reference) = mixed_over_revolute(&mixed, &revolute);
    let op_counts = [costs(&mixed.model), costs(&revolute.model)];

    let lines = core::array::from_fn(|a| {
        let mut s = format!("| {N} | {} |", names[a]);
        for (speed_up, gen_ns, ref_ns) in rows[a] {
            s.push_str(&format!(" {gen_ns:.1} | {ref_ns:.1} | {speed_up:.2}x |"));
        }
        s
    });
    let mut ratios = format!("| {N} | {} / {} |", names[0], names[1]);
    for r in generated.iter().chain(&reference) {
        ratios.push_str(&format!(" {r:.2} |"));
    }
    let ops = core::array::from_fn(|a| {
        let mut s = format!("| {N} | {} |", names[a]);
        for c in &op_counts[a] {
            s.push_str(&format!(" {c} |"));
        }
        s
    });
    let agreement = format!(
        "| {N} | {} {:.1e} | {} {:.1e} |",
        names[0], agree[0], names[1], agree[1]
    );
    Rows {
        lines,
        ratios,
        ops,
        agreement,
    }
}

/// The generated results at the Pinocchio benchmark's states (`states` in
/// `bench/pinocchio/peers.cpp`: seeds `1000 + 3k`, `1001 + 3k`, `1002 + 3k`, range 1; its
/// `aba` takes the accelerations as torques), one line per result (M by columns), each number
/// in Rust's shortest form that reads back to the same `f64`.
fn values<A: PlanarArm<N> + Default, const N: usize>(name: &str) {
    let arm = A::default();
    let list = |v: &[f64]| {
        v.iter()
            .map(|x| format!("{x:e}"))
            .collect::<Vec<_>>()
            .join(" ")
    };
    for k in 0..4 {
        let q = state::<N>(1000 + 3 * k, 1.0);
        let v = state::<N>(1001 + 3 * k, 1.0);
        let a = state::<N>(1002 + 3 * k, 1.0);
        let tau = arm.inverse_dynamics(&q, &v, &a);
        let m = arm.mass_matrix(&q);
        let fd = arm.forward_dynamics(&q, &v, &a);
        println!("# value, {name}, rnea, {k}, {}", list(tau.as_slice()));
        println!("# value, {name}, crba, {k}, {}", list(m.as_slice()));
        println!("# value, {name}, aba, {k}, {}", list(fd.as_slice()));
    }
}

fn main() {
    if std::env::args().any(|a| a == "--values") {
        values::<Mixed2, 2>("Mixed2");
        values::<AllRevolute2, 2>("AllRevolute2");
        values::<Mixed3, 3>("Mixed3");
        values::<AllRevolute3, 3>("AllRevolute3");
        values::<Mixed4, 4>("Mixed4");
        values::<AllRevolute4, 4>("AllRevolute4");
        values::<Mixed6, 6>("Mixed6");
        values::<AllRevolute6, 6>("AllRevolute6");
        values::<Mixed8, 8>("Mixed8");
        values::<AllRevolute8, 8>("AllRevolute8");
        return;
    }
    let all = [
        measure::<Mixed2, AllRevolute2, 2>(),
        measure::<Mixed3, AllRevolute3, 3>(),
        measure::<Mixed4, AllRevolute4, 4>(),
        measure::<Mixed6, AllRevolute6, 6>(),
        measure::<Mixed8, AllRevolute8, 8>(),
    ];

    println!("Generated against the reference (ns per call; reference / generated):\n");
    let mut head = "| N | joints |".to_string();
    let mut rule = "|---|---|".to_string();
    for (op, reference) in OPS.iter().zip(["RNEA", "CRBA", "ABA", "CRBA + bias"]) {
        head.push_str(&format!(" gen {op} | {reference} | {reference} / gen |"));
        rule.push_str("---|---|---|");
    }
    println!("{head}\n{rule}");
    for r in &all {
        println!("{}\n{}", r.lines[0], r.lines[1]);
    }

    println!("\nMixed arm's time over the all-revolute arm's (same links, same state):\n");
    let mut head = "| N | arms |".to_string();
    for side in ["gen", "ref"] {
        for op in OPS {
            head.push_str(&format!(" {side} {op} |"));
        }
    }
    println!("{head}\n|---|---|{}", "---|".repeat(8));
    for r in &all {
        println!("{}", r.ratios);
    }

    println!("\nEmitted operations, mul + add, sin_cos pairs (form):\n");
    let mut head = "| N | joints |".to_string();
    for op in OPS {
        head.push_str(&format!(" {op} |"));
    }
    head.push_str(" M's recursive candidate |");
    println!("{head}\n|---|---|{}", "---|".repeat(5));
    for r in &all {
        println!("{}\n{}", r.ops[0], r.ops[1]);
    }

    println!("\nAgreement with the reference (largest relative difference, 100 states):\n");
    println!("| N | mixed | all revolute |\n|---|---|---|");
    for r in &all {
        println!("{}", r.agreement);
    }
}
