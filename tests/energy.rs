//! Conservation of energy: a free arm (zero motor torques) swinging under gravity keeps
//! T + V constant. Integrated with classical RK4 on the generated forward dynamics; the
//! drift must shrink like dt^4 when the step is halved, which a wrong Coriolis or gravity term
//! would break (the energy then drifts at first order, whatever the step).

use planar_arm::prelude::*;

#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct Paper3 {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 1, mass = 1)]
    fore: Revolute,
    #[arm(length = 1, mass = 1)]
    hand: Revolute,
}

#[derive(PlanarArm, Default)]
#[arm(gravity = 9.80665)]
struct Uneven5 {
    #[arm(length = 0.8, mass = 3, inertia = 0.2, com = 0.3)]
    a: Revolute,
    #[arm(length = 0.6, mass = 2, com = -0.1)]
    b: Revolute,
    #[arm(length = 0.5, mass = 1.5, inertia = 1/50)]
    c: Revolute,
    #[arm(length = 0.3, mass = 1/2, inertia = 0, com = 0.3)]
    d: Revolute,
    #[arm(length = 0.2, mass = 1/4)]
    e: Revolute,
}

fn energy<A: PlanarArm<N>, const N: usize>(
    arm: &A,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
) -> f64 {
    arm.kinetic_energy(q, qd) + arm.potential_energy(q)
}

/// Largest |E(t) - E(0)| over `seconds` of free motion with step `dt`, integrating
/// `qdd = accel(q, qd)` by classical RK4.
fn drift_with<A: PlanarArm<N>, const N: usize>(
    arm: &A,
    accel: impl Fn(&SVector<f64, N>, &SVector<f64, N>) -> SVector<f64, N>,
    q0: SVector<f64, N>,
    dt: f64,
    seconds: f64,
) -> f64 {
    let f = |q: &SVector<f64, N>, qd: &SVector<f64, N>| (*qd, accel(q, qd));
    let (mut q, mut qd) = (q0, SVector::<f64, N>::zeros());
    let e0 = energy(arm, &q, &qd);
    let mut worst: f64 = 0.0;
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let steps = (seconds / dt).round() as usize;
    for _ in 0..steps {
        let (k1q, k1v) = f(&q, &qd);
        let (k2q, k2v) = f(&(q + k1q * (dt / 2.0)), &(qd + k1v * (dt / 2.0)));
        let (k3q, k3v) = f(&(q + k2q * (dt / 2.0)), &(qd + k2v * (dt / 2.0)));
        let (k4q, k4v) = f(&(q + k3q * dt), &(qd + k3v * dt));
        q += (k1q + k2q * 2.0 + k3q * 2.0 + k4q) * (dt / 6.0);
        qd += (k1v + k2v * 2.0 + k3v * 2.0 + k4v) * (dt / 6.0);
        worst = worst.max((energy(arm, &q, &qd) - e0).abs());
    }
    worst
}

/// The drift of the free arm, and the energy scale: the largest potential-energy swing.
fn drift<A: PlanarArm<N>, const N: usize>(
    arm: &A,
    q0: SVector<f64, N>,
    dt: f64,
    seconds: f64,
) -> (f64, f64) {
    let zero = SVector::<f64, N>::zeros();
    let worst = drift_with(
        arm,
        |q, qd| arm.forward_dynamics(q, qd, &zero),
        q0,
        dt,
        seconds,
    );
    let model = arm.model();
    let scale: f64 =
        model.links.iter().map(|l| l.mass * l.length).sum::<f64>() * model.gravity.norm();
    (worst, scale)
}

fn check<A: PlanarArm<N>, const N: usize>(arm: &A, q0: SVector<f64, N>, dt: f64) {
    let (coarse, scale) = drift(arm, q0, dt, 2.0);
    let (fine, _) = drift(arm, q0, dt / 2.0, 2.0);
    assert!(
        coarse / scale < 1e-6,
        "relative energy drift {}",
        coarse / scale
    );
    // Fourth order: halving the step divides the drift by about 16.
    assert!(
        fine < coarse / 8.0 || fine / scale < 1e-12,
        "drift {coarse:e} -> {fine:e}: not fourth order"
    );
}

#[test]
fn paper_three_links_conserve_energy() {
    check(
        &Paper3::default(),
        SVector::<f64, 3>::new(0.3, 0.5, -0.4),
        2e-3,
    );
}

#[test]
fn uneven_five_links_conserve_energy() {
    // Short light distal links swing fast: a finer step.
    check(
        &Uneven5::default(),
        SVector::<f64, 5>::new(1.0, -0.5, 0.7, 0.2, -1.2),
        2.5e-4,
    );
}

#[test]
fn a_wrong_coriolis_term_is_caught() {
    // The check above can fail: integrate with the velocity-product torques halved and the
    // energy drifts at first order.
    let arm = Paper3::default();
    let wrong = |q: &SVector<f64, 3>, qd: &SVector<f64, 3>| {
        arm.forward_dynamics(q, qd, &(arm.coriolis(q, qd) * 0.5))
    };
    let worst = drift_with(
        &arm,
        wrong,
        SVector::<f64, 3>::new(0.3, 0.5, -0.4),
        1e-3,
        2.0,
    );
    assert!(
        worst / (3.0 * 9.81) > 1e-3,
        "a wrong model should drift, drift = {worst}"
    );
}
