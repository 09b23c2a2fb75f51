//! The chosen methods split at their parameter-only frontier ([`crate::frozen`]) compute what
//! the whole ones do, with fewer operations.

use crate::frozen::freeze;
use crate::methods::Derived;
use crate::poly::{Param, Poly};
use crate::ring::ratio;
use crate::slp::{Input, Node};
use crate::{ArmSpec, JointKind, LinkSpec};

fn arm(n: usize) -> ArmSpec<Poly> {
    let lit = ArmSpec::paper(n);
    let p = |s: &str, i: usize| Poly::param(Param::new(&format!("{s}{i}")));
    ArmSpec {
        links: lit
            .links
            .iter()
            .enumerate()
            .map(|(i, l)| LinkSpec {
                length: Poly::constant(l.length.clone()),
                mass: p("m", i),
                inertia: p("i", i),
                com: (p("c", i), Poly::constant(ratio(1, 10))),
                armature: Poly::constant(ratio(0, 1)),
                damping: p("d", i),
                frictionloss: Poly::constant(ratio(0, 1)),
                stiffness: Default::default(),
                springref: Default::default(),
                joint: JointKind::Revolute,
                range: None,
                offset: None,
                reversed: false,
            })
            .collect(),
        gravity: crate::down(Poly::constant(ratio(981, 100))),
        payload: None,
    }
}

fn value(name: &str) -> f64 {
    // Distinct positive values from the name's bytes.
    let h = name
        .bytes()
        .fold(7u32, |h, b| h.wrapping_mul(31).wrapping_add(u32::from(b)));
    f64::from(h % 97 + 3) / 37.0
}

fn input(params: &[crate::Param], frozen: &[f64], i: Input) -> f64 {
    match i {
        Input::Param(k) => value(params[k].name()),
        Input::Frozen(k) => frozen[k],
        Input::Q(j) => 0.3 + 0.7 * f64::from(u32::try_from(j).unwrap_or(0)),
        Input::Qd(j) => -0.4 + 0.5 * f64::from(u32::try_from(j).unwrap_or(0)),
        Input::Qdd(j) | Input::Tau(j) => 1.1 - 0.3 * f64::from(u32::try_from(j).unwrap_or(0)),
        Input::Force(_) | Input::TipTorque | Input::Virtual(_) => 0.0,
    }
}

#[test]
fn split_methods_compute_what_the_whole_ones_do_with_fewer_operations() {
    for n in 1..=4 {
        let d = Derived::new(&arm(n));
        let whole = vec![
            d.mass_matrix_method(),
            d.inverse_dynamics_method(),
            d.forward_dynamics_method(),
            d.mass_matrix_and_bias_method(),
        ];
        let f = freeze(&whole).expect("a parameterised arm has parameter-only work");
        let bp = f.block.program.params();
        let block = f.block.eval(&|i| input(bp, &[], i));
        for (w, s) in whole.iter().zip(&f.methods) {
            let a = w.eval(&|i| input(w.program.params(), &[], i));
            let b = s.eval(&|i| input(s.program.params(), &block, i));
            assert_eq!(a.len(), b.len());
            for (x, y) in a.iter().zip(&b) {
                assert_eq!(x.to_bits(), y.to_bits(), "n={n}: {x} vs {y}");
            }
            let (cw, cs) = (w.op_count(), s.op_count());
            assert!(cs.mul + cs.add < cw.mul + cw.add, "n={n}: {cs} vs {cw}");
            assert!(s
                .program
                .nodes()
                .iter()
                .any(|node| matches!(node, Node::Input(Input::Frozen(_)))));
        }
    }
}

#[test]
fn literal_arms_have_nothing_to_freeze() {
    let d = Derived::new(&ArmSpec::paper(3));
    assert!(freeze(&[d.mass_matrix_method(), d.inverse_dynamics_method()]).is_none());
}
