//! Unit tests of the inverse statics: the closed forms and the least-squares wrench against
//! the transposed Jacobian, and the paper's printed inverses entry by entry.

use super::*;
use crate::kinematics::jacobian_of;
use crate::kinematics::test_support::{fk_joints, jacobian, Rng, PAIRS, TRIPLES};
use crate::{Joint, Link};
use core::f64::consts::{PI, TAU};
use nalgebra::{Matrix2, Matrix3, Vector3};

/// `a x b = a.x b.y - a.y b.x`, the paper's planar cross product.
fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

/// Joint torques for tip force `f` and torque `t` from the paper's statics:
/// tau_i = t + (r_i + ... + r_n) x f.
fn joint_torques(lengths: &[f64], q: &[f64], f: Vector2<f64>, t: f64) -> Vec<f64> {
    let mut phi = 0.0;
    let links: Vec<Vector2<f64>> = lengths
        .iter()
        .zip(q)
        .map(|(l, qk)| {
            phi += qk;
            Vector2::new(l * phi.cos(), l * phi.sin())
        })
        .collect();
    (0..links.len())
        .map(|i| t + cross(links[i..].iter().sum(), f))
        .collect()
}

fn random_force(rng: &mut Rng) -> Vector2<f64> {
    Vector2::new(rng.range(-10.0, 10.0), rng.range(-10.0, 10.0))
}

#[test]
fn tip_force2_inverts_the_transposed_jacobian() {
    let mut rng = Rng(5);
    for (l1, l2) in PAIRS {
        for _ in 0..2000 {
            let q = Vector2::new(rng.angle(), rng.angle());
            if q[1].sin().abs() < 0.05 {
                continue;
            }
            // Force -> torques (the paper's statics) -> force.
            let f = random_force(&mut rng);
            let tau = joint_torques(&[l1, l2], q.as_slice(), f, 0.0);
            let back = tip_force2(l1, l2, &q, &Vector2::new(tau[0], tau[1])).unwrap();
            assert!(
                (back - f).norm() < 1e-9 * f.norm().max(1.0),
                "{f} came back as {back}"
            );
            // Torques -> force -> torques, via the independent Jacobian.
            let tau = Vector2::new(rng.range(-5.0, 5.0), rng.range(-5.0, 5.0));
            let f = tip_force2(l1, l2, &q, &tau).unwrap();
            let j = jacobian(&[l1, l2], &q);
            let again = j.fixed_rows::<2>(0).transpose() * f;
            assert!((again - tau).norm() < 1e-9 * tau.norm().max(1.0));
        }
    }
}

#[test]
fn tip_wrench3_inverts_the_transposed_jacobian() {
    let mut rng = Rng(6);
    for (l1, l2, l3) in TRIPLES {
        for _ in 0..2000 {
            let q = Vector3::new(rng.angle(), rng.angle(), rng.angle());
            if q[1].sin().abs() < 0.05 {
                continue;
            }
            let f = random_force(&mut rng);
            let t = rng.range(-3.0, 3.0);
            let tau = joint_torques(&[l1, l2, l3], q.as_slice(), f, t);
            let back = tip_wrench3(l1, l2, l3, &q, &Vector3::new(tau[0], tau[1], tau[2])).unwrap();
            let (f_back, t_back) = (back.force, back.torque);
            assert!((f_back - f).norm() < 1e-9 * f.norm().max(1.0));
            assert!((t_back - t).abs() < 1e-9 * t.abs().max(1.0));
            let tau = Vector3::new(
                rng.range(-5.0, 5.0),
                rng.range(-5.0, 5.0),
                rng.range(-5.0, 5.0),
            );
            let w = tip_wrench3(l1, l2, l3, &q, &tau).unwrap();
            let (f, t) = (w.force, w.torque);
            let again = jacobian(&[l1, l2, l3], &q).transpose() * Vector3::new(f.x, f.y, t);
            assert!((again - tau).norm() < 1e-9 * tau.norm().max(1.0));
        }
    }
}

/// The paper's printed inverse statics, entry by entry, against the forward matrices.
#[test]
fn paper_statics_inverses_are_correct_as_printed() {
    let mut rng = Rng(7);
    let (l1, l2, l3) = (1.0, 0.7, 0.4);
    for _ in 0..500 {
        let q = Vector3::new(rng.angle(), rng.angle(), rng.angle());
        let det = l1 * l2 * q[1].sin();
        if det.abs() < 0.05 {
            continue;
        }
        let (s1, c1) = q[0].sin_cos();
        let (s12, c12) = (q[0] + q[1]).sin_cos();
        let (s123, c123) = (q[0] + q[1] + q[2]).sin_cos();
        let (s2, s3, s23) = (q[1].sin(), q[2].sin(), (q[1] + q[2]).sin());
        let forward = Matrix3::new(
            -(l1 * s1 + l2 * s12 + l3 * s123),
            l1 * c1 + l2 * c12 + l3 * c123,
            1.0,
            -(l2 * s12 + l3 * s123),
            l2 * c12 + l3 * c123,
            1.0,
            -(l3 * s123),
            l3 * c123,
            1.0,
        );
        assert!((forward.determinant() - det).abs() < 1e-12);
        let printed = Matrix3::new(
            l2 * c12,
            -(l1 * c1 + l2 * c12),
            l1 * c1,
            l2 * s12,
            -(l1 * s1 + l2 * s12),
            l1 * s1,
            l2 * l3 * s3,
            -(l1 * l3 * s23 + l2 * l3 * s3),
            l1 * l2 * s2 + l1 * l3 * s23,
        ) / det;
        assert!((printed * forward - Matrix3::identity()).norm() < 1e-9);
        // Two links: u = {l2 c12 T1 - (l1 c1 + l2 c12) T2} / (l1 l2 s2), v likewise.
        let forward2 = Matrix2::new(
            -(l1 * s1 + l2 * s12),
            l1 * c1 + l2 * c12,
            -(l2 * s12),
            l2 * c12,
        );
        let printed2 = Matrix2::new(
            l2 * c12,
            -(l1 * c1 + l2 * c12),
            l2 * s12,
            -(l1 * s1 + l2 * s12),
        ) / det;
        assert!((printed2 * forward2 - Matrix2::identity()).norm() < 1e-9);
    }
}

/// `J^T (F, T)` with `J` from central differences of the independent forward kinematics.
fn generalised_forces<const N: usize>(
    kinds: &[Joint; N],
    lengths: &[f64; N],
    q: &SVector<f64, N>,
    w: Vector3<f64>,
) -> SVector<f64, N> {
    SVector::from_fn(|i, _| {
        let h = 1e-6;
        let (mut qp, mut qm) = (*q, *q);
        qp[i] += h;
        qm[i] -= h;
        let (xp, yp, pp) = fk_joints(kinds, lengths, qp.as_slice());
        let (xm, ym, pm) = fk_joints(kinds, lengths, qm.as_slice());
        Vector3::new(xp - xm, yp - ym, pp - pm).dot(&w) / (2.0 * h)
    })
}

fn mixed_case<const N: usize>(kinds: [Joint; N], lengths: [f64; N], rng: &mut Rng) {
    let links: [Link; N] =
        core::array::from_fn(|i| Link::rod(lengths[i], 1.0).with_joint(kinds[i]));
    let mut solved = 0;
    for _ in 0..500 {
        let q = SVector::<f64, N>::from_fn(|_, _| rng.range(-2.0, 2.0));
        let f = random_force(rng);
        let t = if N >= 3 { rng.range(-3.0, 3.0) } else { 0.0 };
        let tau = generalised_forces(&kinds, &lengths, &q, Vector3::new(f.x, f.y, t));
        match inverse_statics_of(&links, &q, &tau) {
            Ok(w) => {
                solved += 1;
                let scale = tau.norm().max(1.0);
                let again = generalised_forces(
                    &kinds,
                    &lengths,
                    &q,
                    Vector3::new(w.force.x, w.force.y, w.torque),
                );
                assert!((again - tau).norm() < 1e-6 * scale);
                // One slide determines only the force along it.
                let expected = if N == 1 { Vector2::new(f.x, 0.0) } else { f };
                assert!(
                    (w.force - expected).norm() < 1e-6 * scale,
                    "{kinds:?}: {f} came back as {}",
                    w.force
                );
                assert!((w.torque - t).abs() < 1e-6 * scale);
                assert!(w.residual.norm() < 1e-6 * scale);
                if N > 3 {
                    // Torques from no wrench: the residual is what J^T w cannot explain.
                    let noise = SVector::<f64, N>::from_fn(|_, _| rng.range(-1.0, 1.0));
                    let w = inverse_statics_of(&links, &q, &noise).unwrap();
                    let j = jacobian_of(&links, &q);
                    // Orthogonal to the range of J^T in the metric of the scaled rows:
                    // a hinge's by the reach squared.
                    let reach: f64 = (0..N)
                        .map(|i| {
                            lengths[i].abs()
                                + if kinds[i] == Joint::Prismatic {
                                    q[i].abs()
                                } else {
                                    0.0
                                }
                        })
                        .sum();
                    let weighted = SVector::<f64, N>::from_fn(|i, _| {
                        w.residual[i]
                            / if kinds[i] == Joint::Revolute {
                                reach * reach
                            } else {
                                1.0
                            }
                    });
                    assert!((j * weighted).norm() < 1e-9, "residual not orthogonal");
                    let explained = j.transpose() * Vector3::new(w.force.x, w.force.y, w.torque);
                    assert!((explained + w.residual - noise).norm() < 1e-9);
                }
            }
            Err(ArmError::Singular { .. }) => {}
            Err(e) => panic!("{e:?}"),
        }
    }
    assert!(solved > 450, "{kinds:?}: {solved} of 500");
}

#[test]
fn inverse_statics_of_any_mix_inverts_the_transposed_jacobian() {
    let mut rng = Rng(30);
    let (r, p) = (Joint::Revolute, Joint::Prismatic);
    mixed_case([p], [0.5], &mut rng);
    mixed_case([r, p], [0.2, 0.5], &mut rng);
    mixed_case([p, r], [0.3, 0.5], &mut rng);
    mixed_case([p, r, r], [0.2, 0.6, 0.3], &mut rng);
    mixed_case([r, p, r], [0.4, 0.5, 0.3], &mut rng);
    mixed_case([r, p, r, p], [0.4, 1.0, 0.3, 0.2], &mut rng);
    mixed_case([p, r, r, r, r], [0.2, 0.5, 0.4, 0.3, 0.2], &mut rng);
    // Revolute links: exactly inverse_statics.
    let links = [
        Link::rod(1.0, 1.0),
        Link::rod(0.5, 1.0),
        Link::rod(0.25, 1.0),
        Link::rod(0.5, 1.0),
    ];
    let q = SVector::<f64, 4>::new(0.3, 0.9, -0.4, 1.1);
    let tau = SVector::<f64, 4>::new(1.0, -0.5, 0.25, 2.0);
    assert_eq!(
        inverse_statics_of(&links, &q, &tau),
        inverse_statics(&[1.0, 0.5, 0.25, 0.5], &q, &tau)
    );
    // The polar arm with its tip at the base: no force balances the hinge.
    let polar = [Link::rod(0.2, 1.0), Link::rod(0.5, 1.0).with_joint(p)];
    assert!(matches!(
        inverse_statics_of(&polar, &Vector2::new(0.3, -0.7), &Vector2::new(1.0, 1.0)),
        Err(ArmError::Singular { .. })
    ));
    // Sliders alone feel no tip torque.
    let sliders = [
        Link::rod(0.2, 1.0).with_joint(p),
        Link::rod(0.2, 1.0).with_joint(p),
        Link::rod(0.2, 1.0).with_joint(p),
    ];
    assert!(matches!(
        inverse_statics_of(
            &sliders,
            &Vector3::new(0.1, 0.2, 0.3),
            &Vector3::new(1.0, 1.0, 1.0)
        ),
        Err(ArmError::Singular { .. })
    ));
    assert_eq!(
        inverse_statics_of(&polar, &Vector2::new(f64::NAN, 0.0), &Vector2::zeros()),
        Err(ArmError::NonFinite { argument: "q" })
    );
}

#[test]
fn singular_configurations_are_rejected() {
    let (l1, l2, l3) = (1.0, 0.5, 0.25);
    for q2 in [0.0, PI, -PI, 1e-12, PI - 1e-12, TAU, 0.5e-9] {
        let expected = Err(ArmError::Singular {
            measure: l1 * l2 * f64::sin(q2),
            threshold: SINGULAR_THRESHOLD * l1 * l2,
        });
        let tau2 = Vector2::new(1.0, -1.0);
        assert_eq!(tip_force2(l1, l2, &Vector2::new(0.3, q2), &tau2), expected);
        let tau3 = Vector3::new(1.0, -1.0, 0.5);
        let got = tip_wrench3(l1, l2, l3, &Vector3::new(0.3, q2, 1.0), &tau3);
        assert_eq!(got.map(|_| Vector2::zeros()), expected);
    }
    for q2 in [2e-9, 1e-6, PI - 1e-6] {
        assert!(tip_force2(l1, l2, &Vector2::new(0.3, q2), &Vector2::new(1.0, 0.0)).is_ok());
    }
    assert!(matches!(
        tip_force2(0.0, l2, &Vector2::new(0.3, 1.0), &Vector2::new(1.0, 0.0)),
        Err(ArmError::Singular { .. })
    ));
    // Zero torques give zero force even near (but not at) a singularity.
    assert_eq!(
        tip_force2(l1, l2, &Vector2::new(0.3, 1e-6), &Vector2::zeros()),
        Ok(Vector2::zeros())
    );
}
