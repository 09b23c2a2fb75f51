//! The paper, reproduced: the derivations of its two- and three-link arms with exact
//! rationals, the errata found by re-deriving it, and a check of the code that
//! `#[derive(PlanarArm)]` generated for the same arms against the numeric reference
//! (recursive Newton-Euler, composite rigid body, articulated body).
//!
//! ```text
//! cargo run --example paper
//! ```

#[path = "support/num.rs"]
mod num;

use planar_arm::prelude::*;
use planar_arm::reference;

use num::sig;
use planar_arm::symbolic::ring::{int, ratio, show, Rational};
use planar_arm::symbolic::{
    Angle, ArmSpec, Dynamics, Expr, Kinematics, LinkSpec, Monomial, Trig, Var,
};

/// The paper's two equal links: uniform unit rods, no gravity for the dynamics.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct Paper2 {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 1, mass = 1)]
    fore: Revolute,
}

/// The paper's three equal links.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct Paper3 {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 1, mass = 1)]
    fore: Revolute,
    #[arm(length = 1, mass = 1)]
    hand: Revolute,
}

/// Three links with a short hand (1, 1, 1/2), the paper's example of a usable work-space.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct ShortHand {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 1, mass = 1)]
    fore: Revolute,
    #[arm(length = 1/2, mass = 1/2)]
    hand: Revolute,
}

fn cos(k: &[i32]) -> Trig {
    Trig::Cos(Angle::new(k.to_vec()))
}

/// The coefficient of `qd_i qd_j` in an energy, as an expression in q.
fn rate_coefficient(e: &Expr, i: usize, j: usize) -> Expr {
    e.diff_var(Var::Qd(i))
        .diff_var(Var::Qd(j))
        .scale(&if i == j { ratio(1, 2) } else { int(1) })
}

/// In the paper's normalisation `L = 1/2 m l^2 L'` (m = l = 1): multiply by two.
fn paper_units(e: &Expr) -> Expr {
    e.scale(&int(2))
}

fn constant(e: &Expr) -> Rational {
    e.constant_term().cloned().unwrap_or_else(|| int(0))
}

fn section(title: &str) {
    println!("\n{title}\n{}", "=".repeat(title.len()));
}

fn print_dynamics(n: usize) -> Dynamics {
    let d = Dynamics::derive(&ArmSpec::paper(n));
    println!("Lagrangian, in the paper's units (L = 1/2 m l^2 L'):");
    println!("  L' = {}", paper_units(&d.lagrangian()));
    println!("Mass (sensitivity) matrix, SI with m = l = 1:");
    for i in 0..n {
        for j in i..n {
            println!("  M{}{} = {}", i + 1, j + 1, d.mass_matrix[i][j]);
        }
    }
    println!("Velocity-product torques c(q, qd):");
    for (i, c) in d.coriolis.iter().enumerate() {
        println!("  c{} = {c}", i + 1);
    }
    d
}

fn main() {
    section("Two equal links (the paper's dynamics section)");
    let d2 = print_dynamics(2);
    let m = &d2.mass_matrix;
    let det = paper_units(&m[0][0])
        .mul(&paper_units(&m[1][1]))
        .sub(&paper_units(&m[0][1]).mul(&paper_units(&m[1][0])));
    println!("Determinant of the sensitivity matrix (paper's units): {det}");
    println!("  (cos^2 q2 = (1 + cos 2 q2) / 2, so this is 16/9 - cos^2 q2)");
    println!(
        "Decoupling: M12 = {} vanishes where cos q2 = -{}",
        m[0][1],
        show(
            &(constant(&m[0][1])
                / m[0][1]
                    .coefficient(&cos(&[0, 1]))
                    .cloned()
                    .unwrap_or_else(|| int(1)))
        )
    );
    let mut general = ArmSpec::paper(2);
    general.gravity = planar_arm::symbolic::down(ratio(981, 100));
    general.links[0] = LinkSpec::rod(ratio(3, 2), ratio(2, 1));
    general.links[1] = LinkSpec::rod(ratio(1, 1), ratio(1, 2));
    let dg = Dynamics::derive(&general);
    println!("Gravity torques for l = (3/2, 1), m = (2, 1/2), g = 981/100:");
    println!(
        "  g1 = {}   (paper: g[(m1/2 + m2) l1 c1 + m2/2 l2 c12])",
        dg.gravity[0]
    );
    println!("  g2 = {}   (paper: g[m2/2 l2 c12])", dg.gravity[1]);

    section("Three equal links");
    let d3 = print_dynamics(3);

    section("Kinematics and statics (the first half of the paper)");
    kinematics_and_statics();

    section("Errata: printed in the paper vs derived here");
    let l3 = paper_units(&d3.lagrangian());
    let mut link3 = ArmSpec::paper(3);
    for l in &mut link3.links[..2] {
        l.mass = int(0);
        l.inertia = int(0);
    }
    link3.links[2].inertia = int(0);
    // With only link 3's centre carrying (unit) mass, T = |v3|^2 / 2.
    let v3 = Dynamics::derive(&link3).kinetic_energy.scale(&int(2));
    let c1 = paper_units(&d3.coriolis[0]);
    let sin_coeffs = |e: &Expr, a: &Monomial| {
        let c = e.coefficient_of(a);
        format!("{c}")
    };
    let pair = |i: usize, j: usize| Monomial::var(Var::Qd(i)).mul(&Monomial::var(Var::Qd(j)));
    let rows: Vec<(&str, String, String)> = vec![
        (
            "2 links, sensitivity matrix (2,2)",
            "2(7/3)".into(),
            format!("2({})", show(&constant(&d2.mass_matrix[1][1]))),
        ),
        (
            "3 links, |v| of link 3's centre squared, qd1 qd2 constant",
            "11/2".into(),
            show(&constant(&rate_coefficient(&v3, 0, 1))),
        ),
        (
            "3 links, Lagrangian L', qd1 qd2 constant",
            "19/3".into(),
            show(&constant(&rate_coefficient(&l3, 0, 1))),
        ),
        (
            "3 links, sensitivity matrix (1,2) constant (paper's units)",
            "19/3".into(),
            show(&constant(&paper_units(&d3.mass_matrix[0][1]))),
        ),
        (
            "3 links, sensitivity matrix (3,3) (paper's units)",
            "theta1 (garbled)".into(),
            show(&constant(&paper_units(&d3.mass_matrix[2][2]))),
        ),
        (
            "3 links, T1' qd2 qd3 term",
            "-(2 s23)".into(),
            sin_coeffs(&c1, &pair(1, 2)),
        ),
        (
            "3 links, T1' qd3 qd1 term",
            "-(2 s23 + s3)".into(),
            sin_coeffs(&c1, &pair(0, 2)),
        ),
        (
            "3 links, inverse kinematics, last angle",
            "theta3 = -theta2 - theta1".into(),
            "q3 = phi - q1 - q2 (tests/kinematics.rs)".into(),
        ),
        (
            "3 links, usable work-space disk radius",
            "l3 - |l1 - l2|".into(),
            "min(l3 - |l1 - l2|, l1 + l2 - l3)".into(),
        ),
    ];
    let w = rows.iter().map(|r| r.0.len()).max().unwrap_or(0);
    println!("{:w$}  {:28}  derived", "where", "printed");
    for (place, printed, derived) in &rows {
        println!("{place:w$}  {printed:28}  {derived}");
    }
    println!("(full list with the test that checks each row: docs/errata.md)");

    reference_check();
}

/// The code the derive generated for the paper's arms against the numeric reference.
fn reference_check() {
    section("Generated code against the numeric reference");
    let worst2 = compare(&Paper2::default(), 500);
    let worst3 = compare(&Paper3::default(), 500);
    println!(
        "two links:   max relative difference over 500 random states: {}",
        sig(worst2, 3)
    );
    println!(
        "three links: max relative difference over 500 random states: {}",
        sig(worst3, 3)
    );
    assert!(
        worst2 < 1e-12 && worst3 < 1e-12,
        "generated code disagrees with the reference"
    );
    println!(
        "(tau against Newton-Euler, M against composite rigid body, qdd against articulated body)"
    );
}

/// The determinant of a square matrix of expressions, by cofactor expansion (small N only).
fn det(m: &[Vec<Expr>]) -> Expr {
    match m.len() {
        1 => m[0][0].clone(),
        n => (0..n).fold(Expr::zero(), |acc, j| {
            let minor: Vec<Vec<Expr>> = m[1..]
                .iter()
                .map(|row| {
                    row.iter()
                        .enumerate()
                        .filter(|(k, _)| *k != j)
                        .map(|(_, e)| e.clone())
                        .collect()
                })
                .collect();
            let term = m[0][j].mul(&det(&minor));
            if j % 2 == 0 {
                acc.add(&term)
            } else {
                acc.sub(&term)
            }
        }),
    }
}

fn kinematics_and_statics() {
    let mut arm = ArmSpec::paper(2);
    arm.links[0].length = ratio(3, 2);
    let k2 = Kinematics::derive(&arm);
    println!("Two links, l1 = 3/2, l2 = 1:");
    println!("  x = {}", k2.points[2].0);
    println!("  y = {}", k2.points[2].1);
    println!(
        "  r^2 = x^2 + y^2 = {}   (no q1: the arm is an r-theta generator)",
        k2.radius_squared
    );
    let j2 = vec![k2.jacobian[0].clone(), k2.jacobian[1].clone()];
    println!(
        "  statics tau = J^T (u, v): det J = {}   (paper: l1 l2 sin q2; singular at q2 = 0, pi)",
        det(&j2)
    );
    let k3 = Kinematics::derive(&ArmSpec::paper(3));
    println!("Three equal links: tau = A (u, v, T) with A = J^T,");
    for (i, row) in (0..3).map(|j| {
        (
            j,
            [&k3.jacobian[0][j], &k3.jacobian[1][j], &k3.jacobian[2][j]],
        )
    }) {
        println!(
            "  tau{} = ({}) u + ({}) v + ({}) T",
            i + 1,
            row[0],
            row[1],
            row[2]
        );
    }
    println!("  det A = {}   (paper: l1 l2 sin q2)", det(&k3.jacobian));

    let two = Paper2::default();
    let target = Point2::new(1.2, 0.9);
    match two.inverse_kinematics(&target) {
        Ok([up, down]) => println!(
            "Inverse kinematics of the paper's two links to (1.2, 0.9): q = ({:.4}, {:.4}) or ({:.4}, {:.4})",
            up[0], up[1], down[0], down[1]
        ),
        Err(e) => println!("inverse kinematics failed: {e}"),
    }
    match two.inverse_kinematics(&Point2::new(2.5, 0.0)) {
        Ok(_) => println!("unexpected: (2.5, 0) reached"),
        Err(e) => println!("  and to (2.5, 0): {e}"),
    }
    let q = Vector2::new(0.4, 1.1);
    let tau = two.joint_torques(&q, &Vector2::new(1.0, -2.0), 0.0);
    match two.tip_force(&q, &tau) {
        Ok(f) => println!(
            "Statics of the two links at q = (0.4, 1.1): the tip force (1, -2) needs tau = ({:.4}, {:.4}); \
             inverted back, the force is ({:.4}, {:.4})",
            tau[0], tau[1], f.x, f.y
        ),
        Err(e) => println!("inverse statics failed: {e}"),
    }

    let three = Paper3::default();
    let pose = Isometry2::new(Vector2::new(1.5, 1.0), 0.3);
    match three.inverse_kinematics(&pose) {
        Ok([a, b]) => println!(
            "Inverse kinematics of the paper's three links to (1.5, 1) at 0.3 rad: q = ({:.4}, {:.4}, {:.4}) or ({:.4}, {:.4}, {:.4})",
            a[0], a[1], a[2], b[0], b[1], b[2]
        ),
        Err(e) => println!("three-link inverse kinematics failed: {e}"),
    }
    println!(
        "Work-spaces: the two equal links reach radii {} to {};",
        two.workspace().inner_radius(),
        two.workspace().outer_radius()
    );
    let usable = ShortHand::default().dexterous_workspace();
    match usable.disk_radius() {
        Some(r) => println!(
            "  links 1, 1, 1/2 reach every orientation within radius {r} (paper: 2l - l3 = 1.5)"
        ),
        None => println!("  links 1, 1, 1/2 have no disk of every orientation"),
    }

    section("A short simulation");
    simulate(&two);
}

/// The two rods released from rest, q = (-1, 0.4), swing for 5 s under gravity; RK4 at 1 ms
/// keeps their energy (no friction) to about 1e-11 J.
fn simulate(arm: &Paper2) {
    // The prelude's `Dynamics` trait, which the engine's `symbolic::Dynamics` above shadows.
    use planar_arm::sim::{from_fn, Rk4, Simulator};
    use planar_arm::Dynamics as _;
    let energy =
        |q: &Vector2<f64>, qd: &Vector2<f64>| arm.kinetic_energy(q, qd) + arm.potential_energy(q);
    let start = Vector2::new(-1.0, 0.4);
    let e0 = energy(&start, &Vector2::zeros());
    let run = Simulator::new(Rk4, 1e-3)
        .and_then(|sim| sim.with_control_period(0.5))
        .and_then(|sim| {
            let free = from_fn(|_, _: &Vector2<f64>, _: &Vector2<f64>| Vector2::zeros());
            sim.run(arm, start, Vector2::zeros(), 5.0, free)
        });
    let run = match run {
        Ok(run) => run,
        Err(e) => {
            println!("simulation failed: {e}");
            return;
        }
    };
    println!("   t       q1       q2      tip x    tip y    energy drift");
    for state in run {
        match state {
            Ok(s) => {
                let tip = arm.tip_pose(&s.q).translation;
                println!(
                    "{:5.2} {:8.4} {:8.4} {:8.4} {:8.4}    {:>9} J",
                    s.t,
                    s.q[0],
                    s.q[1],
                    tip.x,
                    tip.y,
                    sig(energy(&s.q, &s.qd) - e0, 3)
                );
            }
            Err(e) => {
                println!("simulation stopped: {e}");
                return;
            }
        }
    }
}

/// The largest relative difference between generated and reference dynamics.
fn compare<A: PlanarArm<N>, const N: usize>(arm: &A, samples: u64) -> f64 {
    let mut seed = 0x2545_F491_4F6C_DD1D_u64;
    let mut next = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        #[allow(clippy::cast_precision_loss)]
        let u = (seed >> 11) as f64 / (1u64 << 53) as f64;
        6.0 * u - 3.0
    };
    let model = arm.model();
    let mut worst: f64 = 0.0;
    for _ in 0..samples {
        let q = SVector::<f64, N>::from_fn(|_, _| next());
        let qd = SVector::<f64, N>::from_fn(|_, _| next());
        let qdd = SVector::<f64, N>::from_fn(|_, _| next());
        let tau = arm.inverse_dynamics(&q, &qd, &qdd);
        let tau_ref = reference::inverse_dynamics(&model, &q, &qd, &qdd);
        let m = arm.mass_matrix(&q);
        let m_ref = reference::mass_matrix(&model, &q);
        let qdd_back = arm.forward_dynamics(&q, &qd, &tau_ref);
        let qdd_ref = reference::forward_dynamics(&model, &q, &qd, &tau_ref);
        worst = worst
            .max((tau - tau_ref).amax() / tau_ref.amax().max(1.0))
            .max((m - m_ref).amax() / m_ref.amax())
            .max((qdd_back - qdd_ref).amax() / qdd_ref.amax().max(1.0));
    }
    worst
}
