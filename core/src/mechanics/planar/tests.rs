//! Tests of the Lagrangian derivation: M, c, C and g against Lagrange's equation expanded, the
//! Christoffel symbols summed one by one, the squared velocities, and closed forms by hand.

use super::bodies::bodies;
use super::energy::{kinetic_energy, kinetic_energy_of_velocities};
use super::kinematics::point_on_link;
use super::rates::rate;
use super::*;
use crate::expr::{Expr, Var};
use crate::ring::{int, ratio, Coefficient, Rational};
use crate::trig::{Angle, Trig};

fn c(k: &[i32]) -> Trig {
    Trig::Cos(Angle::new(k.to_vec()))
}

#[test]
fn two_equal_links_mass_matrix() {
    let d = Dynamics::derive(&ArmSpec::paper(2));
    // M = m l^2 [[5/3 + c2, 1/3 + c2/2], [1/3 + c2/2, 1/3]]
    assert_eq!(d.mass_matrix[0][0].constant_term(), Some(&ratio(5, 3)));
    assert_eq!(d.mass_matrix[0][0].coefficient(&c(&[0, 1])), Some(&int(1)));
    assert_eq!(d.mass_matrix[0][1].constant_term(), Some(&ratio(1, 3)));
    assert_eq!(
        d.mass_matrix[0][1].coefficient(&c(&[0, 1])),
        Some(&ratio(1, 2))
    );
    assert_eq!(d.mass_matrix[1][1], Expr::constant(ratio(1, 3)));
    assert_eq!(d.mass_matrix[0][1], d.mass_matrix[1][0]);
}

#[test]
fn mass_matrix_two_ways_agree_and_c_is_christoffel() {
    for (n, pattern) in (1..=4).flat_map(|n| (0..1u32 << n).map(move |p| (n, p))) {
        let mut arm = ArmSpec::paper(n);
        arm.gravity = crate::down(ratio(981, 100));
        for (i, l) in arm.links.iter_mut().enumerate() {
            *l = LinkSpec {
                length: ratio(i as i64 + 2, 3),
                mass: ratio(2 * i as i64 + 1, 2),
                inertia: ratio(1, i as i64 + 5),
                com: (ratio(1, i as i64 + 2), ratio(1 - i as i64, 7)),
                armature: ratio(i as i64, 10),
                ..LinkSpec::rod(int(1), int(1))
            };
        }
        let arm = arm.with_prismatic(pattern);
        let d = Dynamics::derive(&arm);
        assert_eq!(d.mass_matrix, d.mass_matrix_from_lagrange(), "n = {n}");
        let cm = d.coriolis_matrix();
        assert_eq!(cm, christoffel(&d.mass_matrix), "n = {n}");
        assert_eq!(d.torques(), d.lagrange_torques(), "n = {n}");
        for (i, row) in cm.iter().enumerate() {
            let mut cqd = Expr::zero();
            for (j, cij) in row.iter().enumerate() {
                cqd = cqd.add(&cij.mul(&Expr::var(Var::Qd(j))));
            }
            assert_eq!(cqd, d.coriolis[i], "n = {n}, row {i}");
            // g = dV/dq
            assert_eq!(d.gravity[i], d.potential_energy.diff_q(i));
        }
    }
}

/// `C_ij = sum_k 1/2 (dM_ij/dq_k + dM_ik/dq_j - dM_jk/dq_i) qd_k`.
pub(crate) fn christoffel<C: Coefficient>(m: &[Vec<Expr<C>>]) -> Vec<Vec<Expr<C>>> {
    let n = m.len();
    let half = ratio(1, 2);
    // Every dM_ab/dq_k once (M is symmetric): the sum below reads each of them three times.
    let dm: Vec<Vec<Vec<Expr<C>>>> = (0..n)
        .map(|a| {
            (0..n)
                .map(|b| {
                    if b < a {
                        Vec::new()
                    } else {
                        (0..n).map(|k| m[a][b].diff_q(k)).collect()
                    }
                })
                .collect()
        })
        .collect();
    let d = |a: usize, b: usize, k: usize| &dm[a.min(b)][a.max(b)][k];
    (0..n)
        .map(|i| {
            (0..n)
                .map(|j| {
                    // Twice C_ij, halved once at the end.
                    let mut c = Expr::zero();
                    for k in 0..n {
                        let mut gamma = d(i, j, k).clone();
                        gamma.add_assign(d(i, k, j));
                        let gamma = gamma.sub(d(j, k, i));
                        c.add_assign(&gamma.mul_var(rate(k)));
                    }
                    c.scale(&half)
                })
                .collect()
        })
        .collect()
}

/// The kinetic energy the long way: the centres' velocities by the chain rule on their
/// positions, squared and summed, plus the rotations and rotors.
fn kinetic_energy_by_velocities<C: Coefficient>(arm: &ArmSpec<C>) -> Expr<C> {
    let n = arm.links.len();
    let half = ratio(1, 2);
    let mut kinetic = Expr::zero();
    for (i, at, mass, inertia) in bodies(arm) {
        let (x, y) = point_on_link(arm, i, &at);
        let (vx, vy) = (x.dt(n), y.dt(n));
        let v2 = vx.mul(&vx).add(&vy.mul(&vy));
        kinetic.add_assign(&v2.scale_by(mass).scale(&half));
        let mut w = Expr::zero();
        for j in 0..=i {
            if arm.links[j].joint == JointKind::Revolute {
                let qd = Expr::var(rate(j));
                w = if arm.links[j].reversed {
                    w.sub(&qd)
                } else {
                    w.add(&qd)
                };
            }
        }
        kinetic.add_assign(&w.mul(&w).scale_by(inertia).scale(&half));
    }
    for (i, link) in arm.links.iter().enumerate() {
        let qd = Expr::var(rate(i));
        kinetic.add_assign(&qd.mul(&qd).scale_by(&link.armature).scale(&half));
    }
    kinetic
}

/// `n` links of uneven lengths, masses, inertias, offset centres of mass and armature, holding
/// an offset payload.
pub(crate) fn uneven_arm(n: usize) -> ArmSpec {
    let mut arm = ArmSpec::paper(n);
    for (i, l) in arm.links.iter_mut().enumerate() {
        let i = i as i64;
        *l = LinkSpec {
            length: ratio(i + 2, 3),
            mass: ratio(2 * i + 1, 2),
            inertia: ratio(1, i + 5),
            com: (ratio(1 - i, i + 2), ratio(1 - i, 7)),
            armature: ratio(i, 10),
            ..LinkSpec::rod(int(1), int(1))
        };
    }
    arm.payload = Some(PayloadSpec {
        mass: ratio(3, 4),
        inertia: ratio(1, 9),
        com: (ratio(1, 5), ratio(-2, 7)),
    });
    arm
}

#[test]
fn kinetic_energy_of_any_joints_is_the_squared_velocities() {
    for (n, pattern) in (1..=4).flat_map(|n| (0..1u32 << n).map(move |p| (n, p))) {
        let arm = uneven_arm(n);
        let arm = arm.with_prismatic(pattern);
        let bodies = standard_bodies(&arm);
        let by_velocities = kinetic_energy_by_velocities(&arm);
        assert_eq!(
            kinetic_energy_of_velocities(&arm, &bodies),
            by_velocities,
            "n = {n}, joints {pattern:b}"
        );
        if pattern == 0 {
            let pairwise = kinetic_energy(&arm, &bodies, &mut RateProducts::new());
            assert_eq!(pairwise, by_velocities, "n = {n}");
        }
    }
}

/// The polar arm (revolute, then prismatic) by hand: with `r = l1 + q2 + c2` the distance
/// of the boom's centre from the axis, `T = (I1 + m1 c1^2 + I2 + m2 r^2) qd1^2 / 2 + m2
/// qd2^2 / 2` (the boom's centre moves radially at `qd2`, tangentially at `r qd1`), and
/// `V = g (m1 c1 + m2 r) sin q1`.
#[test]
fn polar_arm_by_hand() {
    let (l1, c1, m1, i1) = (ratio(1, 5), ratio(1, 10), int(3), ratio(1, 100));
    let (c2, m2, i2) = (ratio(1, 4), ratio(3, 2), ratio(1, 32));
    let g = ratio(981, 100);
    let arm = ArmSpec {
        links: vec![
            LinkSpec {
                inertia: i1.clone(),
                com: (c1.clone(), int(0)),
                ..LinkSpec::rod(l1.clone(), m1.clone())
            },
            LinkSpec {
                inertia: i2.clone(),
                com: (c2.clone(), int(0)),
                joint: JointKind::Prismatic,
                ..LinkSpec::rod(ratio(1, 2), m2.clone())
            },
        ],
        gravity: crate::down(g.clone()),
        payload: None,
    };
    let d = Dynamics::derive(&arm);
    let q2 = Expr::<Rational>::var(Var::Q(1));
    let r = q2.add(&Expr::constant(l1.clone() + c2.clone()));
    let m11 = r.mul(&r).scale(&m2).add(&Expr::constant(
        i1 + m1.clone() * c1.clone() * c1.clone() + i2,
    ));
    assert_eq!(d.mass_matrix[0][0], m11);
    assert_eq!(d.mass_matrix[0][1], Expr::zero());
    assert_eq!(d.mass_matrix[1][1], Expr::constant(m2.clone()));
    // c = (2 m2 r qd1 qd2, -m2 r qd1^2)
    let (qd1, qd2) = (Expr::var(Var::Qd(0)), Expr::var(Var::Qd(1)));
    assert_eq!(
        d.coriolis[0],
        r.mul(&qd1).mul(&qd2).scale(&(int(2) * m2.clone()))
    );
    assert_eq!(d.coriolis[1], r.mul(&qd1).mul(&qd1).scale(&(-m2.clone())));
    // g = (g (m1 c1 + m2 r) cos q1, g m2 sin q1)
    let q1 = Angle::new(vec![1]);
    let moment = r.scale(&m2).add(&Expr::constant(m1 * c1));
    assert_eq!(d.gravity[0], moment.mul(&Expr::cos(g.clone(), q1.clone())));
    assert_eq!(d.gravity[1], Expr::sin(g * m2, q1));
    let k = Kinematics::derive(&arm);
    // tip = (l1 + q2 + l2) (cos q1, sin q1); the Jacobian's last row (1, 0)
    let reach = q2.add(&Expr::constant(l1 + ratio(1, 2)));
    assert_eq!(
        k.points[2].0,
        reach.mul(&Expr::cos(int(1), Angle::new(vec![1])))
    );
    assert_eq!(k.jacobian[2], vec![Expr::constant(int(1)), Expr::zero()]);
    assert_eq!(k.jacobian[0][1], Expr::cos(int(1), Angle::new(vec![1])));
}

#[test]
fn pairwise_kinetic_energy_is_the_squared_velocities() {
    for n in 1..=5 {
        let arm = uneven_arm(n);
        assert_eq!(
            kinetic_energy(&arm, &standard_bodies(&arm), &mut RateProducts::new()),
            kinetic_energy_by_velocities(&arm),
            "n = {n}"
        );
        // And over the polynomials, every value a parameter.
        let (symbolic, _) = arm.parameterised();
        assert_eq!(
            kinetic_energy(
                &symbolic,
                &standard_bodies(&symbolic),
                &mut RateProducts::new()
            ),
            kinetic_energy_by_velocities(&symbolic),
            "n = {n}, parameters"
        );
    }
}

/// `uneven_arm(n)` with joint `i` reversed where bit `i` of `reversed` is set, and offsets of
/// rational cosine and sine (a Pythagorean angle, a quarter turn, an obtuse one) on the even
/// joints.
pub(crate) fn turned_arm(n: usize, reversed: u32) -> ArmSpec {
    let mut arm = uneven_arm(n);
    let turns = [(3, 4, 5), (0, 1, 1), (-5, 12, 13)];
    for (i, l) in arm.links.iter_mut().enumerate() {
        l.reversed = reversed >> i & 1 == 1;
        if i % 2 == 0 {
            let (c, s, d) = turns[i / 2 % 3];
            l.offset = Some(Offset {
                angle: crate::mechanics::spatial::FixedAngle {
                    radians: Rational::from_float(f64::from(s).atan2(f64::from(c)))
                        .unwrap_or_default(),
                    pi_multiple: int(0),
                },
                cos: ratio(c.into(), d),
                sin: ratio(s.into(), d),
            });
        }
    }
    arm
}

#[test]
fn turned_and_reversed_arms_keep_the_pairwise_form() {
    for n in 1..=4 {
        for reversed in 0..1u32 << n {
            let arm = turned_arm(n, reversed);
            assert!(!arm.plain());
            assert_eq!(
                kinetic_energy(&arm, &standard_bodies(&arm), &mut RateProducts::new()),
                kinetic_energy_by_velocities(&arm),
                "n = {n}, reversed {reversed:b}"
            );
            // M and c of the metric against Lagrange's equation expanded.
            let d = Dynamics::derive(&arm);
            assert_eq!(
                d.mass_matrix,
                d.mass_matrix_from_lagrange(),
                "n = {n}, reversed {reversed:b}"
            );
            assert_eq!(
                d.torques(),
                d.lagrange_torques(),
                "n = {n}, reversed {reversed:b}"
            );
        }
    }
}
