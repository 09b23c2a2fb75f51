//! `inverse_dynamics_derivatives` and `forward_dynamics_derivatives` against central
//! differences of the generated dynamics and of the numeric reference (independent of the
//! derive), on arms with run-time parameters, armature, damping, Coulomb friction and a
//! payload, 1 to 8 links; and the identities between them.

mod common;

#[path = "common/arms.rs"]
mod arms;

use arms::{Eight, Scara};
use common::Rng;
use planar_arm::nalgebra::{SMatrix, SVector};
use planar_arm::prelude::*;
use planar_arm::reference;

#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct One {
    #[arm(length = 0.7, mass = 2, com = (0.3, 0.05), armature = 0.1, damping = 0.2)]
    a: Revolute,
}

/// Three links with run-time masses and a run-time centre of mass, damping, Coulomb friction
/// and a payload: the size at which the expanded formulas still compete with the recursion.
#[derive(PlanarArm, Clone)]
#[arm(gravity = 9.81, payload = self.load)]
struct Three {
    #[arm(length = 0.5, mass = self.m1, com = (0.2, 0.03), armature = 0.05)]
    a: Revolute,
    #[arm(length = 0.4, mass = self.m2, com = self.c2, damping = 0.15)]
    b: Revolute,
    #[arm(length = 0.3, mass = 0.6, frictionloss = 0.2)]
    c: Revolute,
    m1: f64,
    m2: f64,
    c2: f64,
    load: f64,
}

impl Three {
    fn random(rng: &mut Rng) -> Self {
        Self {
            a: Revolute,
            b: Revolute,
            c: Revolute,
            m1: rng.range(0.5, 4.0),
            m2: rng.range(0.5, 3.0),
            c2: rng.range(0.05, 0.35),
            load: rng.range(0.0, 1.5),
        }
    }
}

/// Central differences of `f` along each unit direction, step `h`.
fn central<const N: usize>(
    f: impl Fn(&SVector<f64, N>) -> SVector<f64, N>,
    x: &SVector<f64, N>,
) -> SMatrix<f64, N, N> {
    let h = 1e-6;
    let mut out = SMatrix::<f64, N, N>::zeros();
    for j in 0..N {
        let mut e = SVector::<f64, N>::zeros();
        e[j] = h;
        out.set_column(j, &((f(&(x + e)) - f(&(x - e))) / (2.0 * h)));
    }
    out
}

fn close<const N: usize>(a: &SMatrix<f64, N, N>, b: &SMatrix<f64, N, N>, what: &str) {
    let d = (a - b).amax();
    assert!(
        d <= 1e-6 * (1.0 + b.amax()),
        "{what}: {d:e} (scale {:e})",
        b.amax()
    );
}

fn check<A: PlanarArm<N>, const N: usize>(arm: &A, rng: &mut Rng) {
    let model = arm.model();
    for _ in 0..30 {
        let (q, qdd) = (rng.vector::<N>(3.0), rng.vector::<N>(5.0));
        // Rates away from zero: Coulomb friction jumps there.
        let qd = rng
            .vector::<N>(3.0)
            .map(|w| if w.abs() < 0.05 { w + 0.1 } else { w });
        let (dq, dqd) = arm.inverse_dynamics_derivatives(&q, &qd, &qdd);
        // The emitted derivative program against the same inverse dynamics run in jets:
        // equal to rounding, a far tighter check than the differences below.
        let (jq, jqd) = planar_arm::Jet::inverse_dynamics_derivatives(arm, &q, &qd, &qdd);
        for (got, jet, what) in [(&dq, &jq, "dtau/dq"), (&dqd, &jqd, "dtau/dqd")] {
            let d = (got - jet).amax();
            assert!(d <= 1e-12 * (1.0 + jet.amax()), "{what} vs jets: {d:e}");
        }
        close(
            &dq,
            &central(|x| arm.inverse_dynamics(x, &qd, &qdd), &q),
            "dtau/dq, generated",
        );
        close(
            &dqd,
            &central(|x| arm.inverse_dynamics(&q, x, &qdd), &qd),
            "dtau/dqd, generated",
        );
        let r = |q: &SVector<f64, N>, qd: &SVector<f64, N>| {
            reference::inverse_dynamics(&model, q, qd, &qdd)
        };
        close(&dq, &central(|x| r(x, &qd), &q), "dtau/dq, reference");
        close(&dqd, &central(|x| r(&q, x), &qd), "dtau/dqd, reference");

        let tau = arm.inverse_dynamics(&q, &qd, &qdd);
        let (ddq, ddqd, ddtau) = arm.forward_dynamics_derivatives(&q, &qd, &tau);
        close(
            &ddq,
            &central(|x| arm.forward_dynamics(x, &qd, &tau), &q),
            "dqdd/dq",
        );
        close(
            &ddqd,
            &central(|x| arm.forward_dynamics(&q, x, &tau), &qd),
            "dqdd/dqd",
        );
        close(
            &ddtau,
            &central(|x| arm.forward_dynamics(&q, &qd, x), &tau),
            "dqdd/dtau",
        );
        // The emitted program against the derivatives through jets and a Cholesky inverse of M.
        let minv = arm
            .mass_matrix(&q)
            .cholesky()
            .expect("M is positive definite")
            .inverse();
        let (jq, jqd) = planar_arm::Jet::inverse_dynamics_derivatives(
            arm,
            &q,
            &qd,
            &arm.forward_dynamics(&q, &qd, &tau),
        );
        for (got, want, what) in [
            (&ddq, -(minv * jq), "dqdd/dq vs jets"),
            (&ddqd, -(minv * jqd), "dqdd/dqd vs jets"),
            (&ddtau, minv, "dqdd/dtau vs Cholesky"),
        ] {
            let d = (got - want).amax();
            assert!(d <= 1e-9 * (1.0 + want.amax()), "{what}: {d:e}");
        }
        // The identities: M dqdd/dtau = I and M dqdd/dq = -dtau/dq at qdd = FD(q, qd, tau).
        let m = arm.mass_matrix(&q);
        close(&(m * ddtau), &SMatrix::identity(), "M M^-1");
        close(&(m * ddq), &(-dq), "M dqdd/dq");
        close(&(m * ddqd), &(-dqd), "M dqdd/dqd");
    }
}

#[test]
fn derivatives_match_central_differences_and_the_reference() {
    let mut rng = Rng(0xde71);
    check(&One::default(), &mut rng);
    for _ in 0..3 {
        let scara = Scara::random(&mut rng);
        check(&scara, &mut rng);
        check(&Three::random(&mut rng), &mut rng);
    }
    check(&Eight::default(), &mut rng);
}

#[test]
fn coulomb_friction_contributes_no_rate_derivative_at_rest() {
    // At qd_2 = 0 the jump of frictionloss sign(qd_2) is not differentiated: dtau/dqd is the
    // derivative of everything else (the same arm without Coulomb friction).
    let with = Scara {
        shoulder: Revolute,
        elbow: Revolute,
        m1: 2.0,
        i1: 0.05,
        c1: 0.2,
        f2: 0.4,
        load: 0.5,
    };
    let without = Scara {
        f2: 0.0,
        ..with.clone()
    };
    let (q, qd, qdd) = (
        Vector2::new(0.3, -0.2),
        Vector2::new(0.7, 0.0),
        Vector2::new(1.0, 2.0),
    );
    let (a, b) = (
        with.inverse_dynamics_derivatives(&q, &qd, &qdd),
        without.inverse_dynamics_derivatives(&q, &qd, &qdd),
    );
    assert_eq!(a, b);
    assert!(a.1.iter().all(|x| x.is_finite()));
}

#[test]
fn bad_input_gives_nan_not_a_panic() {
    let arm = Eight::default();
    let mut q = SVector::<f64, 8>::zeros();
    q[3] = f64::NAN;
    let (a, b, c) = arm.forward_dynamics_derivatives(&q, &q, &q);
    assert!(a.iter().chain(b.iter()).chain(c.iter()).any(|x| x.is_nan()));
}

#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct Rods {
    #[arm(length = 1, mass = 1)]
    a: Revolute,
    #[arm(length = 1, mass = 1)]
    b: Revolute,
}

#[test]
fn linearize_is_the_jacobian_of_the_state_derivative() {
    let mut rng = Rng(0x11_4ea7);
    let arm = Scara {
        shoulder: Revolute,
        elbow: Revolute,
        m1: 2.0,
        i1: 0.05,
        c1: 0.2,
        f2: 0.3,
        load: 0.5,
    };
    for _ in 0..20 {
        let (q, tau) = (rng.vector::<2>(3.0), rng.vector::<2>(5.0));
        let qd = rng
            .vector::<2>(3.0)
            .map(|w| if w.abs() < 0.05 { w + 0.1 } else { w });
        let (a, b) = arm.linearize(&q, &qd, &tau);
        // f(x, u) = (qd, FD(q, qd, tau)), differenced along each state and input direction.
        let f = |x: &SVector<f64, 4>, u: &SVector<f64, 2>| -> SVector<f64, 4> {
            let (q, qd) = (Vector2::new(x[0], x[1]), Vector2::new(x[2], x[3]));
            let qdd = arm.forward_dynamics(&q, &qd, u);
            SVector::<f64, 4>::new(qd[0], qd[1], qdd[0], qdd[1])
        };
        let x = SVector::<f64, 4>::new(q[0], q[1], qd[0], qd[1]);
        let h = 1e-6;
        for j in 0..4 {
            let mut e = SVector::<f64, 4>::zeros();
            e[j] = h;
            let col = (f(&(x + e), &tau) - f(&(x - e), &tau)) / (2.0 * h);
            assert!(
                (a.column(j) - col).amax() <= 1e-6 * (1.0 + col.amax()),
                "A column {j}"
            );
        }
        for j in 0..2 {
            let mut e = SVector::<f64, 2>::zeros();
            e[j] = h;
            let col = (f(&x, &(tau + e)) - f(&x, &(tau - e))) / (2.0 * h);
            assert!(
                (b.column(j) - col).amax() <= 1e-6 * (1.0 + col.amax()),
                "B column {j}"
            );
        }
    }
}

#[test]
fn discretize_is_the_zero_order_hold_of_the_linear_system() {
    // Against RK4 on xd = A x + B u with u held, 1000 substeps over dt.
    let arm = Eight::default();
    let mut rng = Rng(0xd15c);
    let (q, qd, tau) = (
        rng.vector::<8>(2.0),
        rng.vector::<8>(2.0),
        rng.vector::<8>(20.0),
    );
    let (a, b) = arm.linearize(&q, &qd, &tau);
    for dt in [1e-3, 1e-2, 5e-2] {
        let (ad, bd) = arm.discretize(&q, &qd, &tau, dt);
        let (x0, u) = (rng.vector::<16>(1.0), rng.vector::<8>(1.0));
        let g = |x: &SVector<f64, 16>| a * x + b * u;
        let (mut x, k) = (x0, 1000);
        let h = dt / f64::from(k);
        for _ in 0..k {
            let k1 = g(&x);
            let k2 = g(&(x + k1 * (h / 2.0)));
            let k3 = g(&(x + k2 * (h / 2.0)));
            let k4 = g(&(x + k3 * h));
            x += (k1 + k2 * 2.0 + k3 * 2.0 + k4) * (h / 6.0);
        }
        let d = (ad * x0 + bd * u - x).amax();
        assert!(d <= 1e-9 * (1.0 + x.amax()), "dt = {dt}: {d:e}");
    }
}

#[test]
fn upright_rods_have_the_textbook_eigenvalues() {
    // Two uniform unit rods balanced straight up (q1 = pi/2, q2 = 0), both joints actuated
    // and holding gravity. By hand from the paper's closed forms (m = l = 1):
    // M = [[5/3 + c2, 1/3 + c2/2], [1/3 + c2/2, 1/3]] = [[8/3, 5/6], [5/6, 1/3]] at q2 = 0,
    // g = g (3/2 c1 + 1/2 c12, 1/2 c12), so -dg/dq = g [[2, 1/2], [1/2, 1/2]] there, and the
    // linearised motion is M dqdd = K dq with K = g [[2, 1/2], [1/2, 1/2]]. The eigenvalues
    // are +- sqrt of those of M^-1 K: two unstable, two stable real pairs.
    let g: f64 = 9.81;
    let (m11, m12, m22): (f64, f64, f64) = (8.0 / 3.0, 5.0 / 6.0, 1.0 / 3.0);
    let (k11, k12, k22): (f64, f64, f64) = (2.0 * g, 0.5 * g, 0.5 * g);
    let det = m11 * m22 - m12 * m12;
    // M^-1 K, entry by entry.
    let p11 = (m22 * k11 - m12 * k12) / det;
    let p12 = (m22 * k12 - m12 * k22) / det;
    let p21 = (m11 * k12 - m12 * k11) / det;
    let p22 = (m11 * k22 - m12 * k12) / det;
    let (tr, dt) = (p11 + p22, p11 * p22 - p12 * p21);
    let disc = (tr * tr / 4.0 - dt).sqrt();
    let mut want = vec![];
    for mu in [tr / 2.0 + disc, tr / 2.0 - disc] {
        want.extend([mu.sqrt(), -mu.sqrt()]);
    }
    want.sort_by(f64::total_cmp);

    let arm = Rods::default();
    let q = Vector2::new(core::f64::consts::FRAC_PI_2, 0.0);
    let (a, _) = arm.linearize(&q, &Vector2::zeros(), &arm.gravity(&q));
    let eig = a.complex_eigenvalues();
    let mut got: Vec<f64> = eig
        .iter()
        .map(|z| {
            assert!(z.im.abs() < 1e-9, "{z}");
            z.re
        })
        .collect();
    got.sort_by(f64::total_cmp);
    for (g, w) in got.iter().zip(&want) {
        assert!((g - w).abs() < 1e-9, "{got:?} vs {want:?}");
    }
    assert!(want[3] > 0.0, "upright is unstable");
}

#[test]
fn linearize_and_discretize_with_bad_input_give_nan_not_a_panic() {
    let arm = Rods::default();
    let q = Vector2::new(f64::NAN, 0.0);
    let (a, b) = arm.linearize(&q, &Vector2::zeros(), &Vector2::zeros());
    assert!(a.iter().chain(b.iter()).any(|x| x.is_nan()));
    let ok = Vector2::new(0.3, 0.2);
    for dt in [f64::NAN, f64::INFINITY] {
        let (ad, _) = arm.discretize(&ok, &ok, &ok, dt);
        assert!(ad.iter().any(|x| !x.is_finite()), "dt = {dt}");
    }
    let (ad, _) = arm.discretize(&q, &ok, &ok, 0.01);
    assert!(ad.iter().any(|x| x.is_nan()));
}
