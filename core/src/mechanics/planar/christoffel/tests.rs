//! Both routes to C against the Christoffel symbols summed one by one, exactly, and the
//! absolute angles' premise (each `Mt_ab` a function of `phi_a - phi_b`) checked on its own.

use super::*;
use crate::mechanics::planar::tests::{christoffel, uneven_arm};
use crate::mechanics::{Dynamics, JointKind};
use crate::poly::Poly;
use crate::trig::Trig;

/// `C = J^T Ct J` with `Ct_ab = D_ab w_b`, `D_ba = -D_ab`, assembled as expressions.
fn assembled<C: Coefficient>(d: &[Vec<Expr<C>>]) -> Vec<Vec<Expr<C>>> {
    let n = d.len();
    let w = |b: usize| {
        let mut w = Expr::zero();
        for k in 0..=b {
            w.add_assign(&Expr::var(Var::Qd(k)));
        }
        w
    };
    let dab = |a: usize, b: usize| match a.cmp(&b) {
        std::cmp::Ordering::Greater => d[a][b].clone(),
        std::cmp::Ordering::Less => d[b][a].scale(&ratio(-1, 1)),
        std::cmp::Ordering::Equal => Expr::zero(),
    };
    (0..n)
        .map(|i| {
            (0..n)
                .map(|j| {
                    let mut c = Expr::zero();
                    for a in i..n {
                        for b in j..n {
                            c.add_assign(&dab(a, b).mul(&w(b)));
                        }
                    }
                    c
                })
                .collect()
        })
        .collect()
}

#[test]
fn both_routes_are_the_christoffel_symbols() {
    for n in 1..=5 {
        let arm = uneven_arm(n);
        let dy = Dynamics::derive(&arm);
        let by_symbols = christoffel(&dy.mass_matrix);
        assert_eq!(expanded(&dy.mass_matrix), by_symbols, "n = {n}");
        let d = absolute_derivatives(&arm, &dy.mass_matrix).expect("all revolute");
        assert_eq!(assembled(&d), by_symbols, "n = {n}");
    }
}

#[test]
fn with_run_time_parameters_too() {
    for n in 1..=4 {
        let (arm, _) = uneven_arm(n).parameterised();
        let dy: Dynamics<Poly> = Dynamics::derive(&arm);
        let d = absolute_derivatives(&arm, &dy.mass_matrix).expect("all revolute");
        assert_eq!(assembled(&d), christoffel(&dy.mass_matrix), "n = {n}");
    }
}

#[test]
fn mixed_chains_take_the_expanded_route() {
    for pattern in 1..8u32 {
        let arm = uneven_arm(3).with_prismatic(pattern);
        let dy = Dynamics::derive(&arm);
        assert!(absolute_derivatives(&arm, &dy.mass_matrix).is_none());
        assert_eq!(expanded(&dy.mass_matrix), christoffel(&dy.mass_matrix));
    }
}

/// The route's premise: below the diagonal, `Mt_ab` has only the atoms of
/// `phi_a - phi_b = q_(b+1) + ... + q_a` and a constant; and it is what `M` is built from.
#[test]
fn the_metric_in_absolute_angles_depends_on_differences() {
    let n = 5;
    let arm = uneven_arm(n);
    assert!(arm.links.iter().all(|l| l.joint == JointKind::Revolute));
    let m = Dynamics::derive(&arm).mass_matrix;
    let at = |i: usize, j: usize| (i < n && j < n).then(|| m[i][j].clone());
    let mt = |a: usize, b: usize| {
        let mut e = m[a][b].clone();
        for (k, x) in [(1, at(a + 1, b)), (1, at(a, b + 1)), (-1, at(a + 1, b + 1))] {
            if let Some(x) = x {
                e = e.sub(&x.scale(&ratio(k, 1)));
            }
        }
        e
    };
    // M_ij = sum_(a >= i, b >= j) Mt_ab.
    for (i, row) in m.iter().enumerate() {
        for (j, mij) in row.iter().enumerate() {
            let mut sum = Expr::zero();
            for a in i..n {
                for b in j..n {
                    sum.add_assign(&mt(a, b));
                }
            }
            assert_eq!(&sum, mij, "M{i}{j}");
        }
    }
    for a in 0..n {
        for b in 0..a {
            let difference = crate::trig::Angle::range(b + 1, a + 1);
            let e = mt(a, b);
            assert!(!e.is_zero(), "Mt{a}{b}");
            for (mono, t, _) in e.terms() {
                assert_eq!(mono.degree(), 0);
                match t {
                    Trig::One => {}
                    Trig::Cos(angle) | Trig::Sin(angle) => {
                        assert_eq!(angle, &difference, "Mt{a}{b}");
                    }
                }
            }
        }
    }
}
