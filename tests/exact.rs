//! `PlanarArm::EXACT`, stored compactly: decoded, it is the engine's derivation term for term,
//! and evaluated it gives the generated methods' numbers.

mod common;

use common::Rng;

use planar_arm::exact::{self, Terms, Trig as ExactTrig, Var as ExactVar};
use planar_arm::nalgebra::SVector;
use planar_arm::prelude::*;
use planar_arm::symbolic::compact::encode;
use planar_arm::symbolic::ring::{ratio, to_i128_pair};
use planar_arm::symbolic::slp::Emit;
use planar_arm::symbolic::{ArmSpec, Dynamics, Expr, JointKind, LinkSpec, PayloadSpec, Trig, Var};

/// One term as comparable plain data: coefficient, kind, angle, powers, parameters.
type Plain = (
    (i128, i128),
    u8,
    Vec<i32>,
    Vec<(u8, usize, u32)>,
    Vec<(String, u32)>,
);

fn engine_terms<C: Emit>(e: &Expr<C>) -> Vec<Plain> {
    let mut out = Vec::new();
    for (m, t, coeff) in e.terms() {
        for (pm, c) in coeff.parts() {
            let (kind, angle) = match t {
                Trig::One => (0, Vec::new()),
                Trig::Cos(a) => (1, a.coefficients().to_vec()),
                Trig::Sin(a) => (2, a.coefficients().to_vec()),
            };
            let powers = m
                .powers()
                .map(|(v, e)| match v {
                    Var::Qd(j) => (0, j, e),
                    Var::Qdd(j) => (1, j, e),
                    Var::Q(j) => (2, j, e),
                })
                .collect();
            let params = pm
                .powers()
                .iter()
                .map(|(p, e)| (p.name().to_string(), *e))
                .collect();
            out.push((to_i128_pair(&c).expect("fits"), kind, angle, powers, params));
        }
    }
    out
}

fn decoded_terms(t: Terms) -> Vec<Plain> {
    t.iter()
        .map(|t| {
            let (kind, angle) = match t.trig {
                ExactTrig::One => (0, Vec::new()),
                ExactTrig::Cos(a) => (1, a.coefficients().collect()),
                ExactTrig::Sin(a) => (2, a.coefficients().collect()),
            };
            let powers = t
                .powers
                .into_iter()
                .map(|(v, e)| match v {
                    ExactVar::Qd(j) => (0, j, e),
                    ExactVar::Qdd(j) => (1, j, e),
                    ExactVar::Q(j) => (2, j, e),
                })
                .collect();
            let params = t
                .params
                .into_iter()
                .map(|(p, e)| (p.to_string(), e))
                .collect();
            (
                (t.coeff.numer(), t.coeff.denom()),
                kind,
                angle,
                powers,
                params,
            )
        })
        .collect()
}

/// Encodes with the engine and reads back with the run-time crate.
fn round_trip<C: Emit>(e: &Expr<C>, names: &mut Vec<String>) -> Terms {
    let code: &'static [u8] = Box::leak(encode(e, names).expect("fits").into_boxed_slice());
    let table: &'static [&'static str] = Box::leak(
        names
            .iter()
            .map(|n| &*Box::leak(n.clone().into_boxed_str()))
            .collect::<Vec<&'static str>>()
            .into_boxed_slice(),
    );
    Terms::from_code(code, table)
}

fn random_arm(rng: &mut Rng, n: usize) -> ArmSpec {
    #[allow(clippy::cast_possible_truncation, clippy::cast_precision_loss)]
    let mut r = |lo: i64, hi: i64| rng.range(lo as f64, (hi + 1) as f64).floor() as i64;
    let links = (0..n)
        .map(|_| LinkSpec {
            length: ratio(r(1, 40), r(1, 9)),
            mass: ratio(r(1, 50), r(1, 7)),
            inertia: ratio(r(0, 30), r(1, 11)),
            com: (ratio(r(-20, 40), r(1, 13)), ratio(r(-5, 5), r(1, 17))),
            armature: ratio(r(0, 3), 10),
            damping: ratio(0, 1),
            frictionloss: ratio(0, 1),
            stiffness: Default::default(),
            springref: Default::default(),
            // About a third prismatic: their displacements are the third kind of variable.
            joint: if r(0, 2) == 0 {
                JointKind::Prismatic
            } else {
                JointKind::Revolute
            },
            range: None,
            offset: None,
            reversed: false,
        })
        .collect();
    ArmSpec {
        links,
        gravity: planar_arm_core::down(ratio(980_665, 100_000)),
        payload: Some(PayloadSpec {
            mass: ratio(r(0, 9), 4),
            inertia: ratio(r(0, 9), 40),
            com: (ratio(r(-3, 3), 10), ratio(r(-3, 3), 10)),
        }),
    }
}

#[test]
fn the_encoding_reads_back_as_the_engines_terms() {
    let mut rng = Rng(0x1234_5678_9abc_def1);
    for n in 1..=6 {
        let arm = random_arm(&mut rng, n);
        let (symbolic, _) = arm.parameterised();
        let literal = Dynamics::derive(&arm);
        let with_params = Dynamics::derive(&symbolic);
        let mut names = Vec::new();
        for e in [&literal.kinetic_energy, &literal.potential_energy]
            .into_iter()
            .chain(&literal.coriolis)
            .chain(literal.mass_matrix.iter().flatten())
        {
            let t = round_trip(e, &mut names);
            assert_eq!(decoded_terms(t), engine_terms(e), "n = {n}");
            assert_eq!(t.len(), e.len());
        }
        assert!(names.is_empty());
        for e in [&with_params.kinetic_energy, &with_params.potential_energy]
            .into_iter()
            .chain(&with_params.gravity)
            .chain(with_params.mass_matrix.iter().flatten())
        {
            let t = round_trip(e, &mut names);
            assert_eq!(decoded_terms(t), engine_terms(e), "n = {n}, parameters");
        }
        assert!(!names.is_empty());
    }
}

#[derive(PlanarArm, Default)]
#[arm(gravity = 981/100)]
struct Paper3 {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 1, mass = 1)]
    fore: Revolute,
    #[arm(length = 1, mass = 1)]
    hand: Revolute,
}

#[derive(PlanarArm)]
#[arm(gravity = 9.81, payload = self.load, payload_com = (0.05, self.offset))]
struct Carrier {
    #[arm(length = 0.4, mass = self.m1, com = (self.cx, 0.01), armature = 0.03)]
    upper: Revolute,
    #[arm(length = self.l2, mass = 1.5, inertia = self.i2)]
    fore: Revolute,
    m1: f64,
    cx: f64,
    l2: f64,
    i2: f64,
    load: f64,
    offset: f64,
}

/// EXACT evaluated against the generated methods (which the other tests check against the
/// numeric reference).
fn check_numbers<A: PlanarArm<N>, const N: usize>(
    arm: &A,
    param: &dyn Fn(&str) -> f64,
    rng: &mut Rng,
) {
    let ex = A::EXACT;
    for _ in 0..20 {
        let (q, qd) = (rng.vector::<N>(3.0), rng.vector::<N>(3.0));
        let (qs, qds) = (q.as_slice(), qd.as_slice());
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-10 * (1.0 + b.abs());
        let m = arm.mass_matrix(&q);
        let c = arm.coriolis(&q, &qd);
        let g = arm.gravity(&q);
        for i in 0..N {
            for j in 0..N {
                let v = exact::eval_with(ex.mass_matrix[i][j], qs, qds, param);
                assert!(close(v, m[(i, j)]), "M{i}{j}: {v} vs {}", m[(i, j)]);
            }
            let v = exact::eval_with(ex.coriolis[i], qs, qds, param);
            assert!(close(v, c[i]), "c{i}: {v} vs {}", c[i]);
            let v = exact::eval_with(ex.gravity[i], qs, qds, param);
            assert!(close(v, g[i]), "g{i}: {v} vs {}", g[i]);
        }
        let t = exact::eval_with(ex.kinetic_energy, qs, qds, param);
        assert!(close(t, arm.kinetic_energy(&q, &qd)));
        let v = exact::eval_with(ex.potential_energy, qs, qds, param);
        assert!(close(v, arm.potential_energy(&q)));
    }
}

#[test]
fn exact_data_gives_the_methods_numbers() {
    let mut rng = Rng(99);
    check_numbers(&Paper3::default(), &|_| f64::NAN, &mut rng);
    let arm = Carrier {
        upper: Revolute,
        fore: Revolute,
        m1: 2.0,
        cx: 0.18,
        l2: 0.3,
        i2: 0.02,
        load: 0.7,
        offset: -0.02,
    };
    let param = |name: &str| match name {
        "m1" => arm.m1,
        "cx" => arm.cx,
        "l2" => arm.l2,
        "i2" => arm.i2,
        "load" => arm.load,
        "offset" => arm.offset,
        _ => f64::NAN,
    };
    check_numbers(&arm, &param, &mut rng);
    let _ = SVector::<f64, 2>::zeros();
    // A prismatic joint's displacement is a polynomial variable of the exact data.
    check_numbers(&Slider::default(), &|_| f64::NAN, &mut rng);
    let m11 = <Slider as PlanarArm<3>>::EXACT.mass_matrix[0][0].to_string();
    assert!(m11.contains("q2^2"), "{m11}");
}

#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81, payload = 0.3)]
struct Slider {
    #[arm(length = 0.3, mass = 2)]
    turret: Revolute,
    #[arm(length = 0.5, mass = 1, com = (0.2, 0.02), armature = 0.1)]
    boom: Prismatic,
    #[arm(length = 0.2, mass = 0.4)]
    wrist: Revolute,
}

#[test]
fn terms_print_and_read_in_const_contexts() {
    const M11: Terms = <Paper3 as PlanarArm<3>>::EXACT.mass_matrix[0][0];
    const LEN: usize = M11.len();
    // Three unit rods: M11 = 3/12 + (1/4) + (1 + 1/4 + c2) + (2 + 1/4 + 2 c2 + c23 + c3).
    const _: () = assert!(LEN == 4);
    assert_eq!(M11.to_string(), "4 + 3 cos(q2) + cos(q2 + q3) + cos(q3)");
    assert_eq!(M11.iter().count(), LEN);
    assert!(exact::cos_coefficient(M11, &[0, 1, 1]).eq(exact::Rational::new(1, 1)));
    assert!(exact::sin_coefficient(M11, &[0, 1]).eq(exact::Rational::ZERO));
    let carried = <Carrier as PlanarArm<2>>::EXACT.mass_matrix[1][1].to_string();
    assert!(carried.contains("load"), "{carried}");
}

#[derive(PlanarArm)]
#[arm(gravity = 0, payload = self.load)]
struct PaperRods {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 1, mass = 1)]
    fore: Revolute,
    load: f64,
}

#[test]
fn the_derivation_prints_as_formulas_and_latex() {
    let d = <PaperRods as PlanarArm<2>>::EXACT;
    let text = d.to_string();
    let lines: Vec<&str> = text.lines().collect();
    // T, V, the upper triangle of M, c1, c2, g1, g2.
    assert_eq!(lines.len(), 2 + 3 + 2 + 2, "{text}");
    // The paper's mass matrix for two unit rods (m = l = 1) with a point load at the tip:
    // the rods give 5/3 + cos q2, 1/3 + 1/2 cos q2 and 1/3; the load adds
    // load (|r1 + r2|^2, r2 . (r1 + r2), |r2|^2) = load (2 + 2 cos q2, 1 + cos q2, 1).
    assert!(
        lines.contains(&"M11 = 5/3 + 2 load + cos(q2) + 2 load cos(q2)"),
        "{text}"
    );
    assert!(
        lines.contains(&"M12 = 1/3 + load + 1/2 cos(q2) + load cos(q2)"),
        "{text}"
    );
    assert!(lines.contains(&"M22 = 1/3 + load"), "{text}");
    assert!(
        lines.contains(&"g1 = 0") && lines.contains(&"V = 0"),
        "{text}"
    );
    assert!(!text.contains("Rational") && !text.contains("numer"));

    let latex = d.latex().to_string();
    assert!(latex.starts_with("\\begin{aligned}\n") && latex.ends_with("\\end{aligned}"));
    assert!(
        latex.contains(
            r"M_{11} &= \frac{5}{3} + 2 \mathrm{load} + \cos q_{2} + 2 \mathrm{load} \cos q_{2} \\"
        ),
        "{latex}"
    );
    // Every formula on its own line, each but the last ended by a LaTeX line break.
    assert_eq!(latex.matches(" &= ").count(), lines.len());
    assert_eq!(latex.matches(" \\\\\n").count(), lines.len() - 1);
    // The velocity products: rates as dots, squares as exponents.
    let c1 = d.coriolis[0].latex().to_string();
    assert!(
        c1.contains(r"\sin q_{2} \dot{q}_{2}^{2}") && c1.contains(r"\dot{q}_{1} \dot{q}_{2}"),
        "{c1}"
    );
}
