//! Tests of the regressor and the exact base parameters: exact against the torques, the
//! energies' elimination against the torques', groupings with run-time lengths.

use super::*;
use crate::methods::identification::poly_arm;
use crate::ring::{int, ratio};

fn arm(n: usize, gravity: bool, armature: bool, payload: bool) -> ArmSpec {
    let mut a = ArmSpec::paper(n);
    a.gravity = crate::down(if gravity { ratio(981, 100) } else { int(0) });
    for (i, l) in a.links.iter_mut().enumerate() {
        let i = i64::try_from(i).unwrap_or(0);
        l.length = ratio(i + 3, 4);
        l.mass = ratio(2 * i + 3, 2);
        l.inertia = ratio(1, i + 7);
        l.com = (ratio(i + 1, 5), ratio(1 - i, 9));
        if armature {
            l.armature = ratio(i + 1, 20);
            l.damping = ratio(i + 2, 10);
        }
    }
    if payload {
        a.payload = Some(crate::mechanics::PayloadSpec {
            mass: ratio(1, 2),
            inertia: ratio(1, 50),
            com: (ratio(1, 10), ratio(-1, 20)),
        });
    }
    a
}

/// `sum_k columns[k] values[k]`, without the damping columns (the Lagrangian torques have
/// no friction).
fn combine(reg: &Regressor<Poly>, values: &[(usize, Rational)], n: usize) -> Vec<Expr<Poly>> {
    (0..n)
        .map(|i| {
            let mut t = Expr::zero();
            for (k, v) in values {
                if reg.parameters[*k].kind != Kind::Damping {
                    t.add_assign(&reg.columns[*k][i].scale(v));
                }
            }
            t
        })
        .collect()
}

/// Joint patterns to test (bit `i` set: joint `i` prismatic): all of them up to three
/// links.
fn patterns(n: usize) -> Vec<u32> {
    if n <= 3 {
        (0..1 << n).collect()
    } else {
        vec![0, 0b0101, 0b1010]
    }
}

#[test]
fn regressor_times_standard_parameters_is_the_torque_exactly() {
    for (n, pattern) in (1..=4).flat_map(|n| patterns(n).into_iter().map(move |p| (n, p))) {
        for (g, a, p) in [
            (true, false, false),
            (true, true, true),
            (false, true, false),
        ] {
            let literal = arm(n, g, a, p).with_prismatic(pattern);
            let reg = regressor(&poly_arm(&literal));
            let values = standard_values(&literal, &reg.parameters);
            let torques = Dynamics::derive(&poly_arm(&literal)).torques();
            let pairs: Vec<(usize, Rational)> = values.into_iter().enumerate().collect();
            assert_eq!(combine(&reg, &pairs, n), torques, "n = {n}");
            // And with the base parameters.
            let base = base_parameters(&reg).expect("rational");
            let standard = standard_values(&literal, &reg.parameters);
            let base_values: Vec<(usize, Rational)> = base
                .columns
                .iter()
                .zip(&base.grouping)
                .map(|(&c, group)| {
                    let v = group.iter().fold(Rational::zero(), |acc, (k, x)| {
                        acc + x.clone() * standard[*k].clone()
                    });
                    (c, v)
                })
                .collect();
            assert_eq!(combine(&reg, &base_values, n), torques, "n = {n}, base");
        }
    }
}

#[test]
fn energies_give_the_torques_base_parameters() {
    for (n, pattern) in (1..=4).flat_map(|n| patterns(n).into_iter().map(move |p| (n, p))) {
        for (g, a, p) in [
            (true, false, false),
            (true, true, true),
            (false, true, true),
        ] {
            let arm = poly_arm(&arm(n, g, a, p).with_prismatic(pattern));
            let reg = regressor(&arm);
            let from_torques = base_parameters(&reg).expect("rational");
            let (params, from_energies) = base_parameters_from_energies(&arm).expect("rational");
            assert_eq!(params[..reg.parameters.len()], reg.parameters[..]);
            assert_eq!(from_energies.columns, from_torques.columns, "n = {n}");
            assert_eq!(
                from_energies.grouping,
                from_torques.into_poly().grouping,
                "n = {n}"
            );
        }
    }
}

#[test]
fn run_time_lengths_give_the_rational_groupings_as_polynomials() {
    // Lengths l1, l2, l3 as symbols: the columns and the groupings are those of any
    // numeric lengths, with the numbers replaced by the polynomials Gautier and Khalil's
    // rules give (zz1 + l1^2 (m2 + m3), mx1 + l1 (m2 + m3), ...).
    for (g, a, p) in [
        (true, false, false),
        (true, true, true),
        (false, true, true),
    ] {
        let numeric = poly_arm(&arm(3, g, a, p));
        let mut symbolic = numeric.clone();
        for (i, l) in symbolic.links.iter_mut().enumerate() {
            l.length = param(&format!("l{}", i + 1));
        }
        if !g {
            // Without gravity the first moments enter only through l_i cos(..) terms:
            // no numeric pivot, so no polynomial groupings.
            assert!(base_parameters_from_energies(&symbolic).is_none());
            continue;
        }
        let (_, with_numbers) = base_parameters_from_energies(&numeric).expect("rational");
        let (params, with_symbols) = base_parameters_from_energies(&symbolic).expect("polynomial");
        assert_eq!(with_symbols.columns, with_numbers.columns);
        let lengths = [ratio(3, 4), int(1), ratio(5, 4)];
        let at = |c: &Poly| -> Rational {
            c.parts().iter().fold(Rational::zero(), |acc, (m, r)| {
                let mut x = r.clone();
                for (p, e) in m.powers() {
                    let i: usize = p.to_string()[1..].parse().expect("l<i>");
                    for _ in 0..*e {
                        x *= lengths[i - 1].clone();
                    }
                }
                acc + x
            })
        };
        for (gs, gn) in with_symbols.grouping.iter().zip(&with_numbers.grouping) {
            let substituted: Vec<(usize, Rational)> = gs.iter().map(|(k, c)| (*k, at(c))).collect();
            let numbers: Vec<(usize, Rational)> = gn
                .iter()
                .map(|(k, c)| (*k, c.as_rational().expect("number")))
                .collect();
            assert_eq!(substituted, numbers);
        }
        let f = |b: usize| with_symbols.formula(b, &params);
        // (+ l1^2 mp with the payload, + ia1 with armature)
        assert!(f(0).starts_with("zz1 + l1^2 m2 + l1^2 m3"), "{}", f(0));
        assert!(f(1).starts_with("mx1 + l1 m2 + l1 m3"), "{}", f(1));
    }
    // A run-time gravity: the first moments of link 1 would need dividing by it.
    let mut free = poly_arm(&arm(2, true, false, false));
    free.gravity = crate::down(param("g"));
    assert!(base_parameters_from_energies(&free).is_none());
}

#[test]
fn base_parameters_are_three_per_link_and_group_the_classical_way() {
    for n in 1..=5 {
        let reg = regressor(&poly_arm(&arm(n, true, false, false)));
        let base = base_parameters(&reg).expect("rational");
        assert_eq!(base.columns.len(), 3 * n, "n = {n}, gravity");
        let reg = regressor(&poly_arm(&arm(n, false, false, false)));
        let base = base_parameters(&reg).expect("rational");
        assert_eq!(base.columns.len(), 3 * n - 2, "n = {n}, no gravity");
        // Armature: ia1 joins zz1, the others are their own; damping is its own.
        let reg = regressor(&poly_arm(&arm(n, true, true, false)));
        let base = base_parameters(&reg).expect("rational");
        assert_eq!(base.columns.len(), 3 * n + (n - 1) + n, "n = {n}, armature");
    }
    // Gautier and Khalil's grouping for three links of lengths 3/4, 1, 5/4 with gravity:
    // zz1R = zz1 + l1^2 (m2 + m3), mx1R = mx1 + l1 (m2 + m3), zz2R = zz2 + l2^2 m3, ...
    let reg = regressor(&poly_arm(&arm(3, true, false, false)));
    let base = base_parameters(&reg).expect("rational");
    let f = |b: usize| base.formula(b, &reg.parameters);
    assert_eq!(f(0), "zz1 + 9/16 m2 + 9/16 m3");
    assert_eq!(f(1), "mx1 + 3/4 m2 + 3/4 m3");
    assert_eq!(f(2), "my1");
    assert_eq!(f(3), "zz2 + m3");
    assert_eq!(f(4), "mx2 + m3");
    assert_eq!(f(6), "zz3");
}
