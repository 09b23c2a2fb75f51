//! The dynamics along trajectories: power balance, and Lagrange's equation by finite
//! differences of the energies.

use super::*;

/// Power balance along a trajectory: `d/dt (T + V) = qd . (tau - f)`. Integrates
/// `qdd = ABA(q, qd, tau)` by classical RK4 from `(q, qd)` and returns the energy change,
/// the work done on the arm by `tau - f` (Simpson's rule on the same grid) and the largest
/// difference between the energy's rate (central differences) and the power, each
/// relative to the energy scale of the run.
fn power_balance<const N: usize>(
    model: &Model<N>,
    tau: &SVector<f64, N>,
    mut q: SVector<f64, N>,
    mut qd: SVector<f64, N>,
) -> (f64, f64, f64) {
    let energy = |q: &SVector<f64, N>, qd: &SVector<f64, N>| {
        kinetic_energy(model, q, qd) + potential_energy(model, q)
    };
    let power = |qd: &SVector<f64, N>| qd.dot(&(tau - friction(model, qd)));
    let accel = |q: &SVector<f64, N>, qd: &SVector<f64, N>| forward_dynamics(model, q, qd, tau);
    let (dt, steps) = (2.5e-4, 800);
    let (mut energies, mut powers) = (vec![energy(&q, &qd)], vec![power(&qd)]);
    for _ in 0..steps {
        let k1 = (qd, accel(&q, &qd));
        let (q2, v2) = (q + k1.0 * (dt / 2.0), qd + k1.1 * (dt / 2.0));
        let k2 = (v2, accel(&q2, &v2));
        let (q3, v3) = (q + k2.0 * (dt / 2.0), qd + k2.1 * (dt / 2.0));
        let k3 = (v3, accel(&q3, &v3));
        let (q4, v4) = (q + k3.0 * dt, qd + k3.1 * dt);
        let k4 = (v4, accel(&q4, &v4));
        q += (k1.0 + k2.0 * 2.0 + k3.0 * 2.0 + k4.0) * (dt / 6.0);
        qd += (k1.1 + k2.1 * 2.0 + k3.1 * 2.0 + k4.1) * (dt / 6.0);
        energies.push(energy(&q, &qd));
        powers.push(power(&qd));
    }
    let work: f64 = powers
        .iter()
        .enumerate()
        .map(|(k, p)| {
            let weight = if k == 0 || k == steps {
                1.0
            } else if k % 2 == 1 {
                4.0
            } else {
                2.0
            };
            weight * p
        })
        .sum::<f64>()
        * (dt / 3.0);
    // Fourth-order central differences: truncation O(dt^4), like the integrator's.
    let rate_error = (2..steps - 1)
        .map(|k| {
            let rate = (energies[k - 2] - 8.0 * energies[k - 1] + 8.0 * energies[k + 1]
                - energies[k + 2])
                / (12.0 * dt);
            (rate - powers[k]).abs()
        })
        .fold(0.0, f64::max);
    let scale = energies
        .iter()
        .chain(powers.iter())
        .fold(1.0_f64, |m, e| m.max(e.abs()));
    (
        (energies[steps] - energies[0]) / scale,
        work / scale,
        rate_error / scale,
    )
}

fn power_balance_check<const N: usize>(rng: &mut Rng, mixed: bool, worst: &mut Worst) {
    let mut model: Model<N> = if mixed {
        rng.mixed_model()
    } else {
        rng.model()
    };
    for link in &mut model.links {
        // Coulomb friction switches at qd_i = 0, which RK4 does not resolve; the law is
        // checked on its own in `friction_law`.
        link.frictionloss = 0.0;
        link.damping = rng.uniform(0.1, 2.0);
    }
    let (q, qd) = (rng.configuration(&model, 3.0), rng.vector::<N>(2.0));

    // Unforced: the energy only decreases, by exactly the damping's dissipation.
    let (change, work, rate) = power_balance(&model, &SVector::zeros(), q, qd);
    assert!(change < 0.0, "a damped free arm loses energy: {change}");
    assert!(
        (change - work).abs() < 1e-10 && rate < 1e-8,
        "N = {N}: dE {change:e} vs -sum B qd^2 dt {work:e}; rate error {rate:e}"
    );
    worst.note("free: energy change - work", (change - work).abs());
    worst.note("free: dE/dt - power", rate);
    // Driven: the motors' work less the dissipation.
    let tau = rng.vector::<N>(10.0);
    let (change, work, rate) = power_balance(&model, &tau, q, qd);
    assert!(
        (change - work).abs() < 1e-10 && rate < 1e-8,
        "N = {N}: dE {change:e} vs work {work:e}; rate error {rate:e}"
    );
    worst.note("driven: energy change - work", (change - work).abs());
    worst.note("driven: dE/dt - power", rate);
}

#[test]
fn power_balance_along_trajectories() {
    let mut rng = Rng(7);
    let mut worst = Worst::default();
    for _ in 0..5 {
        power_balance_check::<1>(&mut rng, false, &mut worst);
        power_balance_check::<2>(&mut rng, false, &mut worst);
        power_balance_check::<3>(&mut rng, false, &mut worst);
        power_balance_check::<5>(&mut rng, false, &mut worst);
    }
    worst.print("power_balance_along_trajectories");
}

#[test]
fn power_balance_with_mixed_joints() {
    let mut rng = Rng(17);
    let mut worst = Worst::default();
    for _ in 0..5 {
        power_balance_check::<1>(&mut rng, true, &mut worst);
        power_balance_check::<2>(&mut rng, true, &mut worst);
        power_balance_check::<3>(&mut rng, true, &mut worst);
        power_balance_check::<5>(&mut rng, true, &mut worst);
        power_balance_check::<8>(&mut rng, true, &mut worst);
    }
    worst.print("power_balance_with_mixed_joints");
}

/// Lagrange's equation, `tau_i = d/dt (dT/dqd_i) - dT/dq_i + dV/dq_i + f_i`, for one random arm
/// of mixed joints at a random state, every derivative of the energies by finite differences:
/// the inverse dynamics against the energies alone.
fn lagrange_check<const N: usize>(rng: &mut Rng, worst: &mut Worst) {
    let model: Model<N> = rng.mixed_model();
    let q = rng.configuration(&model, std::f64::consts::PI);
    let qd = rng.vector::<N>(2.0);
    let qdd = rng.vector::<N>(4.0);
    let t = |q: &SVector<f64, N>, qd: &SVector<f64, N>| kinetic_energy(&model, q, qd);
    // T is quadratic in qd: a central difference with a unit step is exact but for rounding.
    let momentum = |q: &SVector<f64, N>, qd: &SVector<f64, N>| {
        SVector::<f64, N>::from_fn(|i, _| {
            let e = basis::<N>(i, 1.0);
            (t(q, &(qd + e)) - t(q, &(qd - e))) / 2.0
        })
    };
    // Truncation (h^4) and rounding (1/h) balance near this step: 2e-11 here, against 5e-9 at
    // h = 2e-3 and 5e-11 at h = 1e-4.
    let h = 5e-4;
    // Along the trajectory through (q, qd) with acceleration qdd.
    let momentum_rate = derivative(
        |s| momentum(&(q + qd * s + qdd * (s * s / 2.0)), &(qd + qdd * s)),
        h,
    );
    let along = |j: usize| move |s: f64| q + basis::<N>(j, s);
    let d_dq = |energy: &dyn Fn(&SVector<f64, N>) -> f64| {
        SVector::<f64, N>::from_fn(|j, _| {
            derivative(|s| SVector::<f64, 1>::new(energy(&along(j)(s))), h)[0]
        })
    };
    let dt_dq = d_dq(&|q| t(q, &qd));
    let dv_dq = d_dq(&|q| potential_energy(&model, q));
    let lagrange = momentum_rate - dt_dq + dv_dq + friction(&model, &qd);
    worst.close(
        &inverse_dynamics(&model, &q, &qd, &qdd),
        &lagrange,
        1e-9,
        "RNEA = Lagrange's equation",
    );
}

#[test]
fn lagrange_equation_by_finite_differences() {
    let mut rng = Rng(18);
    let mut worst = Worst::default();
    for _ in 0..100 {
        lagrange_check::<1>(&mut rng, &mut worst);
        lagrange_check::<2>(&mut rng, &mut worst);
        lagrange_check::<3>(&mut rng, &mut worst);
        lagrange_check::<4>(&mut rng, &mut worst);
        lagrange_check::<5>(&mut rng, &mut worst);
        lagrange_check::<6>(&mut rng, &mut worst);
        lagrange_check::<7>(&mut rng, &mut worst);
        lagrange_check::<8>(&mut rng, &mut worst);
    }
    worst.print("lagrange_equation_by_finite_differences");
}
