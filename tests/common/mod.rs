//! Shared checks of a derived arm against the numeric reference and the laws of mechanics.
#![allow(dead_code)] // each test crate uses a different subset

pub mod riccati;

use planar_arm::nalgebra::{SMatrix, SVector};
use planar_arm::prelude::*;
use planar_arm::reference;

/// Deterministic splitmix64 generator, so that failures reproduce.
pub struct Rng(pub u64);

impl Rng {
    /// Uniform in [0, 1).
    pub fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        #[allow(clippy::cast_precision_loss)]
        let u = (z >> 11) as f64 / (1u64 << 53) as f64;
        u
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }

    /// Each entry uniform in [-r, r).
    pub fn vector<const N: usize>(&mut self, r: f64) -> SVector<f64, N> {
        SVector::from_fn(|_, _| self.range(-r, r))
    }
}

/// `count` states `[q, qd, qdd]`, each entry uniform in `[-r, r)`.
pub fn states<const N: usize>(rng: &mut Rng, count: usize, r: f64) -> Vec<[SVector<f64, N>; 3]> {
    (0..count)
        .map(|_| [rng.vector(r), rng.vector(r), rng.vector(r)])
        .collect()
}

/// Asserts `a` and `b` agree to `1e-12` of the larger's largest entry (or of 1).
pub fn assert_matrix_close<const R: usize, const C: usize>(
    a: &SMatrix<f64, R, C>,
    b: &SMatrix<f64, R, C>,
    what: &str,
) {
    let scale = a.amax().max(b.amax()).max(1.0);
    assert!((a - b).amax() <= 1e-12 * scale, "{what}: {a} vs {b}");
}

/// Relative closeness: `|a - b| <= tol * max(1, scale)`.
pub fn close(a: f64, b: f64, tol: f64, scale: f64) -> bool {
    (a - b).abs() <= tol * scale.max(1.0)
}

/// Every check of one derived arm at one state; panics with a message on failure.
pub fn check_state<A: PlanarArm<N>, const N: usize>(
    arm: &A,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    qdd: &SVector<f64, N>,
) {
    let model = arm.model();
    let m = arm.mass_matrix(q);
    let m_ref = reference::mass_matrix(&model, q);
    let tau = arm.inverse_dynamics(q, qd, qdd);
    let tau_ref = reference::inverse_dynamics(&model, q, qd, qdd);
    let scale = m_ref.amax() * (1.0 + qd.amax().powi(2) + qdd.amax()) + tau_ref.amax();
    let tol = 1e-9;
    for i in 0..N {
        assert!(
            close(tau[i], tau_ref[i], tol, scale),
            "tau[{i}] {} vs reference {}",
            tau[i],
            tau_ref[i]
        );
        for j in 0..N {
            assert!(close(m[(i, j)], m_ref[(i, j)], tol, scale), "M[{i}][{j}]");
            assert_eq!(m[(i, j)], m[(j, i)], "M is symmetric");
        }
    }
    // Positive definite: Cholesky succeeds.
    assert!(m.cholesky().is_some(), "M positive definite at q = {q}");

    let c = arm.coriolis(q, qd);
    let gv = arm.gravity(q);
    let c_ref = reference::coriolis(&model, q, qd);
    let g_ref = reference::gravity_torques(&model, q);
    let cm = arm.coriolis_matrix(q, qd);
    let cqd = cm * qd;
    for i in 0..N {
        assert!(
            close(c[i], c_ref[i], tol, scale),
            "c[{i}] {} vs {}",
            c[i],
            c_ref[i]
        );
        assert!(
            close(gv[i], g_ref[i], tol, scale),
            "g[{i}] {} vs {}",
            gv[i],
            g_ref[i]
        );
        assert!(close(cqd[i], c[i], tol, scale), "C qd = c, row {i}");
    }
    // tau = M qdd + c + g + f, four generated methods against a fifth; the bias and M with
    // the bias in one pass against the same.
    let f = arm.friction(qd);
    let f_ref = reference::friction(&model, qd);
    let h = arm.bias(q, qd);
    let (m2, h2) = arm.mass_matrix_and_bias(q, qd);
    let assembled = m * qdd + c + gv + f;
    let from_bias = m2 * qdd + h2;
    for i in 0..N {
        assert!(close(f[i], f_ref[i], tol, scale), "friction[{i}]");
        assert!(
            close(assembled[i], tau[i], tol, scale),
            "M qdd + c + g + f, row {i}"
        );
        assert!(close(h[i], c[i] + gv[i] + f[i], tol, scale), "bias[{i}]");
        assert!(close(h2[i], h[i], tol, scale), "(M, h).h[{i}]");
        assert!(
            close(from_bias[i], tau[i], tol, scale),
            "M qdd + h, row {i}"
        );
        for j in 0..N {
            assert!(close(m2[(i, j)], m[(i, j)], tol, scale), "(M, h).M");
        }
    }

    // Forward dynamics inverts inverse dynamics.
    let back = arm.forward_dynamics(q, qd, &tau);
    let fd_ref = reference::forward_dynamics(&model, q, qd, &tau);
    let m_inv = m
        .cholesky()
        .map(|c| c.inverse())
        .expect("positive definite");
    #[allow(clippy::cast_precision_loss)]
    let cond = m.amax() * m_inv.amax() * N as f64;
    for i in 0..N {
        assert!(
            close(back[i], qdd[i], 1e-12 * cond.max(1.0), qdd.amax()),
            "forward(inverse(qdd))[{i}] = {} vs {}",
            back[i],
            qdd[i]
        );
        assert!(
            close(back[i], fd_ref[i], 1e-12 * cond.max(1.0), qdd.amax()),
            "vs ABA [{i}]"
        );
    }

    // The frozen view evaluates the same formulas with the parameter-only values computed
    // once. Sums are grouped differently (`a + (b + c)` where the direct method writes
    // `a + b + c`), so the numbers agree to rounding, not to the bit.
    let frozen = arm.freeze();
    let (fm, fh) = frozen.mass_matrix_and_bias(q, qd);
    let pairs = [
        ((frozen.mass_matrix(q) - m).amax(), "mass_matrix"),
        ((fm - m2).amax(), "(M, h).M"),
        ((fh - h2).amax(), "(M, h).h"),
        ((frozen.bias(q, qd) - h).amax(), "bias"),
        (
            (frozen.inverse_dynamics(q, qd, qdd) - tau).amax(),
            "inverse_dynamics",
        ),
    ];
    for (diff, what) in pairs {
        assert!(diff <= 1e-13 * scale, "frozen {what} differs by {diff}");
    }
    let fback = frozen.forward_dynamics(q, qd, &tau);
    assert!(
        (fback - back).amax() <= 1e-12 * cond.max(1.0) * (1.0 + qdd.amax()),
        "frozen forward_dynamics: {fback} vs {back}"
    );

    // Mdot - 2C is skew-symmetric; Mdot by central differences along qd.
    let h = 1e-6;
    let mdot = (arm.mass_matrix(&(q + qd * h)) - arm.mass_matrix(&(q - qd * h))) / (2.0 * h);
    let n_mat: SMatrix<f64, N, N> = mdot - cm * 2.0;
    let skew = n_mat + n_mat.transpose();
    assert!(
        skew.amax() <= 1e-6 * scale.max(1.0),
        "Mdot - 2C not skew: {skew}"
    );

    // Energies: T = qd^T M qd / 2 and g = dV/dq.
    let t = arm.kinetic_energy(q, qd);
    let t_quad = 0.5 * (qd.transpose() * m * qd)[(0, 0)];
    assert!(
        close(t, t_quad, tol, scale),
        "T {t} vs qd^T M qd / 2 {t_quad}"
    );
    assert!(close(
        t,
        reference::kinetic_energy(&model, q, qd),
        tol,
        scale
    ));
    assert!(close(
        arm.potential_energy(q),
        reference::potential_energy(&model, q),
        tol,
        scale
    ));
    for i in 0..N {
        let mut e = SVector::<f64, N>::zeros();
        e[i] = h;
        let dv = (arm.potential_energy(&(q + e)) - arm.potential_energy(&(q - e))) / (2.0 * h);
        assert!(
            close(dv, gv[i], 1e-6, scale),
            "dV/dq[{i}] {dv} vs g {}",
            gv[i]
        );
    }

    // Kinematics: tip, joints and Jacobian.
    let tip = arm.tip_pose(q);
    let tip_ref = reference::tip_position(&model, q);
    assert!(close(tip.translation.x, tip_ref.x, tol, 10.0));
    assert!(close(tip.translation.y, tip_ref.y, tol, 10.0));
    // A prismatic joint does not turn its link.
    let phi: f64 = (0..N)
        .filter(|&i| model.links[i].joint == Joint::Revolute)
        .map(|i| q[i])
        .sum();
    assert!(
        (tip.rotation.angle() - planar_arm::nalgebra::UnitComplex::new(phi).angle()).abs() < 1e-9
    );
    let j = arm.jacobian(q);
    let j_ref = reference::jacobian(&model, q);
    assert!(
        (j - j_ref).amax() <= 1e-9 * j_ref.amax().max(1.0),
        "Jacobian"
    );
    let joints = arm.joint_positions(q);
    let joints_ref = reference::joint_positions(&model, q);
    for (a, b) in joints.iter().zip(&joints_ref) {
        assert!(
            (a - b).norm() <= 1e-9 * (1.0 + b.coords.norm()),
            "joint positions"
        );
    }
}

/// One test per arm: `name: Type, N;`, each over proptest-drawn states.
#[macro_export]
macro_rules! planar_arm_tests_check_arms {
    ($($name:ident: $ty:ty, $n:literal;)*) => {
        $(
            proptest::proptest! {
                #![proptest_config(proptest::prelude::ProptestConfig { cases: 64, ..Default::default() })]
                #[test]
                fn $name(
                    q in proptest::collection::vec(-4.0f64..4.0, $n),
                    qd in proptest::collection::vec(-3.0f64..3.0, $n),
                    qdd in proptest::collection::vec(-5.0f64..5.0, $n),
                ) {
                    let arm = <$ty>::default();
                    let v = |x: &Vec<f64>| planar_arm::nalgebra::SVector::<f64, $n>::from_column_slice(x);
                    $crate::common::check_state::<$ty, $n>(&arm, &v(&q), &v(&qd), &v(&qdd));
                }
            }
        )*
    };
}
