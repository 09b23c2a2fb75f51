//! A spatial arm through the code written over [`Dynamics`]: the derivatives, the
//! linearisation, the simulator's integrators and the controllers, which planar arms use, take
//! the PUMA 560 without a copy. Each result is checked against something independent of it:
//! central differences, conservation of energy, the reference's inverse dynamics.

use planar_arm::nalgebra::{SMatrix, SVector};
use planar_arm::prelude::*;
use planar_arm::reference::spatial as reference;
use planar_arm::sim::{
    from_fn, ComputedTorque, PdGravity, Quintic, Rk4, Simulator, Variational4, VariationalMidpoint,
};

/// PUMA 560, Corke's standard DH parameters and mass properties, with a little armature and
/// friction on the first three joints and a spring on the fourth.
#[derive(SpatialArm, Default)]
#[arm(gravity = (0, 0, -9.81))]
struct Puma560 {
    #[arm(dh(a = 0, alpha = pi/2, d = 0), inertia(yy = 0.35), armature = 0.2, damping = 0.5)]
    waist: Revolute,
    #[arm(dh(a = 0.4318, alpha = 0, d = 0), mass = 17.4, com = (-0.3638, 0.006, 0.2275),
          inertia(xx = 0.13, yy = 0.524, zz = 0.539), armature = 0.2, damping = 0.5)]
    shoulder: Revolute,
    #[arm(dh(a = 0.0203, alpha = -pi/2, d = 0.15005), mass = 4.8, com = (-0.0203, -0.0141, 0.07),
          inertia(xx = 0.066, yy = 0.086, zz = 0.0125), armature = 0.1, frictionloss = 0.3)]
    elbow: Revolute,
    #[arm(dh(a = 0, alpha = pi/2, d = 0.4318), mass = 0.82, com = (0, 0.019, 0),
          inertia(xx = 1.8e-3, yy = 1.3e-3, zz = 1.8e-3), stiffness = 2, springref = 0.5)]
    wrist1: Revolute,
    #[arm(dh(a = 0, alpha = -pi/2, d = 0), mass = 0.34, inertia(xx = 0.3e-3, yy = 0.4e-3, zz = 0.3e-3))]
    wrist2: Revolute,
    #[arm(dh(a = 0, alpha = 0, d = 0), mass = 0.09, com = (0, 0, 0.032),
          inertia(xx = 0.15e-3, yy = 0.15e-3, zz = 0.04e-3))]
    wrist3: Revolute,
}

/// The same arm without friction or spring, for the energy checks.
#[derive(SpatialArm, Default)]
#[arm(gravity = (0, 0, -9.81))]
struct FreePuma {
    #[arm(dh(a = 0, alpha = pi/2, d = 0), inertia(yy = 0.35), armature = 0.2)]
    waist: Revolute,
    #[arm(dh(a = 0.4318, alpha = 0, d = 0), mass = 17.4, com = (-0.3638, 0.006, 0.2275),
          inertia(xx = 0.13, yy = 0.524, zz = 0.539), armature = 0.2)]
    shoulder: Revolute,
    #[arm(dh(a = 0.0203, alpha = -pi/2, d = 0.15005), mass = 4.8, com = (-0.0203, -0.0141, 0.07),
          inertia(xx = 0.066, yy = 0.086, zz = 0.0125), armature = 0.1)]
    elbow: Revolute,
    #[arm(dh(a = 0, alpha = pi/2, d = 0.4318), mass = 0.82, com = (0, 0.019, 0),
          inertia(xx = 1.8e-3, yy = 1.3e-3, zz = 1.8e-3))]
    wrist1: Revolute,
    #[arm(dh(a = 0, alpha = -pi/2, d = 0), mass = 0.34, inertia(xx = 0.3e-3, yy = 0.4e-3, zz = 0.3e-3))]
    wrist2: Revolute,
    #[arm(dh(a = 0, alpha = 0, d = 0), mass = 0.09, com = (0, 0, 0.032),
          inertia(xx = 0.15e-3, yy = 0.15e-3, zz = 0.04e-3))]
    wrist3: Revolute,
}

type V6 = SVector<f64, 6>;

fn state() -> (V6, V6, V6) {
    (
        V6::from([0.3, -0.7, 1.1, 0.2, -0.4, 0.9]),
        V6::from([0.5, -1.0, 0.3, 2.0, -0.2, 1.5]),
        V6::from([1.0, 0.2, -0.8, 0.0, 3.0, -1.0]),
    )
}

/// Central differences of `f` along each coordinate of `x`: column `k` is `df/dx_k`.
fn differences(f: impl Fn(&V6) -> V6, x: &V6, h: f64) -> SMatrix<f64, 6, 6> {
    let mut d = SMatrix::<f64, 6, 6>::zeros();
    for k in 0..6 {
        let (mut up, mut down) = (*x, *x);
        up[k] += h;
        down[k] -= h;
        d.set_column(k, &((f(&up) - f(&down)) / (2.0 * h)));
    }
    d
}

#[test]
fn derivatives_and_linearisation_match_differences() {
    let arm = Puma560::default();
    let (q, qd, qdd) = state();
    let (dq, dqd) = arm.inverse_dynamics_derivatives(&q, &qd, &qdd);
    let fd_q = differences(|x| arm.inverse_dynamics(x, &qd, &qdd), &q, 1e-6);
    let fd_qd = differences(|x| arm.inverse_dynamics(&q, x, &qdd), &qd, 1e-6);
    assert!(
        (dq - fd_q).amax() < 1e-6 * (1.0 + fd_q.amax()),
        "{dq} {fd_q}"
    );
    assert!(
        (dqd - fd_qd).amax() < 1e-6 * (1.0 + fd_qd.amax()),
        "{dqd} {fd_qd}"
    );
    // The emitted program against the same derivatives by run-time jets.
    let (jq, jqd) = planar_arm::Jet::inverse_dynamics_derivatives(&arm, &q, &qd, &qdd);
    assert!((dq - jq).amax() < 1e-12 * (1.0 + jq.amax()));
    assert!((dqd - jqd).amax() < 1e-12 * (1.0 + jqd.amax()));
    let tau = arm.inverse_dynamics(&q, &qd, &qdd);
    let (aq, aqd, atau) = arm.forward_dynamics_derivatives(&q, &qd, &tau);
    let fd = differences(|x| arm.forward_dynamics(x, &qd, &tau), &q, 1e-6);
    assert!((aq - fd).amax() < 1e-5 * (1.0 + fd.amax()), "{aq} {fd}");
    let fd = differences(|x| arm.forward_dynamics(&q, x, &tau), &qd, 1e-6);
    assert!((aqd - fd).amax() < 1e-5 * (1.0 + fd.amax()));
    let m = reference::mass_matrix(&arm.model(), &q);
    assert!((atau * m - SMatrix::<f64, 6, 6>::identity()).amax() < 1e-9);
    // The state-space linearisation: x = (q, qd), dx/dt = (qd, qdd).
    let (a, b) = Linearize::<6, 12>::linearize(&arm, &q, &qd, &tau);
    for i in 0..6 {
        for j in 0..6 {
            assert_eq!(a[(i, j + 6)], f64::from(u8::from(i == j)));
            assert_eq!(a[(i + 6, j)], aq[(i, j)]);
            assert_eq!(b[(i + 6, j)], atau[(i, j)]);
        }
    }
}

/// The energy of a free PUMA swinging under gravity, by RK4 and by the variational
/// integrators (whose `C^T v` comes from the mass matrix in a jet).
#[test]
fn a_free_puma_keeps_its_energy_in_every_integrator() {
    let arm = FreePuma::default();
    let start = V6::from([0.0, -0.5, 0.8, 0.3, 0.6, 0.0]);
    let energy = |q: &V6, qd: &V6| arm.kinetic_energy(q, qd) + arm.potential_energy(q);
    let e0 = energy(&start, &V6::zeros());
    let free = || from_fn(|_, _: &V6, _: &V6| V6::zeros());
    let drift = |states: Vec<planar_arm::sim::State<6>>| {
        states
            .iter()
            .map(|s| (energy(&s.q, &s.qd) - e0).abs())
            .fold(0.0_f64, f64::max)
    };
    let rk4 = Simulator::new(Rk4, 1e-3)
        .and_then(|s| s.run(&arm, start, V6::zeros(), 1.0, free()))
        .and_then(|run| run.into_vec())
        .expect("RK4 runs");
    let midpoint = Simulator::new(VariationalMidpoint::default(), 2e-3)
        .and_then(|s| s.run(&arm, start, V6::zeros(), 1.0, free()))
        .and_then(|run| run.into_vec())
        .expect("the variational midpoint rule runs");
    let fourth = Simulator::new(Variational4::default(), 4e-3)
        .and_then(|s| s.run(&arm, start, V6::zeros(), 1.0, free()))
        .and_then(|run| run.into_vec())
        .expect("the fourth-order variational integrator runs");
    let (d_rk4, d_mid, d_4) = (drift(rk4), drift(midpoint), drift(fourth));
    eprintln!("energy drift over 1 s: RK4 {d_rk4:.1e} J, midpoint {d_mid:.1e} J, fourth {d_4:.1e} J (E0 {e0:.3} J)");
    assert!(d_rk4 < 1e-6, "RK4 {d_rk4:e}");
    // The variational integrators keep energy to their order, without drift.
    assert!(d_mid < 1e-2, "midpoint {d_mid:e}");
    assert!(d_4 < 1e-4, "fourth order {d_4:e}");
}

/// Computed torque tracks a quintic path with the exact model; gravity compensation with PD
/// holds a pose. Both controllers are the planar ones.
#[test]
fn controllers_track_and_hold_a_spatial_arm() {
    let arm = Puma560::default();
    let (from, to) = (
        V6::from([0.0, -0.5, 0.8, 0.0, 0.5, 0.0]),
        V6::from([1.0, -0.2, 0.4, 0.5, -0.3, 1.0]),
    );
    let path = Quintic::rest_to_rest(from, to, 2.0).expect("a path");
    let start = from + V6::repeat(0.02);
    let tracked = Simulator::new(Rk4, 1e-3)
        .and_then(|s| {
            s.run(
                &arm,
                start,
                V6::zeros(),
                2.5,
                ComputedTorque::critically_damped(&arm, path, 20.0),
            )
        })
        .and_then(|run| run.into_vec())
        .expect("computed torque runs");
    let last = tracked.last().expect("states");
    assert!((last.q - to).amax() < 1e-3, "{} vs {to}", last.q);
    // Absolute gains sized to each joint's inertia at the pose, 30 rad/s critically damped:
    // the wrist's inertias are a ten-thousandth of the shoulder's.
    let inertia = arm.mass_matrix(&from).diagonal();
    let (kp, kd) = (inertia * 900.0, inertia * 60.0);
    let hold = Quintic::rest_to_rest(from, from, 1.0).expect("a path");
    let held = Simulator::new(Rk4, 1e-3)
        .and_then(|s| {
            s.run(
                &arm,
                from + V6::repeat(0.05),
                V6::zeros(),
                4.0,
                PdGravity::new(&arm, hold, kp, kd),
            )
        })
        .and_then(|run| run.into_vec())
        .expect("PD with gravity compensation runs");
    let last = held.last().expect("states");
    // Coulomb friction on the elbow leaves a small offset: its 0.3 N m over kp = 900 M_33.
    let offset = 0.3 / kp[2];
    assert!(
        (last.q - from).amax() < 2.0 * offset,
        "{} vs {from}",
        last.q
    );
}

/// An arm holding a payload at a turned, offset tool frame, its mass read at run time.
#[derive(SpatialArm)]
#[arm(tool(xyz = (0, 0, 0.1), rpy = (0, 0, pi/2)), payload = self.load,
      payload_com = (0.05, 0, 0), payload_inertia(xx = 0.01, yy = 0.02, zz = 0.03, xy = 0.004))]
struct Carrying {
    #[arm(dh(a = 0.4, alpha = pi/2), mass = 3, com = (-0.2, 0, 0), inertia(xx = 0.01, yy = 0.05, zz = 0.05))]
    shoulder: Revolute,
    #[arm(dh(a = 0.3), armature = 0.05)]
    elbow: Revolute,
    load: f64,
}

/// The same payload written by hand as the massless forearm's body: a quarter turn about z
/// takes the tool's (0.05, 0, 0) to (0, 0.05, 0) and swaps xx and yy, and turns xy to -xy.
#[derive(SpatialArm, Default)]
#[arm(tool(xyz = (0, 0, 0.1), rpy = (0, 0, pi/2)))]
struct CarryingByHand {
    #[arm(dh(a = 0.4, alpha = pi/2), mass = 3, com = (-0.2, 0, 0), inertia(xx = 0.01, yy = 0.05, zz = 0.05))]
    shoulder: Revolute,
    #[arm(dh(a = 0.3), armature = 0.05, mass = 2, com = (0, 0.05, 0.1),
          inertia(xx = 0.02, yy = 0.01, zz = 0.03, xy = -0.004))]
    elbow: Revolute,
}

#[test]
fn a_payload_is_the_last_link_carrying_it() {
    let arm = Carrying {
        shoulder: Revolute,
        elbow: Revolute,
        load: 2.0,
    };
    let hand = CarryingByHand::default();
    let model = arm.model();
    let mut worst: f64 = 0.0;
    let mut gap = |a: f64, b: f64| worst = worst.max((a - b).abs());
    for k in 0..20 {
        let t = f64::from(k);
        let q = SVector::<f64, 2>::new((0.7 * t).sin() * 2.0, (1.3 * t).cos() * 2.5);
        let qd = SVector::<f64, 2>::new((0.4 * t).cos() * 3.0, (2.1 * t).sin() * 1.5);
        let qdd = SVector::<f64, 2>::new(t * 0.3 - 2.0, 1.0 - 0.2 * t);
        let pairs = [
            (
                arm.mass_matrix(&q).as_slice().to_vec(),
                hand.mass_matrix(&q).as_slice().to_vec(),
            ),
            (
                arm.coriolis(&q, &qd).as_slice().to_vec(),
                hand.coriolis(&q, &qd).as_slice().to_vec(),
            ),
            (
                arm.gravity(&q).as_slice().to_vec(),
                hand.gravity(&q).as_slice().to_vec(),
            ),
            (
                arm.inverse_dynamics(&q, &qd, &qdd).as_slice().to_vec(),
                hand.inverse_dynamics(&q, &qd, &qdd).as_slice().to_vec(),
            ),
            (
                arm.mass_matrix_and_bias(&q, &qd).1.as_slice().to_vec(),
                reference::bias_forces(&model, &q, &qd).as_slice().to_vec(),
            ),
            (
                arm.inverse_dynamics(&q, &qd, &qdd).as_slice().to_vec(),
                reference::inverse_dynamics(&model, &q, &qd, &qdd)
                    .as_slice()
                    .to_vec(),
            ),
        ];
        for (a, b) in pairs {
            for (x, y) in a.iter().zip(&b) {
                gap(*x, *y);
            }
        }
        gap(arm.kinetic_energy(&q, &qd), hand.kinetic_energy(&q, &qd));
        gap(arm.potential_energy(&q), hand.potential_energy(&q));
    }
    assert!(worst < 1e-12, "worst gap {worst:e}");
    // A payload of no mass keeps its tensor: the elbow then turns the armature and the
    // payload's zz about a parallel axis, and holds no weight.
    let empty = Carrying { load: 0.0, ..arm };
    let q = SVector::<f64, 2>::new(0.3, -1.2);
    assert!(empty.gravity(&q)[1].abs() < 1e-15);
    assert!((empty.mass_matrix(&q)[(1, 1)] - (0.05 + 0.03)).abs() < 1e-15);
}

/// `FreePuma` in modified Denavit-Hartenberg parameters: link i's frame sits on joint i's axis,
/// `Tx(a_i) Rx(alpha_i)` before the standard one, so each centre of mass `c` becomes
/// `Rx(alpha_i) c + (a_i, 0, 0)` and each tensor `Rx I Rx^T` (a quarter turn about x swaps
/// the diagonal tensors' yy and zz).
#[derive(SpatialArm, Default)]
#[arm(gravity = (0, 0, -9.81))]
struct FreePumaMdh {
    #[arm(mdh(a = 0, alpha = 0, d = 0), inertia(zz = 0.35), armature = 0.2)]
    waist: Revolute,
    #[arm(mdh(a = 0, alpha = pi/2, d = 0), mass = 17.4, com = (0.068, 0.006, 0.2275),
          inertia(xx = 0.13, yy = 0.524, zz = 0.539), armature = 0.2)]
    shoulder: Revolute,
    #[arm(mdh(a = 0.4318, alpha = 0, d = 0.15005), mass = 4.8, com = (0, 0.07, 0.0141),
          inertia(xx = 0.066, yy = 0.0125, zz = 0.086), armature = 0.1)]
    elbow: Revolute,
    #[arm(mdh(a = 0.0203, alpha = -pi/2, d = 0.4318), mass = 0.82, com = (0, 0, 0.019),
          inertia(xx = 1.8e-3, yy = 1.8e-3, zz = 1.3e-3))]
    wrist1: Revolute,
    #[arm(mdh(a = 0, alpha = pi/2, d = 0), mass = 0.34, inertia(xx = 0.3e-3, yy = 0.3e-3, zz = 0.4e-3))]
    wrist2: Revolute,
    #[arm(mdh(a = 0, alpha = -pi/2, d = 0), mass = 0.09, com = (0, 0, 0.032),
          inertia(xx = 0.15e-3, yy = 0.15e-3, zz = 0.04e-3))]
    wrist3: Revolute,
}

/// The same as URDF joints: `Rx(alpha) Tx(a) Tz(d) = T(a, -d sin alpha, d cos alpha) Rx(alpha)`,
/// so each child frame is the modified parameters' link frame and keeps its mass properties.
#[derive(SpatialArm, Default)]
#[arm(gravity = (0, 0, -9.81))]
struct FreePumaUrdf {
    #[arm(origin(xyz = (0, 0, 0)), inertia(zz = 0.35), armature = 0.2)]
    waist: Revolute,
    #[arm(origin(rpy = (pi/2, 0, 0)), mass = 17.4, com = (0.068, 0.006, 0.2275),
          inertia(xx = 0.13, yy = 0.524, zz = 0.539), armature = 0.2)]
    shoulder: Revolute,
    #[arm(origin(xyz = (0.4318, 0, 0.15005)), mass = 4.8, com = (0, 0.07, 0.0141),
          inertia(xx = 0.066, yy = 0.0125, zz = 0.086), armature = 0.1)]
    elbow: Revolute,
    #[arm(origin(xyz = (0.0203, 0.4318, 0), rpy = (-pi/2, 0, 0)), mass = 0.82, com = (0, 0, 0.019),
          inertia(xx = 1.8e-3, yy = 1.8e-3, zz = 1.3e-3))]
    wrist1: Revolute,
    #[arm(origin(rpy = (pi/2, 0, 0)), mass = 0.34, inertia(xx = 0.3e-3, yy = 0.3e-3, zz = 0.4e-3))]
    wrist2: Revolute,
    #[arm(origin(rpy = (-pi/2, 0, 0)), mass = 0.09, com = (0, 0, 0.032),
          inertia(xx = 0.15e-3, yy = 0.15e-3, zz = 0.04e-3))]
    wrist3: Revolute,
}

#[test]
fn the_three_conventions_give_one_pumas_dynamics() {
    let (dh, mdh, urdf) = (
        FreePuma::default(),
        FreePumaMdh::default(),
        FreePumaUrdf::default(),
    );
    let mut worst: f64 = 0.0;
    for k in 0..20 {
        let t = f64::from(k);
        let q = V6::from_fn(|i, _| (0.7 * t + i as f64).sin() * 2.5);
        let qd = V6::from_fn(|i, _| (1.3 * t - i as f64).cos() * 2.0);
        let qdd = V6::from_fn(|i, _| (0.4 * t * (i as f64 + 1.0)).sin() * 3.0);
        let reference = [
            dh.mass_matrix(&q).as_slice().to_vec(),
            dh.coriolis(&q, &qd).as_slice().to_vec(),
            dh.gravity(&q).as_slice().to_vec(),
            dh.inverse_dynamics(&q, &qd, &qdd).as_slice().to_vec(),
        ];
        let others = [
            [
                mdh.mass_matrix(&q).as_slice().to_vec(),
                mdh.coriolis(&q, &qd).as_slice().to_vec(),
                mdh.gravity(&q).as_slice().to_vec(),
                mdh.inverse_dynamics(&q, &qd, &qdd).as_slice().to_vec(),
            ],
            [
                urdf.mass_matrix(&q).as_slice().to_vec(),
                urdf.coriolis(&q, &qd).as_slice().to_vec(),
                urdf.gravity(&q).as_slice().to_vec(),
                urdf.inverse_dynamics(&q, &qd, &qdd).as_slice().to_vec(),
            ],
        ];
        for other in &others {
            for (a, b) in reference.iter().zip(other) {
                let scale = a.iter().fold(1.0_f64, |m, x| m.max(x.abs()));
                for (x, y) in a.iter().zip(b) {
                    worst = worst.max((x - y).abs() / scale);
                }
            }
        }
    }
    assert!(worst < 1e-12, "the conventions differ by {worst:e}");
    // The same base parameters, found from each convention's own regressor: the groupings
    // differ with the frames, the count does not.
    assert_eq!(
        FreePuma::base_parameter_names().len(),
        FreePumaMdh::base_parameter_names().len()
    );
    assert_eq!(
        FreePumaMdh::base_parameter_names(),
        FreePumaUrdf::base_parameter_names()
    );
}

/// A pan-tilt head: a turn about the vertical, a tilt about a horizontal axis, a point mass
/// `m = 2` at `l = 1/2` along the tilted arm: `p = l (cos q1 cos q2, sin q1 cos q2, sin q2)`.
#[derive(SpatialArm, Default)]
#[arm(gravity = (0, 0, -9.81))]
struct PanTilt {
    #[arm(dh(a = 0, alpha = pi/2, d = 0))]
    pan: Revolute,
    #[arm(dh(a = 0.5, alpha = 0, d = 0), mass = 2)]
    tilt: Revolute,
}

#[test]
fn a_small_arms_mass_matrix_and_coriolis_forces_are_multiplied_out_exactly() {
    use planar_arm::exact::eval;
    let expansion = PanTilt::EXACT
        .expansion
        .expect("two right-angle joints multiply out");
    let (m, c) = (
        expansion.mass_matrix.expect("M is small"),
        expansion.coriolis.expect("c is small"),
    );
    // By hand: T = m l^2 (cos^2 q2 qd1^2 + qd2^2) / 2, so M = diag(m l^2 cos^2 q2, m l^2),
    // c1 = -2 m l^2 sin q2 cos q2 qd1 qd2, c2 = m l^2 sin q2 cos q2 qd1^2.
    let ml2 = 2.0 * 0.25;
    for k in 0..10 {
        let t = f64::from(k);
        let (q, qd) = (
            [0.3 * t, (0.7 * t).sin() * 1.4],
            [1.0 - 0.3 * t, (1.1 * t).cos()],
        );
        let (s2, c2) = q[1].sin_cos();
        let want_m = [[ml2 * c2 * c2, 0.0], [0.0, ml2]];
        let want_c = [
            -2.0 * ml2 * s2 * c2 * qd[0] * qd[1],
            ml2 * s2 * c2 * qd[0] * qd[0],
        ];
        for i in 0..2 {
            for j in 0..2 {
                assert!((eval(m[i][j], &q, &[]) - want_m[i][j]).abs() < 1e-15);
            }
            assert!((eval(c[i], &q, &qd) - want_c[i]).abs() < 1e-14);
        }
    }
    // Exact rational coefficients: M11 = 1/4 + 1/4 cos(2 q2).
    let text = PanTilt::EXACT.to_string();
    for line in [
        "M11 = 1/4 + 1/4 cos(2 q2)",
        "M22 = 1/2",
        "c1 = -1/2 sin(2 q2) qd1 qd2",
        "c2 = 1/4 sin(2 q2) qd1^2",
    ] {
        assert!(text.lines().any(|l| l == line), "{line} not in\n{text}");
    }
}

/// The PUMA 560 with `exact_dynamics`: its M and c multiplied out for `EXACT`, past the budget
/// that keeps other arms' builds quick.
#[derive(SpatialArm, Default)]
#[arm(gravity = (0, 0, -9.81), exact_dynamics)]
struct ExactPuma {
    #[arm(dh(a = 0, alpha = pi/2, d = 0), inertia(yy = 0.35), armature = 0.2)]
    waist: Revolute,
    #[arm(dh(a = 0.4318, alpha = 0, d = 0), mass = 17.4, com = (-0.3638, 0.006, 0.2275),
          inertia(xx = 0.13, yy = 0.524, zz = 0.539))]
    shoulder: Revolute,
    #[arm(dh(a = 0.0203, alpha = -pi/2, d = 0.15005), mass = 4.8, com = (-0.0203, -0.0141, 0.07),
          inertia(xx = 0.066, yy = 0.086, zz = 0.0125))]
    elbow: Revolute,
    #[arm(dh(a = 0, alpha = pi/2, d = 0.4318), mass = 0.82, com = (0, 0.019, 0),
          inertia(xx = 1.8e-3, yy = 1.3e-3, zz = 1.8e-3))]
    wrist1: Revolute,
    #[arm(dh(a = 0, alpha = -pi/2, d = 0), mass = 0.34, inertia(xx = 0.3e-3, yy = 0.4e-3, zz = 0.3e-3))]
    wrist2: Revolute,
    #[arm(dh(a = 0, alpha = 0, d = 0), mass = 0.09, com = (0, 0, 0.032),
          inertia(xx = 0.15e-3, yy = 0.15e-3, zz = 0.04e-3))]
    wrist3: Revolute,
}

#[test]
fn exact_dynamics_multiplies_the_pumas_mass_matrix_and_coriolis_forces_out() {
    use planar_arm::exact::eval;
    // Without the key the PUMA keeps the product form (its velocities pass the budget).
    let plain = Puma560::EXACT
        .expansion
        .expect("the PUMA's kinematics multiplies out");
    assert!(plain.mass_matrix.is_none() && plain.coriolis.is_none());
    let expansion = ExactPuma::EXACT
        .expansion
        .expect("the PUMA's kinematics multiplies out");
    let (m, c) = (
        expansion.mass_matrix.expect("asked for"),
        expansion.coriolis.expect("asked for"),
    );
    let arm = ExactPuma::default();
    let model = arm.model();
    let mut worst = (0.0_f64, 0.0_f64);
    for k in 0..20 {
        let t = f64::from(k);
        let q = SVector::<f64, 6>::from_fn(|i, _| (1.7 * t + 0.9 * i as f64).sin() * 3.0);
        let qd = SVector::<f64, 6>::from_fn(|i, _| (0.6 * t - 1.3 * i as f64).cos() * 2.0);
        // Independent of the expansion: the reference's Jacobian mass matrix and its
        // Newton-Euler velocity terms.
        let want_m = reference::mass_matrix(&model, &q);
        let want_c = reference::coriolis(&model, &q, &qd);
        let (qs, qds) = (q.as_slice(), qd.as_slice());
        for i in 0..6 {
            for j in 0..6 {
                let got = eval(m[i][j], qs, &[]);
                worst.0 = worst.0.max((got - want_m[(i, j)]).abs() / want_m.amax());
            }
            let got = eval(c[i], qs, qds);
            worst.1 = worst
                .1
                .max((got - want_c[i]).abs() / want_c.amax().max(1.0));
        }
    }
    eprintln!(
        "EXACT against the reference: M {:.1e}, c {:.1e}",
        worst.0, worst.1
    );
    assert!(worst.0 < 1e-12 && worst.1 < 1e-12, "{worst:?}");
    // Rational coefficients where the geometry is rational: the text names no constant.
    let text = ExactPuma::EXACT.to_string();
    let m11 = text.lines().find(|l| l.starts_with("M11 = ")).expect("M11");
    assert!(m11.contains("cos(2 q2)") && !m11.contains('e'), "{m11}");
}

/// A spatial arm with run-time masses, a centre and a payload, as a controller holds it.
#[derive(SpatialArm)]
#[arm(gravity = (0, 0, -9.81), tool(xyz = (0, 0, 0.1)), payload = self.load)]
struct Adjustable {
    #[arm(dh(a = 0, alpha = pi/2, d = 0.3), inertia(zz = 0.2), armature = 0.1)]
    base: Revolute,
    #[arm(dh(a = 0.4, alpha = 0), mass = self.m2, com = (self.c2, 0, 0.02),
          inertia(xx = 0.01, yy = 0.05, zz = 0.05))]
    upper: Revolute,
    #[arm(dh(a = 0.3, alpha = 0), mass = 1.2, com = (-0.1, 0, 0), inertia(xx = 0.004, yy = 0.02, zz = 0.02))]
    fore: Revolute,
    m2: f64,
    c2: f64,
    load: f64,
}

#[test]
fn a_frozen_spatial_arm_gives_its_own_numbers() {
    let arm = Adjustable {
        base: Revolute,
        upper: Revolute,
        fore: Revolute,
        m2: 3.5,
        c2: -0.2,
        load: 0.8,
    };
    let frozen = arm.freeze();
    let model = arm.model();
    let mut worst: f64 = 0.0;
    for k in 0..20 {
        let t = f64::from(k);
        let q = SVector::<f64, 3>::new((0.3 * t).sin() * 2.0, (0.7 * t).cos(), 0.2 * t - 1.0);
        let qd = SVector::<f64, 3>::new((1.1 * t).cos(), -(0.5 * t).sin(), 0.4);
        let qdd = SVector::<f64, 3>::new(1.0, -0.5 * t, (0.2 * t).sin());
        let tau = frozen.inverse_dynamics(&q, &qd, &qdd);
        let (m, h) = frozen.mass_matrix_and_bias(&q, &qd);
        let pairs = [
            (tau, reference::inverse_dynamics(&model, &q, &qd, &qdd)),
            (h, reference::bias_forces(&model, &q, &qd)),
            (frozen.bias(&q, &qd), arm.bias(&q, &qd)),
            (frozen.forward_dynamics(&q, &qd, &tau), qdd),
            (m * qdd + h, tau),
        ];
        for (a, b) in pairs {
            worst = worst.max((a - b).amax() / b.amax().max(1.0));
        }
        worst = worst.max((frozen.mass_matrix(&q) - reference::mass_matrix(&model, &q)).amax());
    }
    assert!(worst < 1e-12, "frozen views differ by {worst:e}");
}
