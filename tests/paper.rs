//! The paper's two- and three-link results, checked exactly against the crate's symbolic engine.
//!
//! Source: B. K. P. Horn, *Kinematics, Statics, and Dynamics of Two-D Manipulators* (MIT AI
//! working paper; OCR text in `shared/paper/two-d-manipulators.md`). `docs/paper_expected.md`
//! lists the expected values and every row of `docs/errata.md` names the test here that checks
//! it: the derived value is asserted, and so is the fact that the printed one differs.
//!
//! Every comparison is exact. Expressions are compared structurally (the engine's form is
//! canonical, so two expressions are equal exactly when they are the same function), and
//! numbers are rationals obtained by evaluating at the docs' test point P: all joint angles
//! equal to `alpha = atan2(4, 3)`, so every sine and cosine is rational.
//!
//! Normalisation: the paper writes `L = (1/2) m l^2 L'`; with `m = l = 1` that is `L' = 2 L`,
//! `M' = 2 M` and `c' = 2 c`.

use std::ops::{Add, Mul, Neg, Sub};

use planar_arm::exact::{constant_term, cos_coefficient, Rational as ConstRational, Terms};
use planar_arm::kinematics::{ik3, DexterousWorkspace};
use planar_arm::prelude::*;
use planar_arm::symbolic::ring::{int, ratio};
use planar_arm::symbolic::{
    Angle, ArmSpec, Dynamics, Expr, Kinematics, LinkSpec, Monomial, Rational, Trig, Var,
};

// ---------------------------------------------------------------------------------------------
// Angles in the paper's subscript notation (index 0 multiplies q1).

const Q1: &[i32] = &[1];
const Q2: &[i32] = &[0, 1];
const Q3: &[i32] = &[0, 0, 1];
const Q12: &[i32] = &[1, 1];
const Q23: &[i32] = &[0, 1, 1];
const Q123: &[i32] = &[1, 1, 1];

// ---------------------------------------------------------------------------------------------
// A thin operator wrapper so that the paper's formulas can be written as formulas.

#[derive(Clone, Debug, PartialEq)]
struct E(Expr);

impl Add for E {
    type Output = E;
    fn add(self, other: E) -> E {
        E(self.0.add(&other.0))
    }
}

impl Sub for E {
    type Output = E;
    fn sub(self, other: E) -> E {
        E(self.0.sub(&other.0))
    }
}

impl Mul for E {
    type Output = E;
    fn mul(self, other: E) -> E {
        E(self.0.mul(&other.0))
    }
}

impl Mul<E> for i64 {
    type Output = E;
    fn mul(self, e: E) -> E {
        E(e.0.scale(&int(self)))
    }
}

impl Neg for E {
    type Output = E;
    fn neg(self) -> E {
        E(self.0.scale(&int(-1)))
    }
}

/// The integer `n`.
fn k(n: i64) -> E {
    E(Expr::constant(int(n)))
}

/// The fraction `n / d`.
fn fr(n: i64, d: i64) -> E {
    E(Expr::constant(ratio(n, d)))
}

/// A rational constant.
fn rat(x: &Rational) -> E {
    E(Expr::constant(x.clone()))
}

/// `cos` of an angle such as [`Q23`].
fn c(angle: &[i32]) -> E {
    E(Expr::cos(int(1), Angle::new(angle.to_vec())))
}

/// `sin` of an angle such as [`Q23`].
fn s(angle: &[i32]) -> E {
    E(Expr::sin(int(1), Angle::new(angle.to_vec())))
}

/// The paper's `theta-dot_i` (1-based).
fn qd(i: usize) -> E {
    E(Expr::var(Var::Qd(i - 1)))
}

/// The paper's `theta-double-dot_i` (1-based).
fn qdd(i: usize) -> E {
    E(Expr::var(Var::Qdd(i - 1)))
}

#[track_caller]
fn same(engine: &Expr, expected: &E, what: &str) {
    assert!(
        *engine == expected.0,
        "{what}:\n  engine:   {engine}\n  expected: {}",
        expected.0
    );
}

#[track_caller]
fn differs(engine: &Expr, printed: &E, what: &str) {
    assert!(
        *engine != printed.0,
        "{what}: the printed form {} agrees with the engine",
        printed.0
    );
}

// ---------------------------------------------------------------------------------------------
// Exact evaluation.

/// `(cos m alpha, sin m alpha)` for `alpha = atan2(4, 3)`: the powers of `(3 + 4i) / 5`.
fn cis(m: i32) -> (Rational, Rational) {
    let step = (ratio(3, 5), ratio(i64::from(m.signum()) * 4, 5));
    let (mut cos, mut sin) = (int(1), int(0));
    for _ in 0..m.unsigned_abs() {
        (cos, sin) = (
            &cos * &step.0 - &sin * &step.1,
            &cos * &step.1 + &sin * &step.0,
        );
    }
    (cos, sin)
}

/// The exact value at P: every joint angle `alpha`, rates `qd`, accelerations `qdd`.
fn at_p(e: &Expr, qd: &[i64], qdd: &[i64]) -> Rational {
    let mut total = int(0);
    for (monomial, trig, coefficient) in e.terms() {
        let sum = |a: &Angle| a.coefficients().iter().sum::<i32>();
        let t = match trig {
            Trig::One => int(1),
            Trig::Cos(a) => cis(sum(a)).0,
            Trig::Sin(a) => cis(sum(a)).1,
        };
        let mut m = int(1);
        for (v, power) in monomial.powers() {
            let x = match v {
                Var::Qd(j) => int(qd[j]),
                Var::Qdd(j) => int(qdd[j]),
                Var::Q(_) => panic!("the paper's arms have no prismatic joint"),
            };
            for _ in 0..power {
                m = &m * &x;
            }
        }
        total += coefficient * &t * &m;
    }
    total
}

/// The exact value at P of a function of the angles alone.
fn at_p0(e: &Expr) -> Rational {
    at_p(e, &[], &[])
}

/// The exact value of a function of `q2` alone that holds only cosines, given `cos q2`:
/// `cos(k q2) = T_k(cos q2)` (Chebyshev).
fn at_cos_q2(e: &Expr, c2: &Rational) -> Rational {
    let chebyshev = |n: i32| {
        let (mut a, mut b) = (int(1), c2.clone());
        for _ in 0..n {
            (a, b) = (b.clone(), int(2) * c2 * &b - &a);
        }
        a
    };
    let mut total = int(0);
    for (monomial, trig, coefficient) in e.terms() {
        assert_eq!(*monomial, Monomial::one(), "{e} depends on the rates");
        let t = match trig {
            Trig::One => int(1),
            Trig::Cos(a) if a.coefficients().len() == 2 && a.coefficient(0) == 0 => {
                chebyshev(a.coefficient(1))
            }
            other => panic!("{e} holds {other}, not a cosine of a multiple of q2"),
        };
        total += coefficient * &t;
    }
    total
}

fn rats(values: &[(i64, i64)]) -> Vec<Rational> {
    values.iter().map(|&(n, d)| ratio(n, d)).collect()
}

// ---------------------------------------------------------------------------------------------
// Matrices of expressions.

type Matrix = Vec<Vec<Expr>>;

fn det2(m: &Matrix) -> Expr {
    m[0][0].mul(&m[1][1]).sub(&m[0][1].mul(&m[1][0]))
}

fn det3(m: &Matrix) -> Expr {
    let minor = |r: usize, c: usize| {
        let rows: Vec<usize> = (0..3).filter(|&i| i != r).collect();
        let cols: Vec<usize> = (0..3).filter(|&j| j != c).collect();
        det2(&vec![
            vec![m[rows[0]][cols[0]].clone(), m[rows[0]][cols[1]].clone()],
            vec![m[rows[1]][cols[0]].clone(), m[rows[1]][cols[1]].clone()],
        ])
    };
    m[0][0]
        .mul(&minor(0, 0))
        .sub(&m[0][1].mul(&minor(0, 1)))
        .add(&m[0][2].mul(&minor(0, 2)))
}

fn matmul(a: &Matrix, b: &Matrix) -> Matrix {
    (0..a.len())
        .map(|i| {
            (0..b[0].len())
                .map(|j| (0..b.len()).fold(Expr::zero(), |acc, k| acc.add(&a[i][k].mul(&b[k][j]))))
                .collect()
        })
        .collect()
}

fn diagonal(n: usize, d: &Expr) -> Matrix {
    (0..n)
        .map(|i| {
            (0..n)
                .map(|j| if i == j { d.clone() } else { Expr::zero() })
                .collect()
        })
        .collect()
}

fn matrix(rows: Vec<Vec<E>>) -> Matrix {
    rows.into_iter()
        .map(|row| row.into_iter().map(|e| e.0).collect())
        .collect()
}

fn scale_matrix(m: &Matrix, r: &Rational) -> Matrix {
    m.iter()
        .map(|row| row.iter().map(|e| e.scale(r)).collect())
        .collect()
}

fn at_p_matrix(m: &Matrix) -> Vec<Vec<Rational>> {
    m.iter()
        .map(|row| row.iter().map(at_p0).collect())
        .collect()
}

// ---------------------------------------------------------------------------------------------
// Arms.

/// Uniform rods with the given lengths and masses.
fn rods(lengths: &[Rational], masses: &[Rational], gravity: Rational) -> ArmSpec {
    ArmSpec {
        links: lengths
            .iter()
            .zip(masses)
            .map(|(l, m)| LinkSpec::rod(l.clone(), m.clone()))
            .collect(),
        gravity: planar_arm_core::down(gravity),
        payload: None,
    }
}

/// The paper's `n` equal rods, `m = l = 1`, no gravity.
fn paper(n: usize) -> Dynamics {
    Dynamics::derive(&ArmSpec::paper(n))
}

/// `L' = 2 L`, `M' = 2 M`, ... for `m = l = 1`.
fn primed(e: &Expr) -> Expr {
    e.scale(&int(2))
}

/// The velocity part of `d/dt (dL/dqd_i)`: the terms without an acceleration.
fn momentum_rate_velocity_part(d: &Dynamics, i: usize) -> Expr {
    d.lagrangian()
        .diff_var(Var::Qd(i))
        .dt(d.n)
        .filter(|m| m.powers().all(|(v, _)| matches!(v, Var::Qd(_))))
}

/// The paper's three equal links for the const checks (m = l = 1, no gravity).
#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 0)]
struct Paper3 {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 1, mass = 1)]
    fore: Revolute,
    #[arm(length = 1, mass = 1)]
    hand: Revolute,
}

/// The paper's two equal links for the const checks.
#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 0)]
struct Paper2 {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 1, mass = 1)]
    fore: Revolute,
}

/// `l3 < |l1 - l2|`: the usable work-space is an annulus (erratum 5).
#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 0)]
struct ShortHand {
    #[arm(length = 2, mass = 1)]
    upper: Revolute,
    #[arm(length = 1, mass = 1)]
    fore: Revolute,
    #[arm(length = 1/2, mass = 1)]
    hand: Revolute,
}

// ---------------------------------------------------------------------------------------------
// Compile-time checks on the derived arms' exact data (`PlanarArm::EXACT`).

const PAPER3_M12: Terms = <Paper3 as PlanarArm<3>>::EXACT.mass_matrix[0][1];
const PAPER3_M33: Terms = <Paper3 as PlanarArm<3>>::EXACT.mass_matrix[2][2];
const PAPER2_M22: Terms = <Paper2 as PlanarArm<2>>::EXACT.mass_matrix[1][1];

/// `2 x` (the paper's primed units), in a const context.
const fn twice(x: ConstRational) -> ConstRational {
    ConstRational::new(2 * x.numer(), x.denom())
}

/// Errata 8 and 9, checked by the compiler on a derived three-equal-link arm: the SI entry
/// `M12 = 5/3 + (3/2) c2 + (1/2) c23 + c3`, so `M'12 = 10/3 + 3 c2 + c23 + 2 c3`, not the
/// printed `19/3 + ...`; and `M'33 = 2/3` (a slot the OCR garbled). Erratum 2: the two-link
/// `M'22 = 2/3`, not `2(7/3)`.
const M12_IS_10_3_NOT_19_3: () = {
    assert!(constant_term(PAPER3_M12).eq(ConstRational::new(5, 3)));
    assert!(twice(constant_term(PAPER3_M12)).eq(ConstRational::new(10, 3)));
    assert!(!twice(constant_term(PAPER3_M12)).eq(ConstRational::new(19, 3)));
    assert!(cos_coefficient(PAPER3_M12, Q2).eq(ConstRational::new(3, 2)));
    assert!(cos_coefficient(PAPER3_M12, Q23).eq(ConstRational::new(1, 2)));
    assert!(cos_coefficient(PAPER3_M12, Q3).eq(ConstRational::new(1, 1)));
    assert!(PAPER3_M33.len() == 1);
    assert!(twice(constant_term(PAPER3_M33)).eq(ConstRational::new(2, 3)));
    assert!(PAPER2_M22.len() == 1);
    assert!(twice(constant_term(PAPER2_M22)).eq(ConstRational::new(2, 3)));
    assert!(!twice(constant_term(PAPER2_M22)).eq(ConstRational::new(14, 3)));
};
const _: () = M12_IS_10_3_NOT_19_3;

#[test]
fn exact_const_data_matches_the_engine() {
    // The const data the compiler checked above is the engine's own derivation.
    let d = paper(3);
    let m12 = &d.mass_matrix[0][1];
    assert_eq!(m12.len(), PAPER3_M12.len());
    assert_eq!(m12.constant_term(), Some(&ratio(5, 3)));
    for (angle, value) in [(Q2, (3, 2)), (Q23, (1, 2)), (Q3, (1, 1))] {
        let atom = Trig::Cos(Angle::new(angle.to_vec()));
        assert_eq!(m12.coefficient(&atom), Some(&ratio(value.0, value.1)));
        let exact = cos_coefficient(PAPER3_M12, angle);
        assert_eq!(
            (exact.numer(), exact.denom()),
            (i128::from(value.0), i128::from(value.1))
        );
    }
}

// ---------------------------------------------------------------------------------------------
// Two links: kinematics and statics.

/// Erratum 1. Also `r^2`, the inverse rotation, the paper's `tan theta`, `sin q1`, `cos q1` and
/// `l1 + l2 cos q2` identities, and the test point's tip.
#[test]
fn two_link_forward_kinematics() {
    let (l1, l2) = (ratio(7, 4), ratio(2, 5));
    let kin = Kinematics::derive(&rods(
        &[l1.clone(), l2.clone()],
        &rats(&[(1, 1); 2]),
        int(0),
    ));
    let (x, y) = &kin.points[2];
    let reach = || rat(&l1) + rat(&l2) * c(Q2);
    let derived_x = reach() * c(Q1) - rat(&l2) * s(Q2) * s(Q1);
    let printed_x = reach() * c(Q1) - rat(&l2) * s(Q2);
    same(x, &derived_x, "x");
    differs(x, &printed_x, "x (erratum 1)");
    same(y, &(reach() * s(Q1) + rat(&l2) * s(Q2) * c(Q1)), "y");
    // r^2 = l1^2 + 2 l1 l2 cos q2 + l2^2, independent of q1.
    let r2 = rat(&(&l1 * &l1 + &l2 * &l2)) + 2 * rat(&(&l1 * &l2)) * c(Q2);
    same(&kin.radius_squared, &r2, "r^2");
    // The inverse rotation: x c1 + y s1 = l1 + l2 c2 and -x s1 + y c1 = l2 s2.
    let (xe, ye) = (E(x.clone()), E(y.clone()));
    same(
        &(xe.clone() * c(Q1) + ye.clone() * s(Q1)).0,
        &reach(),
        "x c1 + y s1",
    );
    same(
        &(-(xe * s(Q1)) + ye * c(Q1)).0,
        &(rat(&l2) * s(Q2)),
        "-x s1 + y c1",
    );

    // The printed tan theta = y / x quotient has exactly these x and y as denominator and
    // numerator (so only the x of the algebraic solution lost its sin q1).
    let (xe, ye) = (E(x.clone()), E(y.clone()));
    // sin q1 and cos q1 over x^2 + y^2 (hence tan q1), and l1 + l2 cos q2 from r^2.
    let r2e = E(kin.radius_squared.clone());
    same(
        &(r2e.clone() * s(Q1)).0,
        &(-(rat(&l2) * s(Q2) * xe.clone()) + reach() * ye.clone()),
        "(x^2 + y^2) sin q1",
    );
    same(
        &(r2e.clone() * c(Q1)).0,
        &(rat(&l2) * s(Q2) * ye + reach() * xe),
        "(x^2 + y^2) cos q1",
    );
    same(
        &(2 * rat(&l1) * reach()).0,
        &(r2e + rat(&(&l1 * &l1 - &l2 * &l2))),
        "2 l1 (l1 + l2 cos q2) = r^2 + l1^2 - l2^2",
    );

    // At P with l1 = l2 = 1: tip (8/25, 44/25), r^2 = 2 + 2 c2 = 16/5.
    let unit = Kinematics::derive(&ArmSpec::paper(2));
    let (x, y) = &unit.points[2];
    assert_eq!((at_p0(x), at_p0(y)), (ratio(8, 25), ratio(44, 25)));
    assert_eq!(at_p0(&unit.radius_squared), ratio(16, 5));
    same(
        &unit.radius_squared,
        &(k(2) + 2 * c(Q2)),
        "r^2, equal links",
    );
}

/// The paper's two-link statics (correct as printed): `T = A (u, v)` with `A = J^T`, and the
/// inverse with divisor `l1 l2 sin q2`.
#[test]
fn two_link_statics() {
    let (l1, l2) = (ratio(7, 4), ratio(2, 5));
    let kin = Kinematics::derive(&rods(
        &[l1.clone(), l2.clone()],
        &rats(&[(1, 1); 2]),
        int(0),
    ));
    let a: Matrix = (0..2)
        .map(|i| vec![kin.jacobian[0][i].clone(), kin.jacobian[1][i].clone()])
        .collect();
    let (l1e, l2e) = (|| rat(&l1), || rat(&l2));
    // T1 = [l1 c1 + l2 c12] v - [l1 s1 + l2 s12] u and T2 = [l2 c12] v - [l2 s12] u.
    let printed_a = matrix(vec![
        vec![
            -(l1e() * s(Q1) + l2e() * s(Q12)),
            l1e() * c(Q1) + l2e() * c(Q12),
        ],
        vec![-(l2e() * s(Q12)), l2e() * c(Q12)],
    ]);
    assert_eq!(a, printed_a);
    let det = l1e() * l2e() * s(Q2);
    same(&det2(&a), &det, "det A");
    // u = {l2 c12 T1 - [l1 c1 + l2 c12] T2} / (l1 l2 s2), v likewise with sines.
    let printed_inverse = matrix(vec![
        vec![l2e() * c(Q12), -(l1e() * c(Q1) + l2e() * c(Q12))],
        vec![l2e() * s(Q12), -(l1e() * s(Q1) + l2e() * s(Q12))],
    ]);
    assert_eq!(matmul(&printed_inverse, &a), diagonal(2, &det.0));
    assert_eq!(matmul(&a, &printed_inverse), diagonal(2, &det.0));
}

// ---------------------------------------------------------------------------------------------
// Two links: dynamics.

/// `L' = (5/3 + c2) qd1^2 + (2/3 + c2) qd1 qd2 + (1/3) qd2^2`, its parts and derivatives.
#[test]
fn two_link_lagrangian_equal_links() {
    let d = paper(2);
    assert!(d.potential_energy.is_zero());
    let l_prime = primed(&d.lagrangian());
    let expected = qd(1) * qd(1) * (fr(5, 3) + c(Q2))
        + qd(1) * qd(2) * (fr(2, 3) + c(Q2))
        + fr(1, 3) * qd(2) * qd(2);
    same(&l_prime, &expected, "L'");
    assert_eq!(at_p(&l_prime, &[1, 2], &[]), ratio(92, 15));
    assert_eq!(at_p(&d.kinetic_energy, &[1, 2], &[]), ratio(46, 15));

    // Link 2 alone (link 1 massless): (1/2) m l^2 [(4/3 + c2) qd1^2 + (2/3 + c2) qd1 qd2 + qd2^2/3].
    let mut arm = ArmSpec::paper(2);
    arm.links[0].mass = int(0);
    arm.links[0].inertia = int(0);
    let link2 = Dynamics::derive(&arm);
    let expected = qd(1) * qd(1) * (fr(4, 3) + c(Q2))
        + qd(1) * qd(2) * (fr(2, 3) + c(Q2))
        + fr(1, 3) * qd(2) * qd(2);
    same(&primed(&link2.kinetic_energy), &expected, "link 2's L'");

    // dL'/dq2, dL'/dqd1, dL'/dqd2 and the time derivatives, as printed.
    assert!(l_prime.diff_q(0).is_zero());
    same(
        &l_prime.diff_q(1),
        &(-(s(Q2) * qd(1) * (qd(1) + qd(2)))),
        "dL'/dq2",
    );
    let p1 = 2 * (fr(5, 3) + c(Q2)) * qd(1) + (fr(2, 3) + c(Q2)) * qd(2);
    let p2 = (fr(2, 3) + c(Q2)) * qd(1) + 2 * fr(1, 3) * qd(2);
    same(&l_prime.diff_var(Var::Qd(0)), &p1, "dL'/dqd1");
    same(&l_prime.diff_var(Var::Qd(1)), &p2, "dL'/dqd2");
    let dp1 = 2 * qdd(1) * (fr(5, 3) + c(Q2)) + qdd(2) * (fr(2, 3) + c(Q2))
        - s(Q2) * qd(2) * (2 * qd(1) + qd(2));
    let dp2 = qdd(1) * (fr(2, 3) + c(Q2)) + 2 * qdd(2) * fr(1, 3) - s(Q2) * qd(1) * qd(2);
    same(&p1.0.dt(2), &dp1, "d/dt dL'/dqd1");
    same(&p2.0.dt(2), &dp2, "d/dt dL'/dqd2");
}

/// Erratum 2: `M'22 = 2(1/3)`, not `2(7/3)`.
#[test]
fn two_link_mass_matrix_equal_links() {
    let d = paper(2);
    let m_prime = scale_matrix(&d.mass_matrix, &int(2));
    let expected = matrix(vec![
        vec![2 * (fr(5, 3) + c(Q2)), fr(2, 3) + c(Q2)],
        vec![fr(2, 3) + c(Q2), 2 * fr(1, 3)],
    ]);
    assert_eq!(m_prime, expected);
    differs(&m_prime[1][1], &(2 * fr(7, 3)), "M'22 (erratum 2)");
    assert_eq!(d.mass_matrix, d.mass_matrix_from_lagrange());
    assert_eq!(d.torques(), d.lagrange_torques());
    // SI at P: [[34/15, 19/30], [19/30, 1/3]]; the printed entry would give M22 = 7/3.
    assert_eq!(
        at_p_matrix(&d.mass_matrix),
        vec![rats(&[(34, 15), (19, 30)]), rats(&[(19, 30), (1, 3)])]
    );
    assert_eq!(at_p0(&d.mass_matrix[1][1]), ratio(1, 3));
}

/// `det M' = 16/9 - cos^2 q2` and the printed inverse matrix.
#[test]
fn two_link_sensitivity_determinant() {
    let d = paper(2);
    let m_prime = scale_matrix(&d.mass_matrix, &int(2));
    let det = det2(&m_prime);
    same(&det, &(fr(16, 9) - c(Q2) * c(Q2)), "det M'");
    same(
        &det2(&d.mass_matrix),
        &(fr(4, 9) - fr(1, 4) * c(Q2) * c(Q2)),
        "det M (SI)",
    );
    assert_eq!(at_p0(&det2(&d.mass_matrix)), ratio(319, 900));
    // Always positive: 7/36 at c2 = +-1, 4/9 at c2 = 0 (SI).
    let si = det2(&d.mass_matrix);
    assert_eq!(at_cos_q2(&si, &int(1)), ratio(7, 36));
    assert_eq!(at_cos_q2(&si, &int(-1)), ratio(7, 36));
    assert_eq!(at_cos_q2(&si, &int(0)), ratio(4, 9));
    // The printed inverse: [[2/3, -(2/3 + c2)], [-(2/3 + c2), 2(5/3 + c2)]] / (16/9 - c2^2).
    let adjugate = matrix(vec![
        vec![2 * fr(1, 3), -(fr(2, 3) + c(Q2))],
        vec![-(fr(2, 3) + c(Q2)), 2 * (fr(5, 3) + c(Q2))],
    ]);
    assert_eq!(matmul(&m_prime, &adjugate), diagonal(2, &det));
    assert_eq!(matmul(&adjugate, &m_prime), diagonal(2, &det));
}

/// The joints decouple at `cos q2 = -2/3`: `M'12 = 2/3 + c2` vanishes.
#[test]
fn two_link_decoupling() {
    let d = paper(2);
    same(&primed(&d.mass_matrix[0][1]), &(fr(2, 3) + c(Q2)), "M'12");
    let c2 = ratio(-2, 3);
    let at = |e: &Expr| at_cos_q2(e, &c2);
    assert_eq!(at(&primed(&d.mass_matrix[0][1])), int(0));
    assert_eq!(at(&d.mass_matrix[1][0]), int(0));
    assert_eq!(
        (at(&d.mass_matrix[0][0]), at(&d.mass_matrix[1][1])),
        (int(1), ratio(1, 3))
    );
    assert_eq!(at(&det2(&d.mass_matrix)), ratio(1, 3));
    assert_eq!(
        at(&det2(&scale_matrix(&d.mass_matrix, &int(2)))),
        ratio(4, 3)
    );
    // Nowhere else: M'12 = 0 has the single root c2 = -2/3.
    for other in [ratio(-1, 1), ratio(-1, 2), int(0), int(1)] {
        assert_ne!(at_cos_q2(&d.mass_matrix[0][1], &other), int(0));
    }
    // General rods: M12 = m2 (l2^2/3 + l1 l2 c2/2) vanishes at c2 = -2 l2 / (3 l1).
    let general = Dynamics::derive(&rods(
        &rats(&[(2, 1), (1, 1)]),
        &rats(&[(3, 1), (5, 7)]),
        int(0),
    ));
    assert_eq!(at_cos_q2(&general.mass_matrix[0][1], &ratio(-1, 3)), int(0));
}

/// `c' = (-s2 qd2 (2 qd1 + qd2), s2 qd1^2)` and the full equations of motion.
#[test]
fn two_link_velocity_products_equal_links() {
    let d = paper(2);
    let t1v = -(s(Q2) * qd(2) * (2 * qd(1) + qd(2)));
    let t2v = s(Q2) * qd(1) * qd(1);
    same(&primed(&d.coriolis[0]), &t1v, "T1v'");
    same(&primed(&d.coriolis[1]), &t2v, "T2v'");
    assert_eq!(
        (
            at_p(&primed(&d.coriolis[0]), &[1, 2], &[]),
            at_p(&primed(&d.coriolis[1]), &[1, 2], &[])
        ),
        (ratio(-32, 5), ratio(4, 5))
    );
    let si: Vec<Rational> = d.coriolis.iter().map(|e| at_p(e, &[1, 2], &[])).collect();
    assert_eq!(si, rats(&[(-16, 5), (2, 5)]));
    // T1' = 2(5/3 + c2) qdd1 + (2/3 + c2) qdd2 - s2 qd2 (2 qd1 + qd2), T2' likewise.
    let t1 = 2 * (fr(5, 3) + c(Q2)) * qdd(1) + (fr(2, 3) + c(Q2)) * qdd(2) + t1v;
    let t2 = (fr(2, 3) + c(Q2)) * qdd(1) + fr(2, 3) * qdd(2) + t2v;
    same(&primed(&d.torques()[0]), &t1, "T1'");
    same(&primed(&d.torques()[1]), &t2, "T2'");
}

/// The gravity torques `g [(m1/2 + m2) l1 c1 + m2/2 l2 c12]` and `g [m2/2 l2 c12]`, with
/// distinct rational masses, lengths and gravity; and the test point's values.
#[test]
fn two_link_gravity_general() {
    let (m1, m2) = (ratio(3, 2), ratio(5, 7));
    let (l1, l2) = (ratio(2, 3), ratio(9, 4));
    let g = ratio(981, 100);
    let d = Dynamics::derive(&rods(
        &[l1.clone(), l2.clone()],
        &[m1.clone(), m2.clone()],
        g.clone(),
    ));
    let half = ratio(1, 2);
    let g1 =
        rat(&g) * (rat(&((&m1 * &half + &m2) * &l1)) * c(Q1) + rat(&(&half * &m2 * &l2)) * c(Q12));
    let g2 = rat(&g) * rat(&(&half * &m2 * &l2)) * c(Q12);
    same(&d.gravity[0], &g1, "T1g");
    same(&d.gravity[1], &g2, "T2g");
    // P = g m1 (l1/2) s1 + g m2 [l1 s1 + (l2/2) s12], and g = dP/dq.
    let p = rat(&(&g * &m1 * &l1 * &half)) * s(Q1)
        + rat(&(&g * &m2)) * (rat(&l1) * s(Q1) + rat(&(&l2 * &half)) * s(Q12));
    same(&d.potential_energy, &p, "P");

    // m = l = 1 at P: the coefficients of g are (19/25, -7/50).
    let mut arm = ArmSpec::paper(2);
    arm.gravity = planar_arm_core::down(ratio(981, 100));
    let unit = Dynamics::derive(&arm);
    let values: Vec<Rational> = unit.gravity.iter().map(at_p0).collect();
    assert_eq!(values, rats(&[(18639, 2500), (-6867, 5000)]));
    assert_eq!(
        values.iter().map(|v| v / &g).collect::<Vec<_>>(),
        rats(&[(19, 25), (-7, 50)])
    );
}

/// The general-rod results of `paper_expected.md` (a): M, det M and c.
#[test]
fn two_link_general_rods() {
    let (m1, m2) = (ratio(3, 2), ratio(5, 7));
    let (l1, l2) = (ratio(2, 3), ratio(9, 4));
    let d = Dynamics::derive(&rods(
        &[l1.clone(), l2.clone()],
        &[m1.clone(), m2.clone()],
        int(0),
    ));
    let third = ratio(1, 3);
    let m11 = rat(&(&m1 * &l1 * &l1 * &third))
        + rat(&m2) * (rat(&(&l1 * &l1)) + rat(&(&l1 * &l2)) * c(Q2) + rat(&(&l2 * &l2 * &third)));
    let m12 = rat(&m2) * (rat(&(&l2 * &l2 * &third)) + rat(&(&l1 * &l2 * ratio(1, 2))) * c(Q2));
    let m22 = rat(&(&m2 * &l2 * &l2 * &third));
    assert_eq!(
        d.mass_matrix,
        matrix(vec![vec![m11, m12.clone()], vec![m12, m22]])
    );
    let det = rat(&(&m1 * &m2 * &l1 * &l1 * &l2 * &l2 * ratio(1, 9)))
        + rat(&(&m2 * &m2 * &l1 * &l1 * &l2 * &l2)) * (fr(1, 3) - fr(1, 4) * c(Q2) * c(Q2));
    same(&det2(&d.mass_matrix), &det, "det M");
    let h = rat(&(&m2 * &l1 * &l2));
    same(
        &d.coriolis[0],
        &(-(h.clone() * s(Q2) * (qd(1) * qd(2) + fr(1, 2) * qd(2) * qd(2)))),
        "c1",
    );
    same(
        &d.coriolis[1],
        &(h * s(Q2) * fr(1, 2) * qd(1) * qd(1)),
        "c2",
    );
}

// ---------------------------------------------------------------------------------------------
// Three links: kinematics, statics, gravity.

/// Errata 3 and 4: `q3 = phi - q1 - q2`, and the wrist `(x - l3 cos phi, y - l3 sin phi)` is
/// joint 3 (the end of link 2), not joint 2.
#[test]
fn three_link_inverse_kinematics() {
    let (l1, l2, l3) = (ratio(2, 1), ratio(3, 2), ratio(1, 2));
    let kin = Kinematics::derive(&rods(&[l1, l2, l3.clone()], &rats(&[(1, 1); 3]), int(0)));
    // phi, the orientation of the last link, is q1 + q2 + q3: so q3 = phi - q1 - q2. The
    // printed q3 = -q2 - q1 would make phi = 0 for every configuration.
    assert_eq!(kin.tip_angle, Angle::new(Q123.to_vec()));
    assert!(!kin.tip_angle.is_zero());
    let (x, y) = &kin.points[3];
    let wrist = (
        E(x.clone()) - rat(&l3) * c(Q123),
        E(y.clone()) - rat(&l3) * s(Q123),
    );
    assert_eq!(
        (&kin.points[2].0, &kin.points[2].1),
        (&wrist.0 .0, &wrist.1 .0)
    );
    assert_ne!(kin.points[1].0, wrist.0 .0, "joint 2 is not the wrist");

    // At P with l = 1: tip (-77/125, 264/125), phi = 3 alpha, joint 3 = (8/25, 44/25).
    let unit = Kinematics::derive(&ArmSpec::paper(3));
    let tip = (at_p0(&unit.points[3].0), at_p0(&unit.points[3].1));
    assert_eq!(tip, (ratio(-77, 125), ratio(264, 125)));
    assert_eq!(
        (at_p0(&unit.points[2].0), at_p0(&unit.points[2].1)),
        (ratio(8, 25), ratio(44, 25))
    );
    // The printed q3 = -2 alpha: cos q3 = cos 2 alpha = -7/25, not cos alpha = 3/5.
    assert_eq!(cis(1).0, ratio(3, 5));
    assert_eq!(cis(-2).0, ratio(-7, 25));

    // The derived arm's closed form recovers (alpha, alpha, alpha) from (tip, phi).
    let alpha = 4f64.atan2(3.0);
    let target = Isometry2::new(Vector2::new(-77.0 / 125.0, 264.0 / 125.0), 3.0 * alpha);
    let [up, down] = Paper3::default().inverse_kinematics(&target).unwrap();
    for j in 0..3 {
        assert!((up[j] - alpha).abs() < 1e-12, "{up}");
    }
    assert!(down[1] < 0.0);
    let printed = SVector::<f64, 3>::new(up[0], up[1], -up[1] - up[0]);
    let miss = (Paper3::default().tip_pose(&printed).translation.vector
        - target.translation.vector)
        .norm();
    assert!(miss > 0.5, "the printed q3 reaches the target");
}

/// Errata 5 and 6: the usable work-space.
#[test]
fn three_link_usable_workspace() {
    // l = (2, 1, 1/2), l3 < |l1 - l2|: the annulus l3 + |l1 - l2| ..= l1 + l2 - l3 = 3/2 ..= 5/2.
    let [a, b, h] = ShortHand::default().links().map(|l| l.length);
    let usable = DexterousWorkspace::of_lengths(a, b, h);
    assert_eq!(usable.disk_radius(), None);
    let (inner, outer) = usable.annulus().unwrap();
    assert_eq!((inner, outer), (1.5, 2.5));
    let width = outer - inner;
    assert_eq!(width, 2.0 * (a.min(b) - h));
    assert_eq!(width, 1.0);
    assert_ne!(
        width,
        2.0 * a.min(b) - h,
        "erratum 5: 2 min(l1, l2) - l3 = 3/2"
    );
    // The average radius is the longer of links 1 and 2.
    assert_eq!((inner + outer) / 2.0, a.max(b));
    // The reachable work-space, for comparison: 1/2 ..= 7/2.
    let all = ShortHand::default().workspace();
    assert_eq!((all.inner_radius(), all.outer_radius()), (0.5, 3.5));
    // At l3 = |l1 - l2| exactly, as for l = (2, 3/2, 1/2), the origin is usable too.
    let touching = DexterousWorkspace::of_lengths(2.0, 1.5, 0.5);
    assert_eq!(touching.disk_radius(), Some(0.0));
    assert_eq!(touching.annulus(), Some((1.0, 3.0)));

    // l3 > |l1 - l2| (and l3 <= min): an extra disk of radius l3 - |l1 - l2|.
    let both = DexterousWorkspace::of_lengths(1.0, 0.75, 0.5);
    assert_eq!(both.disk_radius(), Some(0.25));
    assert_eq!(both.annulus(), Some((0.75, 1.25)));
    // Equal links: one disk of radius 2 l - l3.
    let equal = DexterousWorkspace::of_lengths(1.0, 1.0, 0.25);
    assert_eq!((equal.disk_radius(), equal.annulus()), (Some(1.75), None));

    // Erratum 6 (the paper's unstated l3 <= min(l1, l2)): beyond it the printed regions are
    // wrong. l = (10, 1, 5): l3 < |l1 - l2| = 9, yet no annulus (nothing at all).
    let none = DexterousWorkspace::of_lengths(10.0, 1.0, 5.0);
    assert!(none.is_empty());
    let printed_annulus = (5.0 + 9.0, 11.0 - 5.0);
    assert!(printed_annulus.0 > printed_annulus.1);
    let p = Point2::new(10.0, 0.0);
    assert!((0..64).any(|i| {
        let phi = f64::from(i) * std::f64::consts::TAU / 64.0;
        ik3(10.0, 1.0, 5.0, &Isometry2::new(p.coords, phi)).is_err()
    }));
    // l = (1, 1/2, 5/4): the disk has radius l1 + l2 - l3 = 1/4, not l3 - |l1 - l2| = 3/4.
    let long = DexterousWorkspace::of_lengths(1.0, 0.5, 1.25);
    assert_eq!((long.disk_radius(), long.annulus()), (Some(0.25), None));
    let between = Point2::new(0.5, 0.0);
    assert!(!long.contains(&between));
    // The wrist for phi = 0 lies 1.75 > l1 + l2 from the base.
    assert!(ik3(
        1.0,
        0.5,
        1.25,
        &Isometry2::new(Vector2::new(-0.5, 0.0), 0.0)
    )
    .is_err());
}

/// The paper's three-link statics (correct as printed): `tau = A (u, v, T)` with `A = J^T`,
/// `det A = l1 l2 s2`, and the printed inverse.
#[test]
fn three_link_statics() {
    let (l1, l2, l3) = (ratio(2, 1), ratio(3, 2), ratio(1, 2));
    let kin = Kinematics::derive(&rods(
        &[l1.clone(), l2.clone(), l3.clone()],
        &rats(&[(1, 1); 3]),
        int(0),
    ));
    let a: Matrix = (0..3)
        .map(|i| (0..3).map(|r| kin.jacobian[r][i].clone()).collect())
        .collect();
    let (l1e, l2e, l3e) = (|| rat(&l1), || rat(&l2), || rat(&l3));
    let printed_a = matrix(vec![
        vec![
            -(l1e() * s(Q1) + l2e() * s(Q12) + l3e() * s(Q123)),
            l1e() * c(Q1) + l2e() * c(Q12) + l3e() * c(Q123),
            k(1),
        ],
        vec![
            -(l2e() * s(Q12) + l3e() * s(Q123)),
            l2e() * c(Q12) + l3e() * c(Q123),
            k(1),
        ],
        vec![-(l3e() * s(Q123)), l3e() * c(Q123), k(1)],
    ]);
    assert_eq!(a, printed_a);
    let det = l1e() * l2e() * s(Q2);
    same(&det3(&a), &det, "det A");
    let adjugate = matrix(vec![
        vec![
            l2e() * c(Q12),
            -(l1e() * c(Q1) + l2e() * c(Q12)),
            l1e() * c(Q1),
        ],
        vec![
            l2e() * s(Q12),
            -(l1e() * s(Q1) + l2e() * s(Q12)),
            l1e() * s(Q1),
        ],
        vec![
            l2e() * l3e() * s(Q3),
            -(l1e() * l3e() * s(Q23) + l2e() * l3e() * s(Q3)),
            l1e() * l2e() * s(Q2) + l1e() * l3e() * s(Q23),
        ],
    ]);
    assert_eq!(matmul(&adjugate, &a), diagonal(3, &det.0));
    assert_eq!(matmul(&a, &adjugate), diagonal(3, &det.0));

    // At P: det = 12/5, A^-1 and tau for (u, v, T) = (1, 2, 3).
    let d = at_p0(&det.0);
    assert_eq!(d, ratio(12, 5));
    let inverse: Vec<Vec<Rational>> = at_p_matrix(&adjugate)
        .into_iter()
        .map(|row| row.into_iter().map(|x| x / &d).collect())
        .collect();
    assert_eq!(
        inverse,
        vec![
            rats(&[(-7, 40), (-13, 40), (1, 2)]),
            rats(&[(3, 5), (-19, 15), (2, 3)]),
            rats(&[(1, 4), (-13, 20), (7, 5)]),
        ]
    );
    let w = [int(1), int(2), int(3)];
    let tau: Vec<Rational> = at_p_matrix(&a)
        .iter()
        .map(|row| row.iter().zip(&w).map(|(x, y)| x * y).sum())
        .collect();
    assert_eq!(tau, rats(&[(51, 125), (-49, 125), (236, 125)]));
    // Equal unit links: det = 4/5 and the inverse of the docs.
    let unit = Kinematics::derive(&ArmSpec::paper(3));
    let a1: Matrix = (0..3)
        .map(|i| (0..3).map(|r| unit.jacobian[r][i].clone()).collect())
        .collect();
    let d1 = at_p0(&det3(&a1));
    assert_eq!(d1, ratio(4, 5));
    let adj1 = matrix(vec![
        vec![c(Q12), -(c(Q1) + c(Q12)), c(Q1)],
        vec![s(Q12), -(s(Q1) + s(Q12)), s(Q1)],
        vec![s(Q3), -(s(Q23) + s(Q3)), s(Q2) + s(Q23)],
    ]);
    let inverse1: Vec<Vec<Rational>> = at_p_matrix(&adj1)
        .into_iter()
        .map(|row| row.into_iter().map(|x| x / &d1).collect())
        .collect();
    assert_eq!(
        inverse1,
        vec![
            rats(&[(-7, 20), (-2, 5), (3, 4)]),
            rats(&[(6, 5), (-11, 5), (1, 1)]),
            rats(&[(1, 1), (-11, 5), (11, 5)]),
        ]
    );
}

/// The three-link gravity torques (correct as printed), general rational masses and lengths.
#[test]
fn three_link_gravity_general() {
    let m = rats(&[(3, 2), (5, 7), (2, 1)]);
    let l = rats(&[(2, 3), (9, 4), (4, 5)]);
    let g = ratio(981, 100);
    let d = Dynamics::derive(&rods(&l, &m, g.clone()));
    let half = ratio(1, 2);
    let t3 = rat(&(&half * &m[2] * &l[2])) * c(Q123);
    let t2 = rat(&((&half * &m[1] + &m[2]) * &l[1])) * c(Q12) + t3.clone();
    let t1 = rat(&((&half * &m[0] + &m[1] + &m[2]) * &l[0])) * c(Q1)
        + rat(&((&half * &m[1] + &m[2]) * &l[1])) * c(Q12)
        + t3.clone();
    for (i, t) in [t1, t2, t3].into_iter().enumerate() {
        same(&d.gravity[i], &(rat(&g) * t), &format!("T{}g", i + 1));
    }
    // m = l = 1 at P: coefficients of g (153/250, -111/125, -117/250).
    let mut arm = ArmSpec::paper(3);
    arm.gravity = planar_arm_core::down(g.clone());
    let unit = Dynamics::derive(&arm);
    same(
        &unit.gravity[0],
        &(rat(&g) * (fr(5, 2) * c(Q1) + fr(3, 2) * c(Q12) + fr(1, 2) * c(Q123))),
        "g1, unit links",
    );
    let values: Vec<Rational> = unit.gravity.iter().map(at_p0).collect();
    assert_eq!(
        values,
        rats(&[(150_093, 25_000), (-108_891, 12_500), (-114_777, 25_000)])
    );
    assert_eq!(
        values.iter().map(|v| v / &g).collect::<Vec<_>>(),
        rats(&[(153, 250), (-111, 125), (-117, 250)])
    );
}

// ---------------------------------------------------------------------------------------------
// Three equal links: dynamics.

/// `L'` with the given `qd1 qd2` constant (derived 10/3, printed 19/3).
fn three_link_l_prime(c12: E) -> E {
    qd(1) * qd(1) * (k(4) + 3 * c(Q2) + c(Q23) + c(Q3))
        + qd(1) * qd(2) * (c12 + 3 * c(Q2) + c(Q23) + 2 * c(Q3))
        + qd(2) * qd(2) * (fr(5, 3) + c(Q3))
        + qd(2) * qd(3) * (fr(2, 3) + c(Q3))
        + fr(1, 3) * qd(3) * qd(3)
        + qd(3) * qd(1) * (fr(2, 3) + c(Q23) + c(Q3))
}

/// `M'` with the given `(1,2)` constant (derived 10/3, printed 19/3).
fn three_link_m_prime(c12: E) -> Matrix {
    let m12 = || c12.clone() + 3 * c(Q2) + c(Q23) + 2 * c(Q3);
    matrix(vec![
        vec![
            2 * (k(4) + 3 * c(Q2) + c(Q23) + c(Q3)),
            m12(),
            fr(2, 3) + c(Q23) + c(Q3),
        ],
        vec![m12(), 2 * (fr(5, 3) + c(Q3)), fr(2, 3) + c(Q3)],
        vec![fr(2, 3) + c(Q23) + c(Q3), fr(2, 3) + c(Q3), fr(2, 3)],
    ])
}

/// Erratum 7: the `qd1 qd2` coefficient of `|v_G3|^2 / l^2` is `5/2`, not `11/2`.
#[test]
fn three_link_link3_com_speed_squared() {
    // Only link 3 carries mass, as a point of mass 2 at its middle: T = |v_G3|^2.
    let point = |mass: i64| LinkSpec {
        inertia: int(0),
        ..LinkSpec::rod(int(1), int(mass))
    };
    let arm = ArmSpec {
        links: vec![point(0), point(0), point(2)],
        gravity: planar_arm_core::down(int(0)),
        payload: None,
    };
    let v2 = Dynamics::derive(&arm).kinetic_energy;
    let speed = |c12: E| {
        qd(1) * qd(1) * (fr(9, 4) + 2 * c(Q2) + c(Q3) + c(Q23))
            + qd(1) * qd(2) * (c12 + 2 * c(Q2) + 2 * c(Q3) + c(Q23))
            + qd(2) * qd(2) * (fr(5, 4) + c(Q3))
            + qd(2) * qd(3) * (fr(1, 2) + c(Q3))
            + fr(1, 4) * qd(3) * qd(3)
            + qd(3) * qd(1) * (fr(1, 2) + c(Q3) + c(Q23))
    };
    same(&v2, &speed(fr(5, 2)), "|v_G3|^2");
    differs(&v2, &speed(fr(11, 2)), "|v_G3|^2 (erratum 7)");
    assert_eq!(at_p(&v2, &[1, 2, 3], &[]), ratio(793, 25));
    assert_eq!(at_p(&speed(fr(11, 2)).0, &[1, 2, 3], &[]), ratio(943, 25));
    // The paper's unexpanded form agrees.
    let unexpanded = qd(1) * qd(1)
        + 2 * c(Q2) * qd(1) * (qd(1) + qd(2))
        + (qd(1) + qd(2)) * (qd(1) + qd(2))
        + c(Q3) * (qd(1) + qd(2)) * (qd(1) + qd(2) + qd(3))
        + fr(1, 4) * (qd(1) + qd(2) + qd(3)) * (qd(1) + qd(2) + qd(3))
        + c(Q23) * qd(1) * (qd(1) + qd(2) + qd(3));
    same(&v2, &unexpanded, "|v_G3|^2, unexpanded");
    // Independently, from the kinematics of the arm cut at link 3's centre.
    let cut = Kinematics::derive(&ArmSpec {
        links: vec![point(1), point(1), LinkSpec::rod(ratio(1, 2), int(1))],
        gravity: planar_arm_core::down(int(0)),
        payload: None,
    });
    let rate = |row: usize| {
        (0..3).fold(E(Expr::zero()), |acc, j| {
            acc + E(cut.jacobian[row][j].clone()) * qd(j + 1)
        })
    };
    same(
        &(rate(0) * rate(0) + rate(1) * rate(1)).0,
        &speed(fr(5, 2)),
        "|J qd|^2",
    );
    // Link 2's centre, as printed (correct).
    let arm2 = ArmSpec {
        links: vec![point(0), point(2)],
        gravity: planar_arm_core::down(int(0)),
        payload: None,
    };
    same(
        &Dynamics::derive(&arm2).kinetic_energy,
        &(qd(1) * qd(1) * (fr(5, 4) + c(Q2))
            + qd(1) * qd(2) * (fr(1, 2) + c(Q2))
            + fr(1, 4) * qd(2) * qd(2)),
        "|v_G2|^2",
    );
}

/// Erratum 8: the `qd1 qd2` coefficient of `L'` is `10/3 + 3c2 + c23 + 2c3`, not `19/3 + ...`.
#[test]
fn three_link_lagrangian_equal_links() {
    let d = paper(3);
    let l_prime = primed(&d.lagrangian());
    same(&l_prime, &three_link_l_prime(fr(10, 3)), "L'");
    differs(&l_prime, &three_link_l_prime(fr(19, 3)), "L' (erratum 8)");
    let cross = l_prime.diff_var(Var::Qd(0)).diff_var(Var::Qd(1));
    assert_eq!(cross.constant_term(), Some(&ratio(10, 3)));
    assert_eq!(at_p(&l_prime, &[1, 2, 3], &[]), ratio(3064, 75));
    assert_eq!(at_p(&d.kinetic_energy, &[1, 2, 3], &[]), ratio(1532, 75));
    assert_eq!(
        at_p(&three_link_l_prime(fr(19, 3)).0, &[1, 2, 3], &[]),
        ratio(3514, 75)
    );
    // -dL'/dq_i as printed (correct), and the momenta with 10/3 (erratum 9's first places).
    assert!(l_prime.diff_q(0).is_zero());
    same(
        &l_prime.diff_q(1).scale(&int(-1)),
        &(qd(1) * qd(1) * (3 * s(Q2) + s(Q23))
            + qd(1) * qd(2) * (3 * s(Q2) + s(Q23))
            + qd(3) * qd(1) * s(Q23)),
        "-dL'/dq2",
    );
    same(
        &l_prime.diff_q(2).scale(&int(-1)),
        &(qd(1) * qd(1) * (s(Q23) + s(Q3))
            + qd(1) * qd(2) * (s(Q23) + 2 * s(Q3))
            + qd(2) * qd(2) * s(Q3)
            + qd(2) * qd(3) * s(Q3)
            + qd(3) * qd(1) * (s(Q23) + s(Q3))),
        "-dL'/dq3",
    );
    let momenta = |c12: E| {
        let m12 = || c12.clone() + 3 * c(Q2) + c(Q23) + 2 * c(Q3);
        [
            2 * qd(1) * (k(4) + 3 * c(Q2) + c(Q23) + c(Q3))
                + qd(2) * m12()
                + qd(3) * (fr(2, 3) + c(Q23) + c(Q3)),
            qd(1) * m12() + 2 * qd(2) * (fr(5, 3) + c(Q3)) + qd(3) * (fr(2, 3) + c(Q3)),
            qd(1) * (fr(2, 3) + c(Q23) + c(Q3)) + qd(2) * (fr(2, 3) + c(Q3)) + 2 * fr(1, 3) * qd(3),
        ]
    };
    for (i, (derived, printed)) in momenta(fr(10, 3))
        .iter()
        .zip(momenta(fr(19, 3)))
        .enumerate()
    {
        let p = l_prime.diff_var(Var::Qd(i));
        same(&p, derived, &format!("dL'/dqd{}", i + 1));
        if i < 2 {
            differs(&p, &printed, &format!("dL'/dqd{} (erratum 9)", i + 1));
        }
    }
}

/// Erratum 9 (the 19/3 carried into M'12 and M'21) and the slot of M'33 (= 2/3).
#[test]
fn three_link_mass_matrix_equal_links() {
    let d = paper(3);
    let m_prime = scale_matrix(&d.mass_matrix, &int(2));
    assert_eq!(m_prime, three_link_m_prime(fr(10, 3)));
    let printed = three_link_m_prime(fr(19, 3));
    for (i, j) in [(0, 1), (1, 0)] {
        differs(
            &m_prime[i][j],
            &E(printed[i][j].clone()),
            "M'12 (erratum 9)",
        );
    }
    assert_eq!(at_p0(&m_prime[0][1]), ratio(454, 75));
    assert_eq!(at_p0(&printed[0][1]), ratio(679, 75));
    assert_eq!(m_prime[2][2], Expr::constant(ratio(2, 3)));
    assert_eq!(d.mass_matrix, d.mass_matrix_from_lagrange());
    assert_eq!(d.torques(), d.lagrange_torques());
}

/// Erratum 13: `T = (1/2) m l^2 [M'] qdd + T_v`, not `1/(2 m l^2) [M'] qdd + T_v`; and the SI
/// values at P.
#[test]
fn three_link_mass_matrix_si() {
    let d = paper(3);
    assert_eq!(
        at_p_matrix(&d.mass_matrix),
        vec![
            rats(&[(153, 25), (227, 75), (37, 75)]),
            rats(&[(227, 75), (34, 15), (19, 30)]),
            rats(&[(37, 75), (19, 30), (1, 3)]),
        ]
    );
    let det = det3(&d.mass_matrix);
    same(
        &det,
        &(fr(28, 27)
            - fr(3, 4) * c(Q2) * c(Q2)
            - fr(7, 12) * c(Q3) * c(Q3)
            - fr(1, 3) * c(Q23) * c(Q23)
            + fr(3, 4) * c(Q2) * c(Q3) * c(Q23)),
        "det M",
    );
    assert_eq!(at_p0(&det), ratio(30733, 67500));
    same(
        &det3(&scale_matrix(&d.mass_matrix, &int(2))),
        &(fr(224, 27) - 6 * c(Q2) * c(Q2) - fr(14, 3) * c(Q3) * c(Q3) - fr(8, 3) * c(Q23) * c(Q23)
            + 6 * c(Q2) * c(Q3) * c(Q23)),
        "det M'",
    );
    // m = 2, l = 3: M = (1/2) m l^2 M' = 9 M', where the printed prefactor gives M' / 36.
    let (m, l) = (int(2), int(3));
    let heavy = Dynamics::derive(&rods(
        &[l.clone(), l.clone(), l.clone()],
        &[m.clone(), m.clone(), m.clone()],
        int(0),
    ));
    let m_prime = three_link_m_prime(fr(10, 3));
    let derived = ratio(1, 2) * &m * &l * &l;
    let printed = ratio(1, 1) / (int(2) * &m * &l * &l);
    assert_eq!(derived, int(9));
    assert_eq!(heavy.mass_matrix, scale_matrix(&m_prime, &derived));
    assert_ne!(heavy.mass_matrix, scale_matrix(&m_prime, &printed));
    for i in 0..3 {
        same(
            &heavy.coriolis[i],
            &E(primed(&paper(3).coriolis[i]).scale(&derived)),
            "c scales like M",
        );
    }
}

/// Errata 10-12: the velocity parts of `d/dt (dL'/dqd_i)`.
#[test]
fn three_link_momentum_rates_equal_links() {
    let d = paper(3);
    let bracket = |sign: i64, s3: i64| {
        3 * s(Q2) * qd(2) + sign * s(Q23) * (qd(2) + qd(3)) + (sign * s3) * s(Q3) * qd(3)
    };
    // Derived (all signs +) and printed (with the OCR'd minus signs).
    let derived = [
        -(2 * qd(1) * bracket(1, 1))
            - qd(2) * (3 * s(Q2) * qd(2) + s(Q23) * (qd(2) + qd(3)) + 2 * s(Q3) * qd(3))
            - qd(3) * (s(Q23) * (qd(2) + qd(3)) + s(Q3) * qd(3)),
        -(qd(1) * (3 * s(Q2) * qd(2) + s(Q23) * (qd(2) + qd(3)) + 2 * s(Q3) * qd(3)))
            - 2 * qd(2) * (s(Q3) * qd(3))
            - qd(3) * (s(Q3) * qd(3)),
        -(qd(1) * (s(Q23) * (qd(2) + qd(3)) + s(Q3) * qd(3))) - qd(2) * (s(Q3) * qd(3)),
    ];
    let printed = [
        -(2 * qd(1) * bracket(-1, 1))
            - qd(2) * (3 * s(Q2) * qd(2) + s(Q23) * (qd(2) + qd(3)) - 2 * s(Q3) * qd(3))
            - qd(3) * (s(Q23) * (qd(2) + qd(3)) - s(Q3) * qd(3)),
        -(qd(1) * bracket(-1, 1)) - 2 * qd(2) * (s(Q3) * qd(3)) - qd(3) * (s(Q3) * qd(3)),
        -(qd(1) * (s(Q23) * (qd(2) + qd(3)) - s(Q3) * qd(3))) - qd(2) * (s(Q3) * qd(3)),
    ];
    let mut values = Vec::new();
    let mut printed_values = Vec::new();
    for i in 0..3 {
        let rate = primed(&momentum_rate_velocity_part(&d, i));
        same(&rate, &derived[i], &format!("R{}", i + 1));
        differs(
            &rate,
            &printed[i],
            &format!("R{} (erratum {})", i + 1, 10 + i),
        );
        values.push(at_p(&rate, &[1, 2, 3], &[]));
        printed_values.push(at_p(&printed[i].0, &[1, 2, 3], &[]));
    }
    assert_eq!(values, rats(&[(-372, 5), (-156, 5), (-12, 1)]));
    assert_eq!(printed_values, rats(&[(-12, 1), (-72, 5), (-36, 5)]));
}

/// `T1v'` with the given `qd2 qd3` and `qd3 qd1` brackets.
fn t1v(b23: E, b31: E) -> E {
    -(qd(1) * qd(2) * (6 * s(Q2) + 2 * s(Q23)))
        - qd(2) * qd(2) * (3 * s(Q2) + s(Q23))
        - qd(2) * qd(3) * b23
        - qd(3) * qd(3) * (s(Q23) + s(Q3))
        - qd(3) * qd(1) * b31
}

/// Errata 14 and 15: the `qd2 qd3` and `qd3 qd1` terms of `T1v'`. `T2v'` and `T3v'` are
/// printed correctly.
#[test]
fn three_link_velocity_products_equal_links() {
    let d = paper(3);
    let c_prime: Vec<Expr> = d.coriolis.iter().map(primed).collect();
    let derived = t1v(2 * s(Q23) + 2 * s(Q3), 2 * s(Q23) + 2 * s(Q3));
    same(&c_prime[0], &derived, "T1v'");
    differs(
        &c_prime[0],
        &t1v(2 * s(Q23), 2 * s(Q23) + 2 * s(Q3)),
        "T1v' qd2 qd3 (erratum 14)",
    );
    differs(
        &c_prime[0],
        &t1v(2 * s(Q23) + 2 * s(Q3), 2 * s(Q23) + s(Q3)),
        "T1v' qd3 qd1 (erratum 15)",
    );
    let printed = t1v(2 * s(Q23), 2 * s(Q23) + s(Q3));
    differs(&c_prime[0], &printed, "T1v' as printed");
    same(
        &c_prime[1],
        &(qd(1) * qd(1) * (3 * s(Q2) + s(Q23))
            - qd(2) * qd(3) * (2 * s(Q3))
            - qd(3) * qd(3) * s(Q3)
            - qd(3) * qd(1) * (2 * s(Q3))),
        "T2v'",
    );
    same(
        &c_prime[2],
        &(qd(1) * qd(1) * (s(Q23) + s(Q3)) + qd(1) * qd(2) * (2 * s(Q3)) + qd(2) * qd(2) * s(Q3)),
        "T3v'",
    );
    let values: Vec<Rational> = c_prime.iter().map(|e| at_p(e, &[1, 2, 3], &[])).collect();
    assert_eq!(values, rats(&[(-372, 5), (-456, 25), (204, 25)]));
    let si: Vec<Rational> = d
        .coriolis
        .iter()
        .map(|e| at_p(e, &[1, 2, 3], &[]))
        .collect();
    assert_eq!(si, rats(&[(-186, 5), (-228, 25), (102, 25)]));
    assert_eq!(at_p(&printed.0, &[1, 2, 3], &[]), ratio(-312, 5));
    // c'1 = R1 because dL'/dq1 = 0.
    assert_eq!(c_prime[0], primed(&momentum_rate_velocity_part(&d, 0)));
}

/// The full equations `T_i' = sum_j M'_ij qdd_j + T_iv'` (with errata 8-15 corrected).
#[test]
fn three_link_torques_equal_links() {
    let d = paper(3);
    let m_prime = three_link_m_prime(fr(10, 3));
    let c_prime = [
        t1v(2 * s(Q23) + 2 * s(Q3), 2 * s(Q23) + 2 * s(Q3)),
        qd(1) * qd(1) * (3 * s(Q2) + s(Q23))
            - qd(2) * qd(3) * (2 * s(Q3))
            - qd(3) * qd(3) * s(Q3)
            - qd(3) * qd(1) * (2 * s(Q3)),
        qd(1) * qd(1) * (s(Q23) + s(Q3)) + qd(1) * qd(2) * (2 * s(Q3)) + qd(2) * qd(2) * s(Q3),
    ];
    let printed_m = three_link_m_prime(fr(19, 3));
    for (i, cv) in c_prime.into_iter().enumerate() {
        let with =
            |m: &Matrix| (0..3).fold(cv.clone(), |acc, j| acc + E(m[i][j].clone()) * qdd(j + 1));
        same(
            &primed(&d.torques()[i]),
            &with(&m_prime),
            &format!("T{}'", i + 1),
        );
        if i < 2 {
            // Erratum 9: the 19/3 in the qdd terms of T1' and T2'.
            differs(
                &primed(&d.torques()[i]),
                &with(&printed_m),
                &format!("T{}' (erratum 9)", i + 1),
            );
        }
    }
    assert!(d.gravity.iter().all(Expr::is_zero));
}
