//! `lqr` and `dlqr` on the two-link arm of `examples/balance.rs`: the cost-to-go against the
//! simulated cost of the return, and the gain against the value iteration the example used
//! before it called `dlqr`.

mod common;

use common::riccati::dare_residual;
use planar_arm::nalgebra::{Matrix1, Matrix2, Matrix4, SMatrix, Vector2, Vector4};
use planar_arm::prelude::*;
use planar_arm::{dlqr, lqr};

/// The paper's two equal links: uniform rods, 1 m and 1 kg, as in `examples/balance.rs`.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct Rods {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 1, mass = 1)]
    fore: Revolute,
}

/// The rods' linearisation upright, holding still.
fn upright() -> (Matrix4<f64>, SMatrix<f64, 4, 2>) {
    let arm = Rods::default();
    let q = Vector2::new(std::f64::consts::FRAC_PI_2, 0.0);
    arm.linearize(&q, &Vector2::zeros(), &arm.gravity(&q))
}

#[test]
fn the_cost_to_go_is_the_cost_of_the_simulated_return() {
    // The infinite-horizon cost from x0 by running the closed loop, against x0^T P x0.
    let (a, b) = upright();
    let q = Matrix4::from_diagonal(&Vector4::new(10.0, 10.0, 1.0, 1.0));
    let r = Matrix2::new(1.0, 0.2, 0.2, 0.5);
    let x0 = Vector4::new(0.1, -0.05, 0.2, 0.0);

    // Continuous: RK4 on (x, cost) with xd = (A - B K) x, costd = x^T (Q + K^T R K) x, 1 ms
    // steps for 20 s (the slowest pole is near -2, so what is left is below 1e-30).
    let c = lqr(&a, &b, &q, &r).unwrap();
    let ac = a - b * c.gain;
    let weight = q + c.gain.transpose() * r * c.gain;
    let rate = |x: &Vector4<f64>| (ac * x, (x.transpose() * weight * x)[0]);
    let (mut x, mut cost, h) = (x0, 0.0, 1e-3);
    for _ in 0..20_000 {
        let (k1, j1) = rate(&x);
        let (k2, j2) = rate(&(x + k1 * (h / 2.0)));
        let (k3, j3) = rate(&(x + k2 * (h / 2.0)));
        let (k4, j4) = rate(&(x + k3 * h));
        x += (k1 + k2 * 2.0 + k3 * 2.0 + k4) * (h / 6.0);
        cost += (j1 + 2.0 * j2 + 2.0 * j3 + j4) * (h / 6.0);
    }
    let predicted = (x0.transpose() * c.cost_to_go * x0)[0];
    println!("continuous: simulated {cost:.15}, x0^T P x0 {predicted:.15}");
    assert!(
        (cost - predicted).abs() < 1e-10 * predicted,
        "{cost} vs {predicted}"
    );

    // Discrete: the sum over 10 ms steps of the held-input pair, 3000 steps (30 s).
    let arm = Rods::default();
    let up = Vector2::new(std::f64::consts::FRAC_PI_2, 0.0);
    let (ad, bd) = arm.discretize(&up, &Vector2::zeros(), &arm.gravity(&up), 0.01);
    let d = dlqr(&ad, &bd, &q, &r).unwrap();
    let (mut x, mut cost) = (x0, 0.0);
    for _ in 0..3000 {
        let u = -d.gain * x;
        cost += (x.transpose() * q * x + u.transpose() * r * u)[0];
        x = ad * x + bd * u;
    }
    let predicted = (x0.transpose() * d.cost_to_go * x0)[0];
    println!("discrete: summed {cost:.15}, x0^T P x0 {predicted:.15}");
    assert!(
        (cost - predicted).abs() < 1e-12 * predicted,
        "{cost} vs {predicted}"
    );
}

/// The value iteration `examples/balance.rs` used before `dlqr`,
/// `P <- Q + Ad^T P (Ad - Bd K(P))` from `P = Q`, here run far past convergence: 3000 steps,
/// where the error shrinks by the slowest closed-loop `|z|^2`, about 0.95, per step. (The
/// example stopped at a change of 1e-13, after 606 and 684 steps.) Returns `K` and `P`.
fn value_iteration<const M: usize>(
    ad: &Matrix4<f64>,
    bd: &SMatrix<f64, 4, M>,
    q: &Matrix4<f64>,
    r: &SMatrix<f64, M, M>,
) -> (SMatrix<f64, M, 4>, Matrix4<f64>) {
    let gain = |p: &Matrix4<f64>| {
        let s = (r + bd.transpose() * p * bd).cholesky().unwrap();
        s.solve(&(bd.transpose() * p * ad))
    };
    let mut p = *q;
    for _ in 0..3000 {
        let next = q + ad.transpose() * p * (ad - bd * gain(&p));
        p = (next + next.transpose()) * 0.5;
    }
    (gain(&p), p)
}

#[test]
fn dlqr_agrees_with_the_balance_examples_value_iteration() {
    let arm = Rods::default();
    let up = Vector2::new(std::f64::consts::FRAC_PI_2, 0.0);
    let (ad, bd) = arm.discretize(&up, &Vector2::zeros(), &arm.gravity(&up), 0.01);
    let q = Matrix4::from_diagonal(&Vector4::new(10.0, 10.0, 1.0, 1.0));
    let elbow = bd * Vector2::new(0.0, 1.0);

    let both = dlqr(&ad, &bd, &q, &Matrix2::identity()).unwrap();
    let acrobot = dlqr(&ad, &elbow, &q, &Matrix1::new(1.0)).unwrap();
    let (k_both, p_both) = value_iteration(&ad, &bd, &q, &Matrix2::identity());
    let (k_acrobot, p_acrobot) = value_iteration(&ad, &elbow, &q, &Matrix1::new(1.0));
    for (name, difference, k, doublings, residuals) in [
        (
            "both joints",
            (both.gain - k_both).amax(),
            k_both.amax(),
            both.iterations,
            [
                dare_residual(&ad, &bd, &q, &Matrix2::identity(), &p_both),
                dare_residual(&ad, &bd, &q, &Matrix2::identity(), &both.cost_to_go),
            ],
        ),
        (
            "acrobot",
            (acrobot.gain - k_acrobot).amax(),
            k_acrobot.amax(),
            acrobot.iterations,
            [
                dare_residual(&ad, &elbow, &q, &Matrix1::new(1.0), &p_acrobot),
                dare_residual(&ad, &elbow, &q, &Matrix1::new(1.0), &acrobot.cost_to_go),
            ],
        ),
    ] {
        println!(
            "{name}: |K| {k:.1}, |K(dlqr) - K(value iteration)| {difference:.1e}; residuals: \
             value iteration {:.1e}, dlqr {:.1e} after {doublings} doublings",
            residuals[0], residuals[1]
        );
        assert!(difference < 1e-9 && residuals[1] < 1e-14);
    }
}
