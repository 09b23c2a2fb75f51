//! A one-link arm is a compound pendulum: M = I + m c^2, g(q) = m g c cos q, no velocity
//! terms. Its parameters are written every way the attribute accepts.
use planar_arm::prelude::*;

#[derive(PlanarArm)]
#[arm(gravity = 9.81)]
struct Pendulum {
    #[arm(length = 0.5, mass = 3/2, inertia = 1/12 * (3/2) * 0.5 * 0.5, com = 1/4)]
    rod: Revolute,
}

/// Every numeric form: integers, decimals, exponents, suffixes, underscores, fractions,
/// parentheses, negation, arithmetic.
#[derive(PlanarArm)]
#[arm(gravity = 1_000e-2 - 0.19)]
struct Forms {
    #[arm(length = 2, mass = 1.5e0, inertia = 25E-3, com = -(1 - 3/2) * 2)]
    a: Revolute,
    #[arm(com = 0.4_f64, inertia = (2 + 1) / (4 * 25), mass = 3i32, length = 1f64)]
    b: Revolute,
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * (1.0 + a.abs().max(b.abs()))
}

fn main() {
    let arm = Pendulum { rod: Revolute };
    let (m, g, c, inertia) = (1.5, 9.81, 0.25, 1.5 * 0.25 / 12.0);
    assert_eq!(arm.model().gravity.y, -9.81);
    assert_eq!(arm.links()[0].length, 0.5);
    assert!(close(arm.links()[0].inertia, inertia));
    for k in -20..=20 {
        let q = SVector::<f64, 1>::new(f64::from(k) * 0.37);
        let qd = SVector::<f64, 1>::new(f64::from(k) * 1.3);
        let qdd = SVector::<f64, 1>::new(0.5 - f64::from(k));
        // By hand: tau = (I + m c^2) qdd + m g c cos q.
        let expected = (inertia + m * c * c) * qdd[0] + m * g * c * q[0].cos();
        assert!(close(arm.mass_matrix(&q)[(0, 0)], inertia + m * c * c));
        assert!(close(arm.gravity(&q)[0], m * g * c * q[0].cos()));
        assert_eq!(arm.coriolis(&q, &qd)[0], 0.0);
        assert!(close(arm.inverse_dynamics(&q, &qd, &qdd)[0], expected));
        let tau = SVector::<f64, 1>::new(expected);
        assert!(close(arm.forward_dynamics(&q, &qd, &tau)[0], qdd[0]));
        assert!(close(arm.potential_energy(&q), m * g * c * q[0].sin()));
        assert!(close(
            arm.kinetic_energy(&q, &qd),
            0.5 * (inertia + m * c * c) * qd[0] * qd[0]
        ));
        let tip = arm.tip_pose(&q).translation.vector;
        assert!(close(tip.x, 0.5 * q[0].cos()) && close(tip.y, 0.5 * q[0].sin()));
    }

    let forms = Forms {
        a: Revolute,
        b: Revolute,
    };
    assert!(close(forms.model().gravity.y, -9.81));
    let [a, b] = forms.links();
    assert_eq!(
        (a.length, a.mass, a.inertia, a.com),
        (2.0, 1.5, 0.025, Vector2::new(1.0, 0.0))
    );
    assert_eq!(
        (b.length, b.mass, b.inertia, b.com),
        (1.0, 3.0, 0.03, Vector2::new(0.4, 0.0))
    );
    let q = SVector::<f64, 2>::new(0.3, -1.1);
    let exact = planar_arm::reference::mass_matrix(&forms.model(), &q);
    assert!((forms.mass_matrix(&q) - exact).amax() < 1e-12);
}
