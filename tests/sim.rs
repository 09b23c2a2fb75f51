//! `planar_arm::sim`: the integrators' orders and energy behaviour, the controllers' tracking
//! with an exact and a wrong model, the trajectories' boundary conditions and continuity, and
//! bad input. That none of it allocates is in `tests/alloc.rs`.

use planar_arm::nalgebra::Vector3;
use planar_arm::prelude::*;
use planar_arm::sim::{
    from_fn, ComputedTorque, Integrator, PdGravity, Quintic, Rk4, Sample, SemiImplicitEuler,
    SimError, Simulator, TipLine, Trajectory, Variational4, VariationalMidpoint, ViaPoints,
};

/// The paper's two rods.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct Rods {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 1, mass = 1)]
    fore: Revolute,
}

/// Two links and a payload at the tip known only at run time.
#[derive(PlanarArm)]
#[arm(gravity = 9.81, payload = self.payload)]
struct Carrier {
    #[arm(length = 0.5, mass = 2)]
    upper: Revolute,
    #[arm(length = 0.4, mass = 1)]
    fore: Revolute,
    payload: f64,
}

/// Three uneven links, for the tip line with a pose target.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct Three {
    #[arm(length = 0.6, mass = 2)]
    a: Revolute,
    #[arm(length = 0.5, mass = 1.5)]
    b: Revolute,
    #[arm(length = 0.2, mass = 0.3)]
    c: Revolute,
}

type V2 = Vector2<f64>;

fn energy<A: PlanarArm<N>, const N: usize>(
    arm: &A,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
) -> f64 {
    arm.kinetic_energy(q, qd) + arm.potential_energy(q)
}

/// A large swing, chaotic: released from 0.3 rad above horizontal with the elbow bent 1 rad.
const CHAOTIC: [f64; 2] = [0.3, 1.0];
/// A swing about hanging down, regular (quasi-periodic).
const REGULAR: [f64; 2] = [-1.0, 0.4];

/// The free rods swinging about hanging down, from rest, after `seconds` with steps `dt`.
fn free_swing<I: Integrator>(integrator: &I, dt: f64, seconds: f64) -> (V2, V2) {
    let arm = Rods::default();
    let (mut q, mut qd) = (V2::from(REGULAR), V2::zeros());
    let steps = (seconds / dt).round() as usize;
    for _ in 0..steps {
        (q, qd) = integrator.step(&arm, &q, &qd, &V2::zeros(), dt).unwrap();
    }
    (q, qd)
}

/// The measured order: log2 of the error ratio when the step is halved, from 0.01 s to 0.005 s
/// and from 0.005 s to 0.0025 s, the error against a fine RK4 solution after 1 s.
fn order<I: Integrator>(integrator: &I) -> [f64; 2] {
    let (qr, vr) = free_swing(&Rk4, 1e-4, 1.0);
    let error = |dt: f64| {
        let (q, qd) = free_swing(integrator, dt, 1.0);
        (q - qr).norm() + (qd - vr).norm()
    };
    let e = [error(0.01), error(0.005), error(0.0025)];
    [(e[0] / e[1]).log2(), (e[1] / e[2]).log2()]
}

#[test]
fn each_integrator_has_its_order() {
    for (name, p, measured) in [
        ("semi-implicit Euler", 1.0, order(&SemiImplicitEuler)),
        ("RK4", 4.0, order(&Rk4)),
        (
            "variational midpoint",
            2.0,
            order(&VariationalMidpoint::default()),
        ),
        ("variational 4", 4.0, order(&Variational4::default())),
    ] {
        for m in measured {
            assert!(
                (m - p).abs() < 0.35,
                "{name}: measured order {m:.3}, expected {p}"
            );
        }
    }
}

/// Largest |E - E0| of the free rods over the first and the second half of `seconds`.
fn energy_error_halves<I: Integrator>(
    integrator: &I,
    start: [f64; 2],
    dt: f64,
    seconds: f64,
) -> [f64; 2] {
    let arm = Rods::default();
    let (mut q, mut qd) = (V2::from(start), V2::zeros());
    let e0 = energy(&arm, &q, &qd);
    let steps = (seconds / dt).round() as usize;
    let mut worst = [0.0_f64; 2];
    for k in 0..steps {
        (q, qd) = integrator.step(&arm, &q, &qd, &V2::zeros(), dt).unwrap();
        let half = usize::from(2 * k >= steps);
        worst[half] = worst[half].max((energy(&arm, &q, &qd) - e0).abs());
    }
    worst
}

#[test]
fn symplectic_integrators_do_not_drift_and_rk4_does() {
    // 20 s at 20 ms: long enough that RK4's drift doubles from the first half to the second.
    let (dt, seconds) = (0.02, 20.0);
    let rk4 = energy_error_halves(&Rk4, REGULAR, dt, seconds);
    assert!(
        rk4[1] > 1.6 * rk4[0],
        "RK4 energy error {rk4:?} did not grow"
    );
    for (name, e) in [
        (
            "midpoint",
            energy_error_halves(&VariationalMidpoint::default(), REGULAR, dt, seconds),
        ),
        (
            "variational 4",
            energy_error_halves(&Variational4::default(), REGULAR, dt, seconds),
        ),
    ] {
        // Bounded: the second half no worse than the first (oscillation, no drift).
        assert!(e[1] < 1.3 * e[0], "{name}: energy error {e:?} grew");
    }
    // And at equal step the fourth-order one is below RK4 by the end.
    let v4 = energy_error_halves(&Variational4::default(), REGULAR, dt, seconds);
    assert!(v4[1] < rk4[1], "variational 4 {v4:?} against RK4 {rk4:?}");
}

#[test]
fn energy_error_shrinks_with_the_order() {
    // The largest energy error over 2 s, dt halved: ratio about 2^p.
    for (name, p, errors) in [
        (
            "RK4",
            4.0,
            [0.02, 0.01].map(|dt| energy_error_halves(&Rk4, CHAOTIC, dt, 2.0)[1]),
        ),
        (
            "midpoint",
            2.0,
            [0.02, 0.01].map(|dt| {
                energy_error_halves(&VariationalMidpoint::default(), CHAOTIC, dt, 2.0)[1]
            }),
        ),
        (
            "variational 4",
            4.0,
            [0.02, 0.01]
                .map(|dt| energy_error_halves(&Variational4::default(), CHAOTIC, dt, 2.0)[1]),
        ),
    ] {
        let measured = (errors[0] / errors[1]).log2();
        assert!(
            (measured - p).abs() < 0.5,
            "{name}: energy order {measured:.2}, {errors:?}"
        );
    }
}

/// The largest tracking error of `run`'s samples against `path`.
fn worst_error<R: Trajectory<2>>(
    states: impl Iterator<Item = Result<planar_arm::sim::State<2>, SimError>>,
    path: &R,
    from: f64,
    to: f64,
) -> f64 {
    let mut worst = 0.0_f64;
    for s in states {
        let s = s.unwrap();
        if (from..=to).contains(&s.t) {
            worst = worst.max((s.q - path.sample(s.t).q).amax());
        }
    }
    worst
}

fn swing() -> Quintic<2> {
    Quintic::rest_to_rest(V2::new(-1.2, 0.3), V2::new(0.6, 1.4), 1.0).unwrap()
}

#[test]
fn computed_torque_error_shrinks_with_the_control_period() {
    let arm = Rods::default();
    let path = swing();
    let errors = [0.02, 0.01, 0.005].map(|period| {
        let sim = Simulator::new(Rk4, 1e-3)
            .unwrap()
            .with_control_period(period)
            .unwrap();
        let ct = ComputedTorque::critically_damped(&arm, path, 20.0);
        let run = sim.run(&arm, path.start().q, V2::zeros(), 1.5, ct).unwrap();
        worst_error(run, &path, 0.0, 1.5)
    });
    // The held torque lags by half a period on average: the error is first order in it.
    for w in errors.windows(2) {
        let ratio = w[0] / w[1];
        assert!((1.6..2.6).contains(&ratio), "errors {errors:?}");
    }
    assert!(errors[2] < 2e-3, "errors {errors:?}");
}

#[test]
fn feedback_keeps_a_payload_error_bounded() {
    // The arm holds 0.3 kg that the model does not know about.
    let real = Carrier {
        upper: Revolute,
        fore: Revolute,
        payload: 0.3,
    };
    let model = Carrier {
        upper: Revolute,
        fore: Revolute,
        payload: 0.0,
    };
    let path = swing();
    let sim = Simulator::new(Rk4, 1e-3)
        .unwrap()
        .with_control_period(5e-3)
        .unwrap();
    let run = |omega: f64, from: f64, to: f64| {
        let ct = ComputedTorque::critically_damped(&model, path, omega);
        worst_error(
            sim.run(&real, path.start().q, V2::zeros(), 3.0, ct)
                .unwrap(),
            &path,
            from,
            to,
        )
    };
    // Dead reckoning alone: the arm sags and falls away, more and more.
    let (open_early, open_late) = (run(0.0, 0.0, 0.25), run(0.0, 0.0, 1.0));
    assert!(
        open_late > 3.0 * open_early && open_late > 0.3,
        "{open_early} {open_late}"
    );
    // With feedback: the error settles to the payload's weight over the stiffness.
    let (closed_motion, closed_hold) = (run(15.0, 0.0, 1.5), run(15.0, 2.0, 3.0));
    // 0.3 kg at the tip nearly doubles the elbow's inertia: the error in motion is large,
    // but bounded, and smaller once the arm holds still.
    assert!(closed_motion < 0.4, "{closed_motion}");
    assert!(
        closed_hold < 0.1 && closed_hold < 0.5 * closed_motion,
        "{closed_motion} {closed_hold}"
    );
    // PD with the model's gravity: bounded too.
    let pd = PdGravity::new(&model, path, V2::new(400.0, 150.0), V2::new(40.0, 12.0));
    let e = worst_error(
        sim.run(&real, path.start().q, V2::zeros(), 3.0, pd)
            .unwrap(),
        &path,
        2.0,
        3.0,
    );
    assert!(e < 0.05, "PD + gravity: {e}");
    // With the exact model the held error is much smaller.
    let exact = PdGravity::new(&real, path, V2::new(400.0, 150.0), V2::new(40.0, 12.0));
    let e_exact = worst_error(
        sim.run(&real, path.start().q, V2::zeros(), 3.0, exact)
            .unwrap(),
        &path,
        2.5,
        3.0,
    );
    assert!(e_exact < 0.1 * e, "exact {e_exact} against wrong {e}");
}

/// Sample values just left and right of `t`, and a central-difference check of the rates.
fn check_continuous<T: Trajectory<N>, const N: usize>(path: &T, t: f64) {
    let h = 1e-7;
    let (a, b) = (path.sample(t - h), path.sample(t + h));
    assert!((a.q - b.q).amax() < 1e-5, "q jumps at {t}");
    assert!((a.qd - b.qd).amax() < 1e-5, "qd jumps at {t}");
    assert!((a.qdd - b.qdd).amax() < 1e-4, "qdd jumps at {t}");
}

/// qd and qdd against central differences of q and qd at `t`.
fn check_rates<T: Trajectory<N>, const N: usize>(path: &T, t: f64, tol: f64) {
    let h = 1e-5;
    let (a, s, b) = (path.sample(t - h), path.sample(t), path.sample(t + h));
    let qd = (b.q - a.q) / (2.0 * h);
    let qdd = (b.qd - a.qd) / (2.0 * h);
    assert!((qd - s.qd).amax() < tol, "qd at {t}: {qd} vs {}", s.qd);
    assert!(
        (qdd - s.qdd).amax() < tol * 10.0,
        "qdd at {t}: {qdd} vs {}",
        s.qdd
    );
}

#[test]
fn quintic_meets_its_boundary_conditions() {
    let start = Sample {
        q: V2::new(0.1, -0.2),
        qd: V2::new(0.5, 0.0),
        qdd: V2::new(-1.0, 2.0),
    };
    let end = Sample {
        q: V2::new(1.0, 0.4),
        qd: V2::new(-0.3, 0.2),
        qdd: V2::new(0.0, -0.5),
    };
    let path = Quintic::new(start, end, 1.7).unwrap();
    let near = |t: f64, s: &Sample<2>| {
        let h = path.sample(t);
        (h.q - s.q)
            .amax()
            .max((h.qd - s.qd).amax())
            .max((h.qdd - s.qdd).amax())
    };
    // Just inside the ends, the polynomial itself (not the clamped end values).
    assert!(near(1e-9, &start) < 1e-7);
    assert!(near(1.7 - 1e-9, &end) < 1e-7);
    for k in 1..17 {
        check_rates(&path, 0.1 * f64::from(k), 1e-6);
    }
}

#[test]
fn via_points_pass_through_and_are_twice_continuous() {
    let times = [0.0, 0.7, 1.5, 2.0, 3.0];
    let points = [
        V2::new(0.0, 0.0),
        V2::new(1.0, 0.5),
        V2::new(1.5, -0.5),
        V2::new(0.5, -0.2),
        V2::new(0.0, 0.3),
    ];
    let path = ViaPoints::new(times, points).unwrap();
    for (t, p) in times.iter().zip(&points) {
        assert!((path.sample(*t).q - p).amax() < 1e-14);
        check_continuous(&path, *t);
    }
    assert_eq!(path.sample(0.0).qd, V2::zeros());
    assert_eq!(path.sample(3.0).qdd, V2::zeros());
    for k in 1..30 {
        check_rates(&path, 0.1 * f64::from(k) + 0.013, 1e-5);
    }
}

#[test]
fn tip_line_stays_on_the_line() {
    fn check<A: PlanarArm<N>, const N: usize>(arm: &A, q0: SVector<f64, N>, to: Point2<f64>) {
        let line = TipLine::new(arm, q0, to, 1.0).unwrap();
        let from = arm.tip_pose(&q0).translation.vector;
        let dir = (to.coords - from).normalize();
        for k in 0..=50 {
            let t = f64::from(k) / 50.0;
            let tip = arm.tip_pose(&line.sample(t).q).translation.vector - from;
            let off_line = tip.x * dir.y - tip.y * dir.x;
            assert!(
                off_line.abs() < 1e-9,
                "N = {N}: {off_line} off the line at {t}"
            );
        }
        let end = arm.tip_pose(&line.sample(1.0).q).translation.vector;
        assert!((end - to.coords).norm() < 1e-10);
        assert_eq!(line.sample(1.0).qd.amax(), 0.0);
        for k in 1..10 {
            check_rates(&line, 0.1 * f64::from(k) + 0.005, 1e-4);
        }
    }
    check(&Rods::default(), V2::new(-0.5, 1.5), Point2::new(0.2, 1.4));
    check(
        &Three::default(),
        Vector3::new(0.2, 1.0, 0.8),
        Point2::new(-0.3, 0.8),
    );
}

#[test]
fn bad_input_is_an_error_not_a_panic() {
    let arm = Rods::default();
    let (q, zero) = (V2::new(0.1, 0.2), V2::zeros());
    for dt in [0.0, -1e-3, f64::NAN, f64::INFINITY] {
        assert!(Simulator::new(Rk4, dt).is_err());
        assert!(Rk4.step(&arm, &q, &zero, &zero, dt).is_err());
        assert!(SemiImplicitEuler.step(&arm, &q, &zero, &zero, dt).is_err());
        assert!(VariationalMidpoint::default()
            .step(&arm, &q, &zero, &zero, dt)
            .is_err());
        assert!(Variational4::default()
            .step(&arm, &q, &zero, &zero, dt)
            .is_err());
    }
    let nan = V2::new(f64::NAN, 0.0);
    assert!(Rk4.step(&arm, &nan, &zero, &zero, 1e-3).is_err());
    assert!(Rk4.step(&arm, &q, &zero, &nan, 1e-3).is_err());
    let sim = Simulator::new(Rk4, 1e-3).unwrap();
    assert!(sim.with_control_period(1.5e-3).is_err());
    assert!(sim.with_control_period(0.0).is_err());
    let free = || from_fn(|_, _: &V2, _: &V2| V2::zeros());
    assert!(sim.run(&arm, q, zero, -1.0, free()).is_err());
    assert!(sim.run(&arm, nan, zero, 1.0, free()).is_err());
    // A controller that returns NaN at 0.25 s stops the run there, with the time.
    let broken = from_fn(|t, _: &V2, _: &V2| if t >= 0.25 { nan } else { V2::zeros() });
    let results: Vec<_> = sim.run(&arm, q, zero, 1.0, broken).unwrap().collect();
    assert_eq!(results.len(), 251);
    match results.last() {
        Some(Err(SimError::NonFinite { argument: "tau", t })) => assert!((t - 0.25).abs() < 1e-12),
        other => panic!("{other:?}"),
    }
    // An implicit step far too large for its iteration says so.
    let huge = VariationalMidpoint::default().step(&arm, &q, &V2::new(50.0, -80.0), &zero, 1.0);
    assert!(
        matches!(huge, Err(SimError::NoConvergence { .. })),
        "{huge:?}"
    );
    assert!(Quintic::rest_to_rest(q, q, f64::NAN).is_err());
    assert!(ViaPoints::new([0.0, f64::NAN], [q, q]).is_err());
    assert!(TipLine::new(&arm, q, Point2::new(f64::NAN, 0.0), 1.0).is_err());
    // Through the base, where the two rods fold onto themselves (q2 = pi, singular).
    let tip = arm.tip_pose(&q).translation.vector;
    let through = TipLine::new(&arm, q, Point2::from(-tip), 1.0);
    assert!(
        matches!(through, Err(SimError::Arm(_))),
        "{:?}",
        through.as_ref().err()
    );
}

/// Two links with viscous and Coulomb friction, for identification from simulated states.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct Geared {
    #[arm(
        length = 0.5,
        mass = 2,
        damping = 0.2,
        frictionloss = 0.1,
        armature = 0.01
    )]
    upper: Revolute,
    #[arm(length = 0.4, mass = 1, damping = 0.2)]
    fore: Revolute,
}

/// The base parameters least squares finds from the states' rows, with each state's
/// acceleration given by `qdd_of`.
fn identified(states: &[planar_arm::sim::State<2>], qdd_of: impl Fn(usize) -> V2) -> Vec<f64> {
    let arm = Geared::default();
    let rows: Vec<_> = (0..states.len())
        .map(|k| arm.base_regressor(&states[k].q, &states[k].qd, &qdd_of(k)))
        .collect();
    let b = rows[0].ncols();
    let w =
        planar_arm::nalgebra::DMatrix::from_fn(2 * rows.len(), b, |r, c| rows[r / 2][(r % 2, c)]);
    let tau =
        planar_arm::nalgebra::DVector::from_fn(2 * rows.len(), |r, _| states[r / 2].tau[r % 2]);
    let x = w.svd(true, true).solve(&tau, 1e-12).unwrap();
    x.iter().copied().collect()
}

#[test]
fn states_carry_their_acceleration_and_identify_exactly() {
    let arm = Geared::default();
    // A swinging reference tracked by PD with gravity compensation: rich enough motion.
    let path = ViaPoints::new(
        [0.0, 1.0, 2.0, 3.0],
        [
            V2::new(-1.0, 0.5),
            V2::new(0.5, -1.0),
            V2::new(1.2, 1.3),
            V2::new(-0.3, 0.2),
        ],
    )
    .unwrap();
    let controller = PdGravity::new(&arm, path, V2::repeat(20.0), V2::repeat(4.0));
    let sim = Simulator::new(Rk4, 1e-3)
        .unwrap()
        .with_control_period(5e-3)
        .unwrap();
    let states = sim
        .run(&arm, path.sample(0.0).q, V2::zeros(), 3.0, controller)
        .unwrap()
        .into_vec()
        .unwrap();
    for s in &states {
        let tau = arm.inverse_dynamics(&s.q, &s.qd, &s.qdd);
        assert!((tau - s.tau).amax() < 1e-9 * (1.0 + s.tau.amax()), "{s:?}");
    }
    let truth: Vec<f64> = arm.base_parameters().iter().copied().collect();
    let names = Geared::base_parameter_names();
    let exact = identified(&states, |k| states[k].qdd);
    for ((x, t), name) in exact.iter().zip(&truth).zip(names) {
        assert!((x - t).abs() < 1e-8 * (1.0 + t.abs()), "{name}: {x} vs {t}");
    }
    // Differencing the sampled rates over a control period biases the estimate: the check
    // above is not one any acceleration would pass.
    let differenced = identified(&states[..states.len() - 1], |k| {
        (states[k + 1].qd - states[k].qd) / 1e-2
    });
    let worst = differenced
        .iter()
        .zip(&truth)
        .map(|(x, t)| (x - t).abs() / (1e-3 + t.abs()))
        .fold(0.0_f64, f64::max);
    assert!(worst > 1e-3, "differenced rates identified within {worst}");
}
