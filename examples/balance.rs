//! Balances the paper's two-link arm (two uniform rods, 1 m and 1 kg each) straight up, the
//! double inverted pendulum, with a linear-quadratic regulator designed from the derived
//! linearisation ([`Linearize`]) and run on the full nonlinear dynamics:
//!
//! 1. a check of the linearisation against numbers that do not come from the crate: the
//!    open-loop eigenvalues of `A` at upright against the textbook double pendulum's, from `M`
//!    and the gravity stiffness worked out by hand;
//! 2. a discrete-time LQR for a 10 ms control period: the zero-order-hold pair from
//!    `discretize` at upright and its gain from [`dlqr`](planar_arm::dlqr), checked here by
//!    the residual of the discrete algebraic Riccati equation written out and by the
//!    closed-loop eigenvalues (inside the unit circle), and set beside the continuous-time
//!    gain [`lqr`](planar_arm::lqr) gives from `linearize` with the same weights, which the
//!    discrete one approaches as the period shrinks;
//! 3. the controller `tau = u* - K (x - x*)`, held for 10 ms at a time, on the nonlinear
//!    dynamics (`forward_dynamics`, RK4 at 1 ms) from 0.15 rad and -0.2 rad off upright, 5 s;
//! 4. the acrobot: the same arm with only the elbow driven. One input, but controllable at
//!    upright (the rank of its controllability matrix), and balanced by the same recipe from
//!    0.02 rad off at the shoulder. Not from 0.05 rad: the passive shoulder is moved only by
//!    swinging the elbow, about 35 times as far as the shoulder is off, and past about a
//!    radian the linear model no longer describes the arm. The example measures how far off
//!    it can start along three directions: about 0.02 rad at the shoulder alone, 0.08 rad at
//!    the elbow alone, and more than 0.5 rad where the centre of mass starts over the base.
//!
//! It asserts that both runs end within 1e-3 of upright, and draws `balance-two-link.svg` and
//! `balance-acrobot.svg`: angle errors and torques against time, and a strobe picture of the
//! arm. The pictures go to `target/pictures/`, to `DIR` with `--out DIR`, or with `--docs` to
//! `docs/`, where README.md shows them.
//!
//! ```text
//! cargo run --release --example balance [-- --out DIR | -- --docs]
//! ```

#[path = "support/num.rs"]
mod num;
#[path = "support/out.rs"]
mod out;
#[path = "balance/pictures.rs"]
mod pictures;
#[path = "support/plot.rs"]
mod plot;

use std::error::Error;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

use planar_arm::nalgebra::{Complex, Matrix2, Matrix4, SMatrix, Vector4};
use planar_arm::prelude::*;
use planar_arm::{dlqr, lqr};

use num::{complex, fixed, sig};
use out::Out;

/// The paper's two equal links: uniform rods, 1 m and 1 kg.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct Rods {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 1, mass = 1)]
    fore: Revolute,
}

/// The arm's gravity, m/s^2, for the hand computation.
const G: f64 = 9.81;
/// Control period, s: the controller samples the state and holds its torque this long.
const PERIOD: f64 = 0.01;
/// RK4 steps per control period: 1 ms, fine enough that the integrator's error is far below
/// what is being checked.
const SUBSTEPS: u32 = 10;
/// Control periods simulated: 5 s.
const STEPS: u32 = 500;

type V2 = Vector2<f64>;
type X = Vector4<f64>;

fn upright() -> V2 {
    V2::new(FRAC_PI_2, 0.0)
}

/// An angle in [-pi, pi): the arm a full turn away is the same arm.
fn wrap(a: f64) -> f64 {
    (a + PI).rem_euclid(TAU) - PI
}

/// `x - x*` with the angles wrapped.
fn state_error(q: &V2, qd: &V2) -> X {
    let e = q - upright();
    X::new(wrap(e[0]), wrap(e[1]), qd[0], qd[1])
}

/// Step 1: the eigenvalues of `A` at upright against the textbook's. Returns the largest
/// difference.
fn textbook_check(arm: &Rods) -> f64 {
    println!("== 1. the linearisation against the textbook double pendulum ==");
    // By hand, from the rods' energies (docs of the crate): at q2 = 0 the mass matrix is
    // M = [[5/3 + 1, 1/3 + 1/2], [1/3 + 1/2, 1/3]], and with c1 = 0, s1 = 1 at q1 = pi/2,
    // g(q) = g (3/2 c1 + 1/2 c12, 1/2 c12) has -dg/dq = g [[3/2 + 1/2, 1/2], [1/2, 1/2]].
    // Small motions obey M dqdd = K dq, so A's eigenvalues are +-sqrt(mu), mu those of
    // M^-1 K, from its trace and determinant.
    let m = Matrix2::new(8.0 / 3.0, 5.0 / 6.0, 5.0 / 6.0, 1.0 / 3.0);
    let k = Matrix2::new(2.0, 0.5, 0.5, 0.5) * G;
    // trace(M^-1 K) = trace(adj(M) K) / det M.
    let trace = (m[(1, 1)] * k[(0, 0)] - 2.0 * m[(0, 1)] * k[(0, 1)] + m[(0, 0)] * k[(1, 1)])
        / m.determinant();
    let det = k.determinant() / m.determinant();
    let disc = (trace * trace / 4.0 - det).sqrt();
    let mu = [trace / 2.0 + disc, trace / 2.0 - disc];
    let mut by_hand: Vec<f64> = mu.iter().flat_map(|m| [m.sqrt(), -m.sqrt()]).collect();
    by_hand.sort_by(f64::total_cmp);
    println!("M = [[8/3, 5/6], [5/6, 1/3]] kg m^2, K = -dg/dq = g [[2, 1/2], [1/2, 1/2]] N m/rad");
    println!(
        "M^-1 K: trace {trace:.6}, determinant {det:.6}; eigenvalues mu = {:.6}, {:.6} 1/s^2",
        mu[0], mu[1]
    );

    let q = upright();
    let (a, _) = arm.linearize(&q, &V2::zeros(), &arm.gravity(&q));
    let eig = a.complex_eigenvalues();
    let largest_imaginary = eig.iter().map(|z| z.im.abs()).fold(0.0, f64::max);
    let mut derived: Vec<f64> = eig.iter().map(|z| z.re).collect();
    derived.sort_by(f64::total_cmp);
    println!("eigenvalues of A (1/s):  by hand +-sqrt(mu)   from linearize   difference");
    let mut worst = largest_imaginary;
    for (h, d) in by_hand.iter().zip(&derived) {
        println!("{:24}{h:>16.12} {d:>16.12} {:>12}", "", sig(d - h, 2));
        worst = worst.max((d - h).abs());
    }
    println!(
        "(largest imaginary part {}); two real unstable modes: upright falls with time constants {:.3} s and {:.3} s",
        sig(largest_imaginary, 2),
        1.0 / by_hand[3],
        1.0 / by_hand[2]
    );
    worst
}

/// Designs the controller for the inputs `drive` (torque = drive * u) and prints its checks.
fn design<const M: usize>(
    arm: &Rods,
    drive: &SMatrix<f64, 2, M>,
    q_cost: &Matrix4<f64>,
    r_cost: &SMatrix<f64, M, M>,
) -> Result<SMatrix<f64, M, 4>, Box<dyn Error>> {
    let q = upright();
    let tau = arm.gravity(&q);
    let (ad, bd) = arm.discretize(&q, &V2::zeros(), &tau, PERIOD);
    let bd = bd * drive;
    let lqr_d = dlqr(&ad, &bd, q_cost, r_cost)?;
    let (k, p) = (lqr_d.gain, lqr_d.cost_to_go);
    // The discrete algebraic Riccati equation at dlqr's P, written out here rather than
    // taken from dlqr's own report.
    let inner = (r_cost + bd.transpose() * p * bd)
        .try_inverse()
        .ok_or("R + Bd^T P Bd is singular")?;
    let riccati = q_cost + ad.transpose() * p * ad
        - ad.transpose() * p * bd * inner * bd.transpose() * p * ad
        - p;
    let residual = riccati.amax() / p.amax();
    println!(
        "dlqr: {} doublings; residual |Q + Ad^T P Ad - Ad^T P Bd (R + Bd^T P Bd)^-1 Bd^T P Ad - P| / |P| = {} (dlqr reports {})",
        lqr_d.iterations,
        sig(residual, 2),
        sig(lqr_d.residual, 2)
    );
    assert!(residual < 1e-12, "Riccati residual too large");
    println!("K (columns q1, q2, qd1, qd2; N m per rad, N m s per rad):");
    for row in k.row_iter() {
        let row: Vec<String> = row.iter().map(|k| format!("{:>9}", fixed(*k, 3))).collect();
        println!("    [{}]", row.join(", "));
    }
    // The continuous-time design from the same linearisation and weights: scaling Q and R
    // together leaves K alone, so the discrete design, whose cost is a sum over 10 ms steps,
    // tends to the continuous one as the period shrinks; its poles s = ln z / dt should be
    // near the continuous poles already.
    let (a, b) = arm.linearize(&q, &V2::zeros(), &tau);
    let lqr_c = lqr(&a, &(b * drive), q_cost, r_cost)?;
    let by_s =
        |x: &Complex<f64>, y: &Complex<f64>| x.re.total_cmp(&y.re).then(x.im.total_cmp(&y.im));
    let mut discrete: Vec<(Complex<f64>, Complex<f64>)> = (ad - bd * k)
        .complex_eigenvalues()
        .iter()
        .map(|z| (z.ln() / PERIOD, *z))
        .collect();
    discrete.sort_by(|x, y| by_s(&x.0, &y.0));
    let mut continuous: Vec<Complex<f64>> = lqr_c.closed_loop_eigenvalues.iter().copied().collect();
    continuous.sort_by(by_s);
    println!(
        "closed-loop eigenvalues z of Ad - Bd K, s = ln z / dt, beside the poles s_c of A - B K_c from lqr (continuous time, same weights):"
    );
    let (mut slowest, mut apart) = (0.0_f64, 0.0_f64);
    for ((s, z), s_c) in discrete.iter().zip(&continuous) {
        println!(
            "    z = {:17}   |z| = {:.6}   s = {} 1/s   s_c = {} 1/s",
            complex(z.re, z.im, 6),
            z.norm(),
            complex(s.re, s.im, 3),
            complex(s_c.re, s_c.im, 3)
        );
        slowest = slowest.max(z.norm());
        apart = apart.max((s - s_c).norm() / s_c.norm());
    }
    assert!(slowest < 1.0, "unstable: a closed-loop |z| = {slowest}");
    println!("all inside the unit circle: largest modulus {slowest:.6}");
    println!(
        "s and s_c differ by at most {:.1}% (the continuous gain K_c differs from K by {:.1}%)",
        100.0 * apart,
        100.0 * (lqr_c.gain - k).amax() / k.amax()
    );
    assert!(
        apart < 0.05,
        "the discrete design is far from the continuous one"
    );
    Ok(k)
}

/// `(qd, qdd)` of the nonlinear arm.
fn rates(arm: &Rods, q: &V2, qd: &V2, tau: &V2) -> (V2, V2) {
    (*qd, arm.forward_dynamics(q, qd, tau))
}

/// One classical Runge-Kutta step with the torque held.
fn rk4(arm: &Rods, q: V2, qd: V2, tau: &V2, h: f64) -> (V2, V2) {
    let (k1q, k1v) = rates(arm, &q, &qd, tau);
    let (k2q, k2v) = rates(arm, &(q + k1q * (h / 2.0)), &(qd + k1v * (h / 2.0)), tau);
    let (k3q, k3v) = rates(arm, &(q + k2q * (h / 2.0)), &(qd + k2v * (h / 2.0)), tau);
    let (k4q, k4v) = rates(arm, &(q + k3q * h), &(qd + k3v * h), tau);
    (
        q + (k1q + k2q * 2.0 + k3q * 2.0 + k4q) * (h / 6.0),
        qd + (k1v + k2v * 2.0 + k3v * 2.0 + k4v) * (h / 6.0),
    )
}

/// A closed-loop run sampled at the control instants.
#[derive(Default)]
struct Run {
    t: Vec<f64>,
    q: Vec<V2>,
    error: Vec<X>,
    tau: Vec<V2>,
}

/// The nonlinear arm under `tau = drive (u* - K (x - x*))`, sampled and held every period.
fn simulate<const M: usize>(
    arm: &Rods,
    k: &SMatrix<f64, M, 4>,
    drive: &SMatrix<f64, 2, M>,
    q0: V2,
) -> Run {
    let u_star = drive.transpose() * arm.gravity(&upright());
    let (mut q, mut qd) = (q0, V2::zeros());
    let mut run = Run::default();
    let h = PERIOD / f64::from(SUBSTEPS);
    for step in 0..=STEPS {
        let x = state_error(&q, &qd);
        let tau = drive * (u_star - k * x);
        run.t.push(f64::from(step) * PERIOD);
        run.q.push(q);
        run.error.push(x);
        run.tau.push(tau);
        for _ in 0..SUBSTEPS {
            (q, qd) = rk4(arm, q, qd, &tau, h);
        }
    }
    run
}

/// Prints a run's summary and fails if it did not come back to upright. Returns the peak
/// torques, the time from which it stays within 0.01 rad, and the final `|x - x*|`.
fn report(run: &Run) -> (V2, f64, f64) {
    let peak = run.tau.iter().fold(V2::zeros(), |m, t| m.sup(&t.abs()));
    let swing = run
        .error
        .iter()
        .fold(V2::zeros(), |m, e| m.sup(&e.fixed_rows::<2>(0).abs()));
    // The end of the last control period with an angle more than 0.01 rad off.
    let settled = run
        .t
        .iter()
        .zip(&run.error)
        .filter(|(_, e)| e.fixed_rows::<2>(0).amax() > 0.01)
        .map(|(t, _)| *t + PERIOD)
        .fold(0.0, f64::max);
    let last = run.error.last().copied().unwrap_or_default();
    println!(
        "largest angle errors {:.4} rad, {:.4} rad; within 0.01 rad of upright from t = {settled:.2} s on",
        swing[0], swing[1]
    );
    println!(
        "peak torques {} N m, {} N m",
        fixed(peak[0], 3),
        fixed(peak[1], 3)
    );
    println!("at t = 5 s: |x - x*| = {}", sig(last.norm(), 3));
    assert!(
        last.norm() < 1e-3,
        "not balanced: |x - x*| = {}",
        sig(last.norm(), 3)
    );
    (peak, settled, last.norm())
}

/// The largest start `q* + d direction` (d to 2 mrad, up to 0.5 rad) from which the
/// controller balances the arm, by bisection (along a ray the region that it catches is an
/// interval in practice), and the largest elbow swing on the way back from there.
fn reach<const M: usize>(
    arm: &Rods,
    k: &SMatrix<f64, M, 4>,
    drive: &SMatrix<f64, 2, M>,
    direction: V2,
) -> (f64, f64) {
    let run = |d: f64| simulate(arm, k, drive, upright() + direction.normalize() * d);
    let balances = |d: f64| run(d).error.last().is_some_and(|e| e.norm() < 1e-3);
    let swing = |d: f64| run(d).error.iter().fold(0.0, |m: f64, e| m.max(e[1].abs()));
    let (mut lo, mut hi) = (0.0, 0.5);
    if balances(hi) {
        return (hi, swing(hi));
    }
    while hi - lo > 0.002 {
        let mid = 0.5 * (lo + hi);
        if balances(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (lo, swing(lo))
}

/// Step 4: the same arm with only the elbow driven, its controllability, how far off upright
/// it can start, and a run from 0.02 rad.
fn acrobot(arm: &Rods, q_cost: &Matrix4<f64>, out: &Out) -> Result<(), Box<dyn Error>> {
    println!("\n== 4. the acrobot: only the elbow driven ==");
    let elbow = SMatrix::<f64, 2, 1>::new(0.0, 1.0);
    let q = upright();
    let (a, b) = arm.linearize(&q, &V2::zeros(), &arm.gravity(&q));
    let b = b * elbow;
    let mut c = Matrix4::zeros();
    let mut column = b;
    for i in 0..4 {
        c.set_column(i, &column);
        column = a * column;
    }
    let sv = c.singular_values();
    let rank = sv.iter().filter(|s| **s > 1e-9 * sv.max()).count();
    println!(
        "controllability matrix [b, Ab, A^2 b, A^3 b] (b: B's elbow column): singular values {:.4?}, rank {rank}",
        sv.as_slice()
    );
    assert_eq!(rank, 4, "the acrobot is not controllable at upright");
    let k = design(arm, &elbow, q_cost, &SMatrix::<f64, 1, 1>::new(1.0))?;

    // The passive shoulder is moved only through the coupling: to bring the centre of mass
    // back over the base the elbow swings far, and past about 1 rad the linear model no
    // longer holds. A start that keeps the centre of mass over the base (dq2 = -4 dq1 to
    // first order, where gravity's torque on the shoulder vanishes) needs little swing.
    println!(
        "largest start from rest that it balances, along three directions (bisection, 2 mrad):"
    );
    for (name, direction) in [
        ("shoulder only, (1, 0)", V2::new(1.0, 0.0)),
        ("elbow only, (0, 1)", V2::new(0.0, 1.0)),
        ("centre of mass over the base, (1, -4)", V2::new(1.0, -4.0)),
    ] {
        let (d, swing) = reach(arm, &k, &elbow, direction);
        let bound = if d >= 0.5 { ">=" } else { "" };
        println!("    {name:38} |dq| {bound}{d:.3} rad, the elbow then swings {swing:.2} rad");
    }
    println!(
        "so 0.05 rad at the shoulder is out of reach: the passive shoulder is moved only by \
         swinging the elbow, and a swing of about a radian leaves the linear model behind"
    );
    let start = V2::new(0.02, 0.0);
    println!(
        "the nonlinear acrobot under it, from q* + ({}, {}) rad at rest:",
        start[0], start[1]
    );
    let acro = simulate(arm, &k, &elbow, upright() + start);
    let (peak, _, last) = report(&acro);
    let file = out.path("balance-acrobot.svg");
    pictures::draw(
        &file,
        arm,
        &acro,
        [
            "The acrobot: the same rods balanced with the elbow motor alone (shoulder passive)",
            &format!(
                "from q* + ({}, {}) rad: the elbow swings {:.2} rad to carry the centre of mass back over the base; peak elbow torque {:.2} N m; |x - x*| = {} at 5 s",
                start[0], start[1], acro.error.iter().map(|e| e[1].abs()).fold(0.0, f64::max), peak[1], sig(last, 1)
            ),
        ],
        ["joint 1 (passive, 0)", "joint 2 (elbow, driven)"],
        &[0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.2, 5.0],
    )?;
    out.wrote(&file);
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    let out = Out::from_args("balance");
    let arm = Rods::default();
    let worst = textbook_check(&arm);
    assert!(
        worst < 1e-9,
        "A differs from the textbook by {}",
        sig(worst, 2)
    );

    println!("\n== 2. LQR with both joints driven ==");
    // Angles weigh ten times the rates; torque costs 1 per (N m)^2.
    let q_cost = Matrix4::from_diagonal(&X::new(10.0, 10.0, 1.0, 1.0));
    let both = Matrix2::identity();
    let k = design(&arm, &both, &q_cost, &Matrix2::identity())?;

    let start = V2::new(0.15, -0.2);
    println!(
        "\n== 3. the nonlinear arm under it, from q* + ({}, {}) rad at rest ==",
        start[0], start[1]
    );
    let run = simulate(&arm, &k, &both, upright() + start);
    let (peak, settled, last) = report(&run);
    let file = out.path("balance-two-link.svg");
    pictures::draw(
        &file,
        &arm,
        &run,
        [
            "Balancing two 1 m, 1 kg rods upright: discrete LQR from the derived linearisation",
            &format!(
                "nonlinear dynamics (RK4, 1 ms) from q* + ({}, {}) rad; both joints driven, 10 ms period; peak torques {:.2} and {:.2} N m; within 0.01 rad after {:.2} s; |x - x*| = {} at 5 s",
                start[0], start[1], peak[0], peak[1], settled, sig(last, 1)
            ),
        ],
        ["joint 1 (shoulder)", "joint 2 (elbow)"],
        &[0.0, 0.1, 0.2, 0.3, 0.4, 0.6, 0.8, 1.0, 1.5, 5.0],
    )?;
    out.wrote(&file);

    acrobot(&arm, &q_cost, &out)
}
