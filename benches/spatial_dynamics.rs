//! Spatial dynamics against Pinocchio (`bench/pinocchio/run.sh`, `ARMS=spatial-dynamics`): the
//! generated `inverse_dynamics`, `mass_matrix`, `bias`, `mass_matrix_and_bias`,
//! `forward_dynamics`, `inverse_dynamics_derivatives` and `forward_dynamics_derivatives`, and
//! `Identification`'s `regressor` and `base_regressor`, of the PUMA 560, the UR5 and the Franka
//! Panda with their published mass properties.
//!
//! Not run in CI. Two modes, both for `run.sh`:
//!
//! - `-- --values` prints, at the first four of the Pinocchio benchmark's states,
//!   `inverse_dynamics(q, qd, qdd)` (`rnea`), `mass_matrix(q)` by columns (`crba`),
//!   `bias(q, qd)` (`nle`), `mass_matrix_and_bias` (`crba+nle`: M by columns, then h) and
//!   `forward_dynamics(q, qd, tau)` with `qdd` as `tau` (`aba`),
//!   `inverse_dynamics_derivatives(q, qd, qdd)` (`rnea_derivatives`: dtau/dq then dtau/dqd,
//!   by columns) and `forward_dynamics_derivatives(q, qd, tau)` with `qdd` as `tau`
//!   (`aba_derivatives`: dqdd/dq, dqdd/dqd, then M^-1, by columns) and `regressor(q, qd, qdd)`'s
//!   first 10 N columns, the ten rigid-body parameters of each link (`regressor`, by columns),
//!   for `run.sh` to compare with Pinocchio's. Before printing, the first five methods are
//!   checked against `reference::spatial` at the 64 states (1e-10 relative), so that the arms
//!   are what the crate's reference makes of the same numbers, and `regressor` and
//!   `base_regressor` times their parameters against `inverse_dynamics`; the derivatives are
//!   checked only against Pinocchio's `computeRNEADerivatives` and `computeABADerivatives`, the
//!   regressor only against `computeJointTorqueRegressor` (the PUMA's after a change of frames:
//!   see `peers.cpp`).
//! - `-- --peer CALLS` times the eight methods (not `bias`) exactly as `peers.cpp` times Pinocchio: 64
//!   states cycled, `CALLS` calls per round, 21 rounds after one warm-up, the medians per call
//!   by the wall clock and by the thread's CPU time, in its output format.
//!
//! ```text
//! CARGO_TARGET_DIR=/tmp/target_bench cargo bench --bench spatial_dynamics -- --values
//! ```
//!
//! The arms' numbers are stated, with their sources, in `bench/pinocchio/README.md`; the UR5's
//! and the Panda's attributes were printed by `bench/pinocchio/urdf_arms.py` from
//! example-robot-data's URDFs.

use core::f64::consts::PI;
use std::hint::black_box;
use std::time::Instant;

use planar_arm::prelude::*;
use planar_arm::reference::spatial as reference;
use planar_arm::spatial::SpatialArm;

/// PUMA 560, Corke's standard DH parameters and mass properties, as `examples/puma.rs` has
/// them.
#[path = "../examples/support/puma_arm.rs"]
mod puma_arm;
use puma_arm::Puma560;

/// The UR5 of example-robot-data's `ur_description/urdf/ur5_robot.urdf` (ROS-Industrial's
/// `ur_description`): URDF joints, each link's mass, centre of mass and inertia tensor as
/// there (the massless `ee_link`, `tool0` and `base` left out; the URDF's quarter turns
/// `1.57079632679` written `pi/2`). Gravity `(0, 0, -9.81)`, as Pinocchio's default.
#[derive(SpatialArm, Default)]
#[arm(gravity = (0, 0, -9.81))]
struct Ur5 {
    #[arm(origin(xyz = (0, 0, 0.089159), rpy = (0, 0, 0)), axis = (0, 0, 1),
          mass = 3.7, com = (0, 0, 0),
          inertia(xx = 0.010267495893, yy = 0.010267495893, zz = 0.00666, xy = 0, xz = 0, yz = 0))]
    shoulder_pan_joint: Revolute,
    #[arm(origin(xyz = (0, 0.13585, 0), rpy = (0, pi/2, 0)), axis = (0, 1, 0),
          mass = 8.393, com = (0, 0, 0.28),
          inertia(xx = 0.22689067591, yy = 0.22689067591, zz = 0.0151074, xy = 0, xz = 0, yz = 0))]
    shoulder_lift_joint: Revolute,
    #[arm(origin(xyz = (0, -0.1197, 0.425), rpy = (0, 0, 0)), axis = (0, 1, 0),
          mass = 2.275, com = (0, 0, 0.25),
          inertia(xx = 0.049443313556, yy = 0.049443313556, zz = 0.004095, xy = 0, xz = 0, yz = 0))]
    elbow_joint: Revolute,
    #[arm(origin(xyz = (0, 0, 0.39225), rpy = (0, pi/2, 0)), axis = (0, 1, 0),
          mass = 1.219, com = (0, 0, 0),
          inertia(xx = 0.111172755531, yy = 0.111172755531, zz = 0.21942, xy = 0, xz = 0, yz = 0))]
    wrist_1_joint: Revolute,
    #[arm(origin(xyz = (0, 0.093, 0), rpy = (0, 0, 0)), axis = (0, 0, 1),
          mass = 1.219, com = (0, 0, 0),
          inertia(xx = 0.111172755531, yy = 0.111172755531, zz = 0.21942, xy = 0, xz = 0, yz = 0))]
    wrist_2_joint: Revolute,
    #[arm(origin(xyz = (0, 0, 0.09465), rpy = (0, 0, 0)), axis = (0, 1, 0),
          mass = 0.1879, com = (0, 0, 0),
          inertia(xx = 0.0171364731454, yy = 0.0171364731454, zz = 0.033822, xy = 0, xz = 0, yz = 0))]
    wrist_3_joint: Revolute,
}

/// The Franka Panda of example-robot-data's `panda_description/urdf/panda.urdf`: URDF joints,
/// links 1-6 as there, link 7 with the hand (fixed 0.107 m along z, turned -pi/4 about it) and
/// its two fingers (locked at zero opening) merged into it by `urdf_arms.py`.
#[derive(SpatialArm, Default)]
#[arm(gravity = (0, 0, -9.81))]
struct Panda {
    #[arm(origin(xyz = (0, 0, 0.333), rpy = (0, 0, 0)), axis = (0, 0, 1),
          mass = 4.970684, com = (0.003875, 0.002081, -0.04762),
          inertia(xx = 0.70337, yy = 0.70661, zz = 0.009117, xy = -0.000139, xz = 0.006772, yz = 0.019169))]
    panda_joint1: Revolute,
    #[arm(origin(xyz = (0, 0, 0), rpy = (-pi/2, 0, 0)), axis = (0, 0, 1),
          mass = 0.646926, com = (-0.003141, -0.02872, 0.003495),
          inertia(xx = 0.007962, yy = 0.02811, zz = 0.025995, xy = -0.003925, xz = 0.010254, yz = 0.000704))]
    panda_joint2: Revolute,
    #[arm(origin(xyz = (0, -0.316, 0), rpy = (pi/2, 0, 0)), axis = (0, 0, 1),
          mass = 3.228604, com = (0.027518, 0.039252, -0.066502),
          inertia(xx = 0.037242, yy = 0.036155, zz = 0.01083, xy = -0.004761, xz = -0.011396, yz = -0.012805))]
    panda_joint3: Revolute,
    #[arm(origin(xyz = (0.0825, 0, 0), rpy = (pi/2, 0, 0)), axis = (0, 0, 1),
          mass = 3.587895, com = (-0.05317, 0.104419, 0.027454),
          inertia(xx = 0.025853, yy = 0.019552, zz = 0.028323, xy = 0.007796, xz = -0.001332, yz = 0.008641))]
    panda_joint4: Revolute,
    #[arm(origin(xyz = (-0.0825, 0.384, 0), rpy = (-pi/2, 0, 0)), axis = (0, 0, 1),
          mass = 1.225946, com = (-0.011953, 0.041065, -0.038437),
          inertia(xx = 0.035549, yy = 0.029474, zz = 0.008627, xy = -0.002117, xz = -0.004037, yz = 0.000229))]
    panda_joint5: Revolute,
    #[arm(origin(xyz = (0, 0, 0), rpy = (pi/2, 0, 0)), axis = (0, 0, 1),
          mass = 1.666555, com = (0.060149, -0.014117, -0.010517),
          inertia(xx = 0.001964, yy = 0.004354, zz = 0.005433, xy = 0.000109, xz = -0.001158, yz = 0.000341))]
    panda_joint6: Revolute,
    #[arm(origin(xyz = (0.088, 0, 0), rpy = (pi/2, 0, 0)), axis = (0, 0, 1),
          mass = 1.4955219999999998, com = (0.0017208742976286568, 0.001360354417161231, 0.1004852811486558),
          inertia(xx = 0.016529853712634632, yy = 0.014107248642161837, zz = 0.006676955556640956, xy = 0.0003948922971191779, xz = -0.0007066957106145017, yz = -0.001051105327046708))]
    panda_joint7: Revolute,
}

/// How many states each timing cycles through, as `peers.cpp`.
const STATES: usize = 64;

#[path = "support/cpu_clock.rs"]
mod cpu_clock;
use cpu_clock::{median, thread_cpu_ns};

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

/// The Pinocchio benchmark's states (`peers.cpp`'s `dynamics_states`): state k has q from
/// seed `1000 + 3k` in `[-pi, pi)`, qd from `1001 + 3k` in `[-1, 1)` and qdd (the torques of
/// `forward_dynamics`) from `1002 + 3k` in `[-1, 1)`.
struct States<const N: usize> {
    q: Vec<SVector<f64, N>>,
    qd: Vec<SVector<f64, N>>,
    qdd: Vec<SVector<f64, N>>,
}

fn states<const N: usize>() -> States<N> {
    let k = 0..STATES as u64;
    States {
        q: k.clone().map(|k| state(1000 + 3 * k, PI)).collect(),
        qd: k.clone().map(|k| state(1001 + 3 * k, 1.0)).collect(),
        qdd: k.map(|k| state(1002 + 3 * k, 1.0)).collect(),
    }
}

/// The largest difference between `a` and `b` relative to the larger max-norm (at least 1).
fn relative(a: &[f64], b: &[f64]) -> f64 {
    let scale = a.iter().chain(b).fold(1.0_f64, |m, x| m.max(x.abs()));
    a.iter()
        .zip(b)
        .fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()))
        / scale
}

/// Every method against `reference::spatial` at the 64 states, and the regressors times
/// their parameters against `inverse_dynamics`, panicking above 1e-10.
fn check<A, const N: usize, const P: usize, const B: usize>(name: &str, arm: &A)
where
    A: SpatialArm<N> + Identification<N, P, B>,
{
    let model = arm.model();
    let s = states::<N>();
    let (theta, base) = (arm.standard_parameters(), arm.base_parameters());
    let mut worst = [0.0_f64; 7];
    for k in 0..STATES {
        let (q, qd, qdd) = (&s.q[k], &s.qd[k], &s.qdd[k]);
        let m = reference::mass_matrix(&model, q);
        let h = reference::bias_forces(&model, q, qd);
        let (gm, gh) = arm.mass_matrix_and_bias(q, qd);
        let errs = [
            relative(
                arm.inverse_dynamics(q, qd, qdd).as_slice(),
                reference::inverse_dynamics(&model, q, qd, qdd).as_slice(),
            ),
            relative(arm.mass_matrix(q).as_slice(), m.as_slice()),
            relative(arm.bias(q, qd).as_slice(), h.as_slice()),
            relative(gm.as_slice(), m.as_slice()).max(relative(gh.as_slice(), h.as_slice())),
            relative(
                arm.forward_dynamics(q, qd, qdd).as_slice(),
                reference::forward_dynamics(&model, q, qd, qdd).as_slice(),
            ),
            relative(
                (arm.regressor(q, qd, qdd) * theta).as_slice(),
                arm.inverse_dynamics(q, qd, qdd).as_slice(),
            ),
            relative(
                (arm.base_regressor(q, qd, qdd) * base).as_slice(),
                arm.inverse_dynamics(q, qd, qdd).as_slice(),
            ),
        ];
        for (w, e) in worst.iter_mut().zip(errs) {
            *w = w.max(e);
        }
    }
    println!(
        "# {name}: generated vs reference::spatial over {STATES} states: inverse_dynamics \
         {:.1e}, mass_matrix {:.1e}, bias {:.1e}, mass_matrix_and_bias {:.1e}, \
         forward_dynamics {:.1e}; regressor * theta {:.1e}, base_regressor * theta_b {:.1e} \
         vs inverse_dynamics ({P} standard, {B} base parameters)",
        worst[0], worst[1], worst[2], worst[3], worst[4], worst[5], worst[6]
    );
    assert!(
        worst.iter().all(|&w| w < 1e-10),
        "{name}: generated and reference::spatial disagree"
    );
}

/// The results at the first four states as `# value, ARM, OP, K, ...` lines (matrices by
/// columns), each number in Rust's shortest form that reads back to the same `f64`.
fn values<A, const N: usize, const P: usize, const B: usize>(name: &str, arm: &A)
where
    A: SpatialArm<N> + Identification<N, P, B>,
{
    check(name, arm);
    let s = states::<N>();
    let list = |v: &[f64]| {
        v.iter()
            .map(|x| format!("{x:e}"))
            .collect::<Vec<_>>()
            .join(" ")
    };
    for k in 0..4 {
        let (q, qd, qdd) = (&s.q[k], &s.qd[k], &s.qdd[k]);
        let (m, h) = arm.mass_matrix_and_bias(q, qd);
        let both: Vec<f64> = m.iter().chain(h.iter()).copied().collect();
        println!(
            "# value, {name}, rnea, {k}, {}",
            list(arm.inverse_dynamics(q, qd, qdd).as_slice())
        );
        println!(
            "# value, {name}, crba, {k}, {}",
            list(arm.mass_matrix(q).as_slice())
        );
        println!(
            "# value, {name}, nle, {k}, {}",
            list(arm.bias(q, qd).as_slice())
        );
        println!("# value, {name}, crba+nle, {k}, {}", list(&both));
        println!(
            "# value, {name}, aba, {k}, {}",
            list(arm.forward_dynamics(q, qd, qdd).as_slice())
        );
        let (dq, dqd) = arm.inverse_dynamics_derivatives(q, qd, qdd);
        let both: Vec<f64> = dq.iter().chain(dqd.iter()).copied().collect();
        println!("# value, {name}, rnea_derivatives, {k}, {}", list(&both));
        let (dq, dqd, minv) = arm.forward_dynamics_derivatives(q, qd, qdd);
        let all: Vec<f64> = dq
            .iter()
            .chain(dqd.iter())
            .chain(minv.iter())
            .copied()
            .collect();
        println!("# value, {name}, aba_derivatives, {k}, {}", list(&all));
        // The rigid-body columns (10 per link), what computeJointTorqueRegressor gives; the
        // arms here have no armature, friction or payload, so that is all of them.
        let y = arm.regressor(q, qd, qdd);
        println!(
            "# value, {name}, regressor, {k}, {}",
            list(&y.as_slice()[..N * 10 * N])
        );
    }
}

/// `peers.cpp`'s `time_op`: `calls` calls of `f(k)` per round over the 64 states, 21 rounds
/// after one warm-up; prints `rust, N, ARM/OP, wall ns/call, cpu ns/call` and returns the
/// checksum (the sum of `f`'s results).
fn time_op<const N: usize>(
    name: &str,
    op: &str,
    calls: usize,
    mut f: impl FnMut(usize) -> f64,
) -> f64 {
    const ROUNDS: usize = 21;
    let (mut wall, mut cpu, mut checksum) = (Vec::new(), Vec::new(), 0.0);
    for r in 0..=ROUNDS {
        let mut acc = 0.0;
        let mut k = 0;
        let c0 = thread_cpu_ns();
        let t0 = Instant::now();
        for _ in 0..calls {
            acc += f(k);
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
        "rust, {N}, {name}/{op}, {:.1}, {:.1}",
        median(wall),
        median(cpu)
    );
    checksum
}

/// The eight methods, one call each per `f(k)`: inputs and whole outputs through `black_box`,
/// one entry of the output returned for the checksum (as `peers.cpp` sums one). The outputs go
/// to `black_box` by reference, where a user's program would read them: moved into it, a
/// result that came back from the AVX2 copy was copied once more, which costs the dispatched
/// methods 20-25 % (docs/performance.md) and no user who reads the result in place.
fn peer<A, const N: usize, const P: usize, const B: usize>(name: &str, arm: &A, calls: usize) -> f64
where
    A: SpatialArm<N> + Identification<N, P, B>,
{
    let s = states::<N>();
    let inputs = |k: usize| {
        (
            black_box(&s.q[k]),
            black_box(&s.qd[k]),
            black_box(&s.qdd[k]),
        )
    };
    let mut checksum = time_op::<N>(name, "inverse_dynamics", calls, |k| {
        let (q, qd, qdd) = inputs(k);
        let tau = arm.inverse_dynamics(q, qd, qdd);
        black_box(&tau);
        tau[0]
    });
    checksum += time_op::<N>(name, "mass_matrix", calls, |k| {
        let m = arm.mass_matrix(black_box(&s.q[k]));
        black_box(&m);
        m[(0, N - 1)]
    });
    checksum += time_op::<N>(name, "forward_dynamics", calls, |k| {
        let (q, qd, tau) = inputs(k);
        let qdd = arm.forward_dynamics(q, qd, tau);
        black_box(&qdd);
        qdd[N - 1]
    });
    checksum += time_op::<N>(name, "mass_matrix_and_bias", calls, |k| {
        let (q, qd, _) = inputs(k);
        let mh = arm.mass_matrix_and_bias(q, qd);
        black_box(&mh);
        mh.0[(0, N - 1)] + mh.1[0]
    });
    checksum += time_op::<N>(name, "inverse_dynamics_derivatives", calls, |k| {
        let (q, qd, qdd) = inputs(k);
        let d = arm.inverse_dynamics_derivatives(q, qd, qdd);
        black_box(&d);
        d.0[(0, N - 1)] + d.1[(0, 0)]
    });
    checksum += time_op::<N>(name, "forward_dynamics_derivatives", calls, |k| {
        let (q, qd, tau) = inputs(k);
        let d = arm.forward_dynamics_derivatives(q, qd, tau);
        black_box(&d);
        d.0[(N - 1, 0)] + d.1[(0, 0)] + d.2[(0, N - 1)]
    });
    checksum += time_op::<N>(name, "regressor", calls, |k| {
        let (q, qd, qdd) = inputs(k);
        let y = arm.regressor(q, qd, qdd);
        black_box(&y);
        y[(N - 1, 10 * N - 1)]
    });
    checksum += time_op::<N>(name, "base_regressor", calls, |k| {
        let (q, qd, qdd) = inputs(k);
        let y = arm.base_regressor(q, qd, qdd);
        black_box(&y);
        y[(N - 1, B - 1)]
    });
    checksum
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.iter().any(|a| a == "--values") {
        values("Puma560", &Puma560::default());
        values("Ur5", &Ur5::default());
        values("Panda", &Panda::default());
        return;
    }
    let calls = args
        .iter()
        .position(|a| a == "--peer")
        .and_then(|i| args.get(i + 1))
        .and_then(|c| c.parse().ok())
        .unwrap_or(200_000);
    println!("variant, N, op, wall ns/call, cpu ns/call");
    let checksum = peer("Puma560", &Puma560::default(), calls)
        + peer("Ur5", &Ur5::default(), calls)
        + peer("Panda", &Panda::default(), calls);
    println!("# checksum {checksum:.17e}");
}
