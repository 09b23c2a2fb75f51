//! Spatial arms (`#[derive(SpatialArm)]`): the tool pose and Jacobian, and the closed-form
//! inverse kinematics against one `tip_pose` call and against damped least squares, for the
//! PUMA 560, the UR5, the Stanford arm and (pose and Jacobian only) the Franka Panda.
//!
//! Not run in CI. One run prints the tables of docs/performance.md, "Spatial arms":
//!
//! ```text
//! CARGO_TARGET_DIR=/tmp/target_bench cargo bench --bench spatial
//! ```
//!
//! Every time is the median over rounds of this thread's CPU time (`CLOCK_THREAD_CPUTIME_ID`,
//! as `bench/pinocchio/peers.cpp` measures): the time the thread was descheduled on a shared
//! machine is left out. Every ratio is the median over 101 rounds of its two sides timed back
//! to back (alternating which goes first), so that the load cancels in each ratio; the ns are
//! the medians of the same rounds. Inputs go through `black_box`, whole outputs too. Before
//! timing, each arm's `tip_pose` and `jacobian` are checked against `reference::spatial` and
//! every closed-form solution against the forward kinematics.
//!
//! Two more modes serve `bench/pinocchio/run.sh` (`ARMS=spatial`):
//!
//! - `-- --values` prints the tool pose (4x4, by columns) and the Jacobian (6xN, by columns)
//!   at the first four of the Pinocchio benchmark's states, for `run.sh` to compare with
//!   Pinocchio's `computeFrameJacobian`.
//! - `-- --peer CALLS` times `tip_pose` + `jacobian` (one call each) exactly as `peers.cpp`
//!   times Pinocchio: 64 states cycled, `CALLS` calls per round, 21 rounds after one warm-up,
//!   the medians per call by the wall clock and by the thread's CPU time, in its output format.

use core::f64::consts::PI;
use std::hint::black_box;
use std::time::Instant;

use planar_arm::prelude::*;
use planar_arm::reference::spatial as reference;
use planar_arm::spatial::{SpatialArm, SpatialModel};

/// PUMA 560, standard Denavit-Hartenberg parameters and mass properties (Corke's model), as
/// `examples/puma.rs` has it.
#[path = "../examples/support/puma_arm.rs"]
mod puma_arm;
use puma_arm::Puma560;

/// The UR5, Universal Robots' standard DH parameters (kinematics only: massless links).
#[derive(SpatialArm, Default)]
struct Ur5 {
    #[arm(dh(a = 0, alpha = pi/2, d = 0.089159))]
    shoulder_pan: Revolute,
    #[arm(dh(a = -0.425, alpha = 0, d = 0))]
    shoulder_lift: Revolute,
    #[arm(dh(a = -0.39225, alpha = 0, d = 0))]
    elbow: Revolute,
    #[arm(dh(a = 0, alpha = pi/2, d = 0.10915))]
    wrist1: Revolute,
    #[arm(dh(a = 0, alpha = -pi/2, d = 0.09465))]
    wrist2: Revolute,
    #[arm(dh(a = 0, alpha = 0, d = 0.0823))]
    wrist3: Revolute,
}

/// The Franka Panda, Craig's modified DH parameters from Franka's documentation, the flange
/// 0.107 m along the last axis (kinematics only: massless links).
#[derive(SpatialArm, Default)]
#[arm(tool(xyz = (0, 0, 0.107)))]
struct Panda {
    #[arm(mdh(a = 0, alpha = 0, d = 0.333))]
    joint1: Revolute,
    #[arm(mdh(a = 0, alpha = -pi/2, d = 0))]
    joint2: Revolute,
    #[arm(mdh(a = 0, alpha = pi/2, d = 0.316))]
    joint3: Revolute,
    #[arm(mdh(a = 0.0825, alpha = pi/2, d = 0))]
    joint4: Revolute,
    #[arm(mdh(a = -0.0825, alpha = -pi/2, d = 0.384))]
    joint5: Revolute,
    #[arm(mdh(a = 0, alpha = pi/2, d = 0))]
    joint6: Revolute,
    #[arm(mdh(a = 0.088, alpha = pi/2, d = 0))]
    joint7: Revolute,
}

/// The Stanford arm (Corke's standard DH parameters; the third joint slides), kinematics only.
#[derive(SpatialArm, Default)]
struct Stanford {
    #[arm(dh(a = 0, alpha = -pi/2, d = 0.412))]
    waist: Revolute,
    #[arm(dh(a = 0, alpha = pi/2, d = 0.154))]
    shoulder: Revolute,
    #[arm(dh(a = 0.0203, alpha = 0, d = 0, theta = -pi/2))]
    boom: Prismatic,
    #[arm(dh(a = 0, alpha = -pi/2, d = 0))]
    wrist1: Revolute,
    #[arm(dh(a = 0, alpha = pi/2, d = 0))]
    wrist2: Revolute,
    #[arm(dh(a = 0, alpha = 0, d = 0.263))]
    wrist3: Revolute,
}

/// The Stanford arm's slide in the random configurations (Corke's range, metres).
const SLIDE: (f64, f64) = (0.3048, 1.27);

/// How many states (or targets) each timing cycles through, as `peers.cpp`.
const STATES: usize = 64;

// ---------------------------------------------------------------------------------------------
// Clocks and timing

#[path = "support/cpu_clock.rs"]
mod cpu_clock;
use cpu_clock::{median, thread_cpu_ns};

/// `calls` calls of `f(k)`, `k` cycling through the states; this thread's CPU time per call.
fn round(f: &mut impl FnMut(usize), calls: usize) -> f64 {
    let start = thread_cpu_ns();
    let mut k = 0;
    for _ in 0..calls {
        f(k);
        k += 1;
        if k == STATES {
            k = 0;
        }
    }
    #[allow(clippy::cast_precision_loss)]
    let per_call = (thread_cpu_ns() - start) / calls as f64;
    per_call
}

/// The calls of `f` that take about 2 ms of CPU time (at least one pass over the states).
fn calls_for(f: &mut impl FnMut(usize)) -> usize {
    let mut calls = STATES;
    loop {
        let start = thread_cpu_ns();
        for k in 0..calls {
            f(k % STATES);
        }
        let ns = thread_cpu_ns() - start;
        if ns > 2e5 {
            #[allow(
                clippy::cast_possible_truncation,
                clippy::cast_sign_loss,
                clippy::cast_precision_loss
            )]
            let n = (2e6 / ns * calls as f64).ceil() as usize;
            return n.max(STATES);
        }
        calls *= 4;
    }
}

/// One comparison: `b`'s CPU time per call over `a`'s, the median over rounds in which the two
/// are timed back to back (alternating which goes first), and the medians of the two times.
struct Pair {
    ratio: f64,
    a_ns: f64,
    b_ns: f64,
}

/// [`Pair`] of `a(k)` and `b(k)` over 101 rounds of about 2 ms of each, after 5 warm-up rounds.
fn interleaved(mut a: impl FnMut(usize), mut b: impl FnMut(usize)) -> Pair {
    const ROUNDS: usize = 101;
    let (calls_a, calls_b) = (calls_for(&mut a), calls_for(&mut b));
    for _ in 0..5 {
        round(&mut a, calls_a);
        round(&mut b, calls_b);
    }
    let (mut ratios, mut a_ns, mut b_ns) = (Vec::new(), Vec::new(), Vec::new());
    for r in 0..ROUNDS {
        let (ta, tb) = if r % 2 == 0 {
            let ta = round(&mut a, calls_a);
            (ta, round(&mut b, calls_b))
        } else {
            let tb = round(&mut b, calls_b);
            (round(&mut a, calls_a), tb)
        };
        ratios.push(tb / ta);
        a_ns.push(ta);
        b_ns.push(tb);
    }
    Pair {
        ratio: median(ratios),
        a_ns: median(a_ns),
        b_ns: median(b_ns),
    }
}

// ---------------------------------------------------------------------------------------------
// States

/// A deterministic pseudo-random vector in `[-range, range)` (the xorshift of
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

/// The Pinocchio benchmark's joint states: seeds `1000 + k`, angles in `[-pi, pi)`.
fn peer_states<const N: usize>() -> Vec<SVector<f64, N>> {
    (0..STATES as u64).map(|k| state(1000 + k, PI)).collect()
}

/// Uniform joint values for the IK targets: angles in (-pi, pi], the Stanford arm's slide in
/// [`SLIDE`] (splitmix64, seeded per arm).
struct Rng(u64);

impl Rng {
    fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        #[allow(clippy::cast_precision_loss)]
        let u = ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64;
        u
    }

    fn q<const N: usize>(&mut self, model: &SpatialModel<N>) -> SVector<f64, N> {
        SVector::from_fn(|i, _| match model.joints[i].kind {
            // 1 - u is in (0, 1], so the angle is in (-pi, pi].
            Joint::Revolute => PI - 2.0 * PI * self.unit(),
            Joint::Prismatic => SLIDE.0 + (SLIDE.1 - SLIDE.0) * self.unit(),
        })
    }

    /// A direction of Euclidean norm `norm`.
    fn offset<const N: usize>(&mut self, norm: f64) -> SVector<f64, N> {
        loop {
            let v = SVector::<f64, N>::from_fn(|_, _| 2.0 * self.unit() - 1.0);
            let n = v.norm();
            if n > 0.1 && n <= 1.0 {
                return v * (norm / n);
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Checks

/// The larger of the distance between the origins and the rotation angle between the frames.
fn pose_gap(a: &Isometry3<f64>, b: &Isometry3<f64>) -> f64 {
    let d = a.inverse() * b;
    d.translation.vector.norm().max(d.rotation.angle())
}

/// `tip_pose` and `jacobian` against `reference::spatial` at the peer states and 100 random
/// configurations; the largest difference (pose gap, Jacobian entry), panicking above 1e-12.
fn agreement<A: SpatialArm<N> + Default, const N: usize>(name: &str) -> f64 {
    let arm = A::default();
    let model = arm.model();
    let mut rng = Rng(7);
    let mut worst = 0.0_f64;
    let mut qs = peer_states::<N>();
    qs.extend((0..100).map(|_| rng.q(&model)));
    for q in &qs {
        worst = worst
            .max(pose_gap(&arm.tip_pose(q), &reference::tip_pose(&model, q)))
            .max((arm.jacobian(q) - reference::jacobian(&model, q)).amax());
    }
    assert!(worst < 1e-12, "{name}: generated vs reference {worst:e}");
    worst
}

/// Whether two configurations agree to 1e-7, angles modulo a turn.
fn same_configuration<const N: usize>(
    model: &SpatialModel<N>,
    a: &SVector<f64, N>,
    b: &SVector<f64, N>,
) -> bool {
    (0..N).all(|i| match model.joints[i].kind {
        Joint::Revolute => {
            let d = (a[i] - b[i]).rem_euclid(2.0 * PI);
            d.min(2.0 * PI - d) < 1e-7
        }
        Joint::Prismatic => (a[i] - b[i]).abs() < 1e-7,
    })
}

// ---------------------------------------------------------------------------------------------
// Pose and Jacobian

/// `tip_pose` + `jacobian`, one call each, whole outputs through `black_box`; one entry of
/// each returned (the checksum of `--peer`).
#[inline(always)]
fn pose_and_jacobian<A: SpatialArm<N>, const N: usize>(arm: &A, q: &SVector<f64, N>) -> f64 {
    let q = black_box(q);
    let pose = black_box(arm.tip_pose(q));
    let j: SMatrix<f64, 6, N> = black_box(arm.jacobian(q));
    pose.translation.vector.x + j[(0, N - 1)]
}

/// What one arm's pose and Jacobian cost: ns per call of `tip_pose`, `jacobian`, both, the
/// reference's two, N `f64::sin_cos` (the floor: one per joint) and the N angles through
/// `trig::sin_cos` (the generated code's kernel), all interleaved with `tip_pose` + `jacobian`.
struct PoseRow {
    name: &'static str,
    n: usize,
    both: f64,
    tip: f64,
    jac: f64,
    reference: f64,
    sin_cos: f64,
    trig: f64,
    agreement: f64,
}

fn pose_row<A: SpatialArm<N> + Default, const N: usize>(name: &'static str) -> PoseRow {
    let agreement = agreement::<A, N>(name);
    let arm = A::default();
    let model = arm.model();
    let qs = peer_states::<N>();
    let both = |k: usize| {
        pose_and_jacobian(&arm, &qs[k]);
    };
    let tip = interleaved(both, |k| {
        black_box(arm.tip_pose(black_box(&qs[k])));
    });
    let jac = interleaved(both, |k| {
        black_box(arm.jacobian::<f64>(black_box(&qs[k])));
    });
    let reference = interleaved(both, |k| {
        let q = black_box(&qs[k]);
        let model = black_box(&model);
        black_box(reference::tip_pose(model, q));
        black_box(reference::jacobian(model, q));
    });
    let sin_cos = interleaved(both, |k| {
        let q = black_box(&qs[k]);
        let out: [(f64, f64); N] = core::array::from_fn(|j| q[j].sin_cos());
        black_box(out);
    });
    // The kernel the generated methods call (`tip_pose` and `jacobian` call it once each).
    let trig = interleaved(both, |k| {
        black_box(planar_arm::trig::sin_cos(black_box(&qs[k]).data.0[0]));
    });
    PoseRow {
        name,
        n: N,
        both: median(vec![
            tip.a_ns,
            jac.a_ns,
            reference.a_ns,
            sin_cos.a_ns,
            trig.a_ns,
        ]),
        tip: tip.b_ns,
        jac: jac.b_ns,
        reference: reference.b_ns,
        sin_cos: sin_cos.b_ns,
        trig: trig.b_ns,
        agreement,
    }
}

// ---------------------------------------------------------------------------------------------
// Inverse kinematics

/// One six-joint arm's closed-form IK against `tip_pose` and against `inverse_kinematics_near`.
struct IkRow {
    name: &'static str,
    /// IK's time over `tip_pose`'s.
    over_tip: Pair,
    /// `inverse_kinematics_near`'s time over IK's.
    near_over_ik: Pair,
    /// How many targets had 0, 1, ..., 8 solutions.
    counts: [usize; 9],
    /// The largest pose gap of a closed-form solution and of a converged DLS solution.
    ik_gap: f64,
    near_gap: f64,
    /// The largest distance (joint space) of a DLS solution from the configuration the
    /// target came from.
    near_distance: f64,
    /// DLS iterations (one `tip_pose` and one `jacobian` each): mean and largest over the
    /// targets.
    iterations: (f64, usize),
}

/// The fewest `max_iterations` with which `inverse_kinematics_near` converges: how many
/// iterations it takes.
fn dls_iterations<A: SpatialArm<6>>(
    arm: &A,
    target: &Isometry3<f64>,
    seed: &SVector<f64, 6>,
    options: &DlsOptions<6>,
) -> usize {
    (1..=options.max_iterations)
        .find(|&max_iterations| {
            let options = DlsOptions {
                max_iterations,
                ..*options
            };
            arm.inverse_kinematics_near(target, seed, &options).is_ok()
        })
        .expect("converges within max_iterations")
}

fn ik_row<A: SpatialArm<6> + Default>(name: &'static str, seed: u64) -> IkRow {
    let arm = A::default();
    let model = arm.model();
    let mut rng = Rng(seed);
    let qs: Vec<SVector<f64, 6>> = (0..STATES).map(|_| rng.q(&model)).collect();
    let targets: Vec<Isometry3<f64>> = qs.iter().map(|q| arm.tip_pose(q)).collect();
    let seeds: Vec<SVector<f64, 6>> = qs.iter().map(|q| q + rng.offset(0.1)).collect();
    let options = DlsOptions::<6>::default();
    assert!((options.tolerance - 1e-10).abs() < 1e-25);

    let (mut counts, mut ik_gap, mut near_gap, mut near_distance) = ([0; 9], 0.0_f64, 0.0, 0.0);
    let (mut iterations, mut most) = (0, 0);
    for ((q, target), seed) in qs.iter().zip(&targets).zip(&seeds) {
        let solutions = arm
            .inverse_kinematics(target)
            .unwrap_or_else(|e| panic!("{name}: {q}: {e}"));
        for s in solutions.iter() {
            ik_gap = ik_gap.max(pose_gap(&arm.tip_pose(s), target));
        }
        assert!(
            solutions.iter().any(|s| same_configuration(&model, s, q)),
            "{name}: {q} is not among the solutions"
        );
        counts[solutions.len()] += 1;
        let near = arm
            .inverse_kinematics_near(target, seed, &options)
            .unwrap_or_else(|e| panic!("{name}: DLS from {seed}: {e}"));
        near_gap = near_gap.max(pose_gap(&arm.tip_pose(&near), target));
        near_distance = near_distance.max((near - q).norm());
        let it = dls_iterations(&arm, target, seed, &options);
        iterations += it;
        most = most.max(it);
    }
    assert!(
        ik_gap < 1e-9,
        "{name}: closed-form solution off by {ik_gap:e}"
    );
    assert!(near_gap < 1e-9, "{name}: DLS solution off by {near_gap:e}");

    let over_tip = interleaved(
        |k| {
            black_box(arm.tip_pose(black_box(&qs[k])));
        },
        |k| {
            let _ = black_box(arm.inverse_kinematics(black_box(&targets[k])));
        },
    );
    let near_over_ik = interleaved(
        |k| {
            let _ = black_box(arm.inverse_kinematics(black_box(&targets[k])));
        },
        |k| {
            let _ = black_box(arm.inverse_kinematics_near(
                black_box(&targets[k]),
                black_box(&seeds[k]),
                black_box(&options),
            ));
        },
    );
    IkRow {
        name,
        over_tip,
        near_over_ik,
        counts,
        ik_gap,
        near_gap,
        near_distance,
        #[allow(clippy::cast_precision_loss)]
        iterations: (iterations as f64 / STATES as f64, most),
    }
}

// ---------------------------------------------------------------------------------------------
// The modes of bench/pinocchio/run.sh

/// The tool pose (homogeneous 4x4) and the Jacobian at the first four peer states, by
/// columns, each number in Rust's shortest form that reads back to the same `f64`.
fn values<A: SpatialArm<N> + Default, const N: usize>(name: &str) {
    let arm = A::default();
    let list = |v: &[f64]| {
        v.iter()
            .map(|x| format!("{x:e}"))
            .collect::<Vec<_>>()
            .join(" ")
    };
    for (k, q) in peer_states::<N>().iter().take(4).enumerate() {
        let pose = arm.tip_pose(q).to_homogeneous();
        let j = arm.jacobian(q);
        println!("# value, {name}, pose, {k}, {}", list(pose.as_slice()));
        println!("# value, {name}, jacobian, {k}, {}", list(j.as_slice()));
    }
}

/// `peers.cpp`'s `time_op` for `tip_pose` + `jacobian`: `calls` calls per round over the 64
/// peer states, 21 rounds after one warm-up; prints `rust, N, ARM/tip_pose+jacobian, wall
/// ns/call, cpu ns/call` and returns the checksum.
fn peer_timing<A: SpatialArm<N> + Default, const N: usize>(name: &str, calls: usize) -> f64 {
    const ROUNDS: usize = 21;
    let arm = A::default();
    let qs = peer_states::<N>();
    let (mut wall, mut cpu, mut checksum) = (Vec::new(), Vec::new(), 0.0);
    for r in 0..=ROUNDS {
        let mut acc = 0.0;
        let mut k = 0;
        let c0 = thread_cpu_ns();
        let t0 = Instant::now();
        for _ in 0..calls {
            acc += pose_and_jacobian(&arm, &qs[k]);
            k += 1;
            if k == STATES {
                k = 0;
            }
        }
        let t1 = t0.elapsed();
        let c1 = thread_cpu_ns();
        checksum += acc;
        if r > 0 {
            #[allow(clippy::cast_precision_loss)]
            let calls = calls as f64;
            wall.push(t1.as_secs_f64() * 1e9 / calls);
            cpu.push((c1 - c0) / calls);
        }
    }
    println!(
        "rust, {N}, {name}/tip_pose+jacobian, {:.1}, {:.1}",
        median(wall),
        median(cpu)
    );
    checksum
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.iter().any(|a| a == "--values") {
        values::<Puma560, 6>("Puma560");
        values::<Ur5, 6>("Ur5");
        values::<Panda, 7>("Panda");
        return;
    }
    if let Some(i) = args.iter().position(|a| a == "--peer") {
        let calls = args
            .get(i + 1)
            .and_then(|c| c.parse().ok())
            .unwrap_or(200_000);
        println!("variant, N, op, wall ns/call, cpu ns/call");
        let checksum = peer_timing::<Puma560, 6>("Puma560", calls)
            + peer_timing::<Ur5, 6>("Ur5", calls)
            + peer_timing::<Panda, 7>("Panda", calls);
        println!("# checksum {checksum:.17e}");
        return;
    }

    let poses = [
        pose_row::<Puma560, 6>("Puma560"),
        pose_row::<Ur5, 6>("Ur5"),
        pose_row::<Panda, 7>("Panda"),
        pose_row::<Stanford, 6>("Stanford"),
    ];
    println!("Tool pose and Jacobian (ns per call, thread CPU time, 64 states in [-pi, pi)):\n");
    println!(
        "| arm | N | tip_pose + jacobian | tip_pose | jacobian | reference (both) | reference / generated | N f64::sin_cos | trig::sin_cos of N | agreement with the reference |"
    );
    println!("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|");
    for r in &poses {
        println!(
            "| {} | {} | {:.1} | {:.1} | {:.1} | {:.1} | {:.1}x | {:.1} | {:.1} | {:.1e} |",
            r.name,
            r.n,
            r.both,
            r.tip,
            r.jac,
            r.reference,
            r.reference / r.both,
            r.sin_cos,
            r.trig,
            r.agreement
        );
    }

    let iks = [
        ik_row::<Puma560>("Puma560", 1),
        ik_row::<Ur5>("Ur5", 2),
        ik_row::<Stanford>("Stanford", 3),
    ];
    println!(
        "\nClosed-form IK (all solutions) of 64 generic targets against one tip_pose call and \
         against inverse_kinematics_near (DlsOptions::default(), tolerance 1e-10) from a seed \
         0.1 rad (Euclidean norm) from the target's configuration; ns per call, thread CPU \
         time; each ratio the median of 101 interleaved rounds:\n"
    );
    println!(
        "| arm | tip_pose | IK | IK / tip_pose | IK | inverse_kinematics_near | near / IK | DLS iterations (mean, max) | solutions (targets) | worst IK pose gap | worst DLS pose gap | DLS to the origin configuration |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|");
    for r in &iks {
        let counts = r
            .counts
            .iter()
            .enumerate()
            .filter(|(_, &c)| c > 0)
            .map(|(n, c)| format!("{n} ({c})"))
            .collect::<Vec<_>>()
            .join(", ");
        println!(
            "| {} | {:.1} | {:.1} | {:.2}x | {:.1} | {:.0} | {:.2}x | {:.1}, {} | {counts} | {:.1e} | {:.1e} | {:.1e} |",
            r.name,
            r.over_tip.a_ns,
            r.over_tip.b_ns,
            r.over_tip.ratio,
            r.near_over_ik.a_ns,
            r.near_over_ik.b_ns,
            r.near_over_ik.ratio,
            r.iterations.0,
            r.iterations.1,
            r.ik_gap,
            r.near_gap,
            r.near_distance
        );
    }
}
