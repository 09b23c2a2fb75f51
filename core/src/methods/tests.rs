//! Tests of the candidate programs: every candidate against the expanded formulas, literal
//! arms against their parameterised twins, for revolute and mixed chains.

mod frozen;

use super::*;
use crate::mechanics::{JointKind, LinkSpec};
use crate::poly::Poly;
use crate::programs::unrolled::Terms;
use crate::ring::ratio;
use crate::slp::Input;

/// An arm with uneven parameters (an offset centre of mass off the link's axis, a
/// counterweight, armature, friction and a payload).
fn arm(n: usize) -> ArmSpec {
    let k = |i: usize| i64::try_from(i).unwrap_or(0);
    ArmSpec {
        links: (0..n)
            .map(|i| LinkSpec {
                length: ratio(k(i) + 3, 4),
                mass: ratio(2 * k(i) + 1, 3),
                inertia: ratio(1, k(i) + 5),
                com: (ratio(k(i % 3) - 1, 2), ratio(k(i % 2), 9)),
                armature: ratio(k(i), 7),
                damping: ratio(1, k(i) + 2),
                frictionloss: ratio(k(i % 2), 3),
                stiffness: Default::default(),
                springref: Default::default(),
                joint: JointKind::Revolute,
                range: None,
                offset: None,
                reversed: false,
            })
            .collect(),
        gravity: crate::down(ratio(981, 100)),
        payload: Some(crate::mechanics::PayloadSpec {
            mass: ratio(3, 4),
            inertia: ratio(1, 50),
            com: (ratio(1, 10), ratio(-1, 20)),
        }),
    }
}

/// The same arm with every value a run-time parameter, and the parameters' values.
fn parameterised(arm: &ArmSpec) -> (ArmSpec<Poly>, Vec<(String, f64)>) {
    let (spec, values) = arm.parameterised();
    let values = values
        .into_iter()
        .map(|(p, r)| {
            (
                p.name().to_string(),
                crate::ring::to_f64(&r).unwrap_or(f64::NAN),
            )
        })
        .collect();
    (spec, values)
}

fn eval_with(m: &Method, n: usize, params: &[(String, f64)]) -> Vec<f64> {
    #[allow(clippy::cast_precision_loss)]
    let at = |j: usize, k: f64| (j as f64 + 1.0).mul_add(0.37, k).sin() * 2.0;
    let names = m.program.params().to_vec();
    m.eval(&|i| match i {
        Input::Q(j) => at(j, 0.1),
        Input::Qd(j) => at(j, 1.3),
        Input::Qdd(j) => at(j, 2.9),
        Input::Tau(j) => at(j + n, 4.1) * 10.0,
        Input::Force(_) | Input::TipTorque | Input::Frozen(_) | Input::Virtual(_) => 0.0,
        Input::Param(k) => params
            .iter()
            .find(|(name, _)| name == names[k].name())
            .map_or(f64::NAN, |p| p.1),
    })
}

fn eval(m: &Method, n: usize) -> Vec<f64> {
    eval_with(m, n, &[])
}

#[test]
fn parameters_give_the_literal_numbers() {
    for n in 1..=4 {
        let literal = Derived::new(&arm(n));
        let (spec, values) = parameterised(&arm(n));
        let symbolic = Derived::new(&spec);
        let pairs = [
            (literal.mass_matrix_method(), symbolic.mass_matrix_method()),
            (literal.coriolis_method(), symbolic.coriolis_method()),
            (literal.gravity_method(), symbolic.gravity_method()),
            (literal.friction_method(), symbolic.friction_method()),
            (
                literal.inverse_dynamics_method(),
                symbolic.inverse_dynamics_method(),
            ),
            (
                literal.forward_dynamics_method(),
                symbolic.forward_dynamics_method(),
            ),
            (
                literal.kinetic_energy_method(),
                symbolic.kinetic_energy_method(),
            ),
            (
                literal.potential_energy_method(),
                symbolic.potential_energy_method(),
            ),
            (literal.jacobian_method(), symbolic.jacobian_method()),
        ];
        for (k, (a, b)) in pairs.iter().enumerate() {
            // (A single link has no velocity-product torque.)
            let coriolis_of_one = n == 1 && k == 1;
            assert!(
                coriolis_of_one || !b.program.params().is_empty(),
                "method {k} reads no parameter"
            );
            same(
                &eval(a, n),
                &eval_with(b, n, &values),
                "literal vs parameters",
            );
        }
        // The Lagrangian over polynomials, evaluated, is the one over the rationals.
        let candidates = [
            (
                symbolic.inverse_dynamics_lagrange_method(),
                symbolic.inverse_dynamics_newton_euler_method(),
            ),
            (
                symbolic.mass_matrix_expanded_method(),
                symbolic.mass_matrix_composite_method(),
            ),
        ];
        for (a, b) in &candidates {
            same(
                &eval_with(a, n, &values),
                &eval_with(b, n, &values),
                "candidates",
            );
        }
    }
}

#[track_caller]
fn same(a: &[f64], b: &[f64], what: &str) {
    let scale = a.iter().chain(b).fold(1.0_f64, |m, x| m.max(x.abs()));
    for (x, y) in a.iter().zip(b) {
        assert!((x - y).abs() <= 1e-11 * scale, "{what}: {a:?} vs {b:?}");
    }
}

#[test]
fn every_candidate_agrees() {
    for n in 1..=7 {
        let d = Derived::new(&arm(n));
        let tau = eval(&d.inverse_dynamics_lagrange_method(), n);
        same(
            &tau,
            &eval(&d.inverse_dynamics_newton_euler_method(), n),
            "tau",
        );
        let m = eval(&d.mass_matrix_expanded_method(), n);
        same(&m, &eval(&d.mass_matrix_composite_method(), n), "M");
        same(
            &eval(&d.vector_method("c", &d.dynamics.coriolis), n),
            &eval(&d.newton_euler_method("c", Terms::CORIOLIS), n),
            "c",
        );
        same(
            &eval(&d.vector_method("g", &d.dynamics.gravity), n),
            &eval(&d.newton_euler_method("g", Terms::GRAVITY), n),
            "g",
        );
        let fd = eval(&d.forward_dynamics_with(false, false, false), n);
        for k in 1..8 {
            let with = d.forward_dynamics_with(k & 1 == 1, k & 2 == 2, k & 4 == 4);
            same(&fd, &eval(&with, n), "qdd");
        }
    }
}

/// For every joint pattern of 1-4 links and a few longer ones, the unrolled recursions
/// (the Newton-Euler torques, the mass matrix by unit accelerations) and forward dynamics
/// agree with the expanded Lagrangian, over the rationals and over parameters.
#[test]
fn prismatic_candidates_agree() {
    let patterns = (1..=4)
        .flat_map(|n| (1..1u32 << n).map(move |p| (n, p)))
        .chain([(6, 0b10_1010), (7, 0b110_0001)]);
    for (n, pattern) in patterns {
        let spec = arm(n).with_prismatic(pattern);
        let d = Derived::new(&spec);
        let what = format!("n = {n}, joints {pattern:b}");
        let tau = eval(&d.inverse_dynamics_lagrange_method(), n);
        same(
            &tau,
            &eval(&d.inverse_dynamics_newton_euler_method(), n),
            &what,
        );
        let m = eval(&d.mass_matrix_expanded_method(), n);
        same(&m, &eval(&d.mass_matrix_composite_method(), n), &what);
        same(
            &eval(&d.vector_method("c", &d.dynamics.coriolis), n),
            &eval(&d.newton_euler_method("c", Terms::CORIOLIS), n),
            &what,
        );
        same(
            &eval(&d.vector_method("g", &d.dynamics.gravity), n),
            &eval(&d.newton_euler_method("g", Terms::GRAVITY), n),
            &what,
        );
        let fd = eval(&d.forward_dynamics_with(false, false, false), n);
        for k in 1..8 {
            let with = d.forward_dynamics_with(k & 1 == 1, k & 2 == 2, k & 4 == 4);
            same(&fd, &eval(&with, n), &what);
        }
        if n <= 3 {
            let (symbolic, values) = parameterised(&spec);
            let s = Derived::new(&symbolic);
            same(
                &tau,
                &eval_with(&s.inverse_dynamics_newton_euler_method(), n, &values),
                &what,
            );
            same(&m, &eval_with(&s.mass_matrix_method(), n, &values), &what);
        }
    }
}

#[test]
#[ignore = "prints a table"]
fn print_op_counts() {
    for n in 1..=8 {
        let d = Derived::new(&arm(n));
        let show = |m: Method| format!("{} depth {} cost {}", m.op_count(), m.depth(), cost(&m));
        println!("N = {n}");
        println!(
            "  tau lagrange     {}",
            show(d.inverse_dynamics_lagrange_method())
        );
        println!(
            "  tau newton-euler {}",
            show(d.inverse_dynamics_newton_euler_method())
        );
        println!(
            "  M expanded       {}",
            show(d.mass_matrix_expanded_method())
        );
        println!(
            "  M composite      {}",
            show(d.mass_matrix_composite_method())
        );
        println!(
            "  c expanded       {}",
            show(d.vector_method("c", &d.dynamics.coriolis))
        );
        println!(
            "  c newton-euler   {}",
            show(d.newton_euler_method("c", Terms::CORIOLIS))
        );
        println!(
            "  g expanded       {}",
            show(d.vector_method("g", &d.dynamics.gravity))
        );
        println!(
            "  g recursion      {}",
            show(d.newton_euler_method("g", Terms::GRAVITY))
        );
        for k in 0..8 {
            let (a, b, c) = (k & 1 == 1, k & 2 == 2, k & 4 == 4);
            let fd = d.forward_dynamics_with(a, b, c);
            println!("  fd M-crba={a} c-rnea={b} g-rec={c} {}", show(fd));
        }
    }
}
