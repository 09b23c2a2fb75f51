//! Kinematics and statics of derived arms, checked against oracles that share nothing with the
//! generated formulas: an independent forward kinematics from `links()`, central finite
//! differences, virtual work, brute-force sampling of configurations and orientations.
//!
//! The arms: the paper's two equal links, an unequal pair, three equal links, three links with
//! equal first two and a short hand, the paper's two three-link cases with unequal first links
//! (`l3 < |l1 - l2|` and `l3 > |l1 - l2|`), and a 4- and a 6-link arm.

use core::f64::consts::{FRAC_PI_2, PI, TAU};

use planar_arm::kinematics::REACH_TOLERANCE;
use planar_arm::nalgebra::Vector3;
use planar_arm::prelude::*;

mod common;

#[path = "common/arms.rs"]
mod arms;

use arms::Six;
use common::Rng;

/// The paper's two equal links.
#[derive(PlanarArm, Default, Debug, Clone, Copy)]
#[arm(gravity = 9.81)]
struct Paper2 {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 1, mass = 1)]
    fore: Revolute,
}

/// Two unequal links: the annulus 0.7 ..= 2.3.
#[derive(PlanarArm, Default, Debug, Clone, Copy)]
#[arm(gravity = 9.81)]
struct Unequal2 {
    #[arm(length = 3/2, mass = 2)]
    upper: Revolute,
    #[arm(length = 4/5, mass = 1)]
    fore: Revolute,
}

/// The paper's three equal links.
#[derive(PlanarArm, Default, Debug, Clone, Copy)]
#[arm(gravity = 9.81)]
struct Paper3 {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 1, mass = 1)]
    fore: Revolute,
    #[arm(length = 1, mass = 1)]
    hand: Revolute,
}

/// Equal first links and a short hand: the usable region is one disk of radius `2 l - l3`.
#[derive(PlanarArm, Default, Debug, Clone, Copy)]
#[arm(gravity = 9.81)]
struct EqualShort3 {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 1, mass = 1)]
    fore: Revolute,
    #[arm(length = 2/5, mass = 1/2)]
    hand: Revolute,
}

/// `l3 < |l1 - l2|`: the usable region is an annulus.
#[derive(PlanarArm, Default, Debug, Clone, Copy)]
#[arm(gravity = 9.81)]
struct Unequal3 {
    #[arm(length = 1, mass = 2)]
    upper: Revolute,
    #[arm(length = 3/5, mass = 1)]
    fore: Revolute,
    #[arm(length = 1/4, mass = 1/2)]
    hand: Revolute,
}

/// `|l1 - l2| < l3 <= min(l1, l2)`: the usable region is an annulus and a disk.
#[derive(PlanarArm, Default, Debug, Clone, Copy)]
#[arm(gravity = 9.81)]
struct Mixed3 {
    #[arm(length = 1, mass = 2)]
    upper: Revolute,
    #[arm(length = 7/10, mass = 1)]
    fore: Revolute,
    #[arm(length = 1/2, mass = 1/2)]
    hand: Revolute,
}

/// Four links, one of them dominant: the work-space has a hole of radius 0.8.
#[derive(PlanarArm, Default, Debug, Clone, Copy)]
#[arm(gravity = 9.81)]
struct Four {
    #[arm(length = 2, mass = 3)]
    l1: Revolute,
    #[arm(length = 1/2, mass = 1)]
    l2: Revolute,
    #[arm(length = 3/10, mass = 1/2)]
    l3: Revolute,
    #[arm(length = 2/5, mass = 1/2)]
    l4: Revolute,
}

/// Runs `$check(&arm, &mut $rng)` for every arm above.
macro_rules! every_arm {
    ($check:ident, $rng:ident) => {
        $check(&Paper2::default(), &mut $rng);
        $check(&Unequal2::default(), &mut $rng);
        $check(&Paper3::default(), &mut $rng);
        $check(&EqualShort3::default(), &mut $rng);
        $check(&Unequal3::default(), &mut $rng);
        $check(&Mixed3::default(), &mut $rng);
        $check(&Four::default(), &mut $rng);
        $check(&Six::default(), &mut $rng);
    };
}

// ---------------------------------------------------------------------------------------------
// Independent helpers.

// The shared generator, with what these tests draw.
impl Rng {
    fn angle(&mut self) -> f64 {
        self.range(-PI, PI)
    }

    fn config<const N: usize>(&mut self) -> SVector<f64, N> {
        SVector::from_fn(|_, _| self.angle())
    }
}

fn lengths<A: PlanarArm<N>, const N: usize>(arm: &A) -> [f64; N] {
    arm.links().map(|l| l.length)
}

/// Forward kinematics from the link lengths alone: the tip and the last link's angle.
fn fk<const N: usize>(lengths: &[f64; N], q: &SVector<f64, N>) -> (Vector2<f64>, f64) {
    let (mut tip, mut phi) = (Vector2::zeros(), 0.0);
    for (l, qk) in lengths.iter().zip(q.iter()) {
        phi += qk;
        tip += Vector2::new(phi.cos(), phi.sin()) * *l;
    }
    (tip, phi)
}

/// `|a - b|` modulo `2 pi`.
fn angle_gap(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(TAU);
    d.min(TAU - d)
}

fn in_range(a: f64) -> bool {
    a > -PI && a <= PI
}

/// `a x b = a.x b.y - a.y b.x`, the paper's planar cross product.
fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

/// The paper's statics: `tau_i = T + (r_i + ... + r_N) x F`.
fn paper_torques<const N: usize>(
    lengths: &[f64; N],
    q: &SVector<f64, N>,
    force: Vector2<f64>,
    torque: f64,
) -> SVector<f64, N> {
    let mut phi = 0.0;
    let links: Vec<Vector2<f64>> = (0..N)
        .map(|k| {
            phi += q[k];
            Vector2::new(phi.cos(), phi.sin()) * lengths[k]
        })
        .collect();
    SVector::from_fn(|i, _| torque + cross(links[i..].iter().sum(), force))
}

/// The task-space pose as `(x, y, phi)`, phi measured relative to `reference` so that central
/// differences do not straddle the cut at pi.
fn pose_vector(pose: &Isometry2<f64>, reference: &Isometry2<f64>) -> Vector3<f64> {
    let t = pose.translation.vector;
    Vector3::new(
        t.x,
        t.y,
        reference.rotation.angle() + reference.rotation.angle_to(&pose.rotation),
    )
}

// ---------------------------------------------------------------------------------------------
// Closed-form inverse kinematics.

fn two_link_round_trip<A>(arm: &A)
where
    A: PlanarArm<2> + ClosedFormIk<2, Target = Point2<f64>>,
{
    let l = lengths(arm);
    let w = arm.workspace();
    let (inner, outer) = (w.inner_radius(), w.outer_radius());
    assert!((inner - (l[0] - l[1]).abs()).abs() < 1e-15 && outer == l[0] + l[1]);
    for i in 0..=60 {
        let r = inner + (outer - inner) * f64::from(i) / 60.0;
        for j in 0..90 {
            let theta = f64::from(j) * TAU / 90.0;
            let target = Point2::new(r * theta.cos(), r * theta.sin());
            assert!(w.contains(&target));
            let solutions = arm.inverse_kinematics(&target).unwrap();
            for (branch, q) in solutions.iter().enumerate() {
                let tip = arm.tip_pose(q).translation.vector;
                let (independent, _) = fk(&l, q);
                assert!(
                    (tip - target.coords).norm() <= 1e-12 * outer
                        && (independent - target.coords).norm() <= 1e-12 * outer,
                    "{l:?}: target {target}, branch {branch}: {q} reaches {tip}"
                );
                assert!(q.iter().all(|a| in_range(*a)), "{q}");
                let s2 = q[1].sin();
                if branch == 0 {
                    assert!(s2 >= -1e-15, "branch 0 has sin q2 = {s2}");
                } else {
                    assert!(s2 <= 1e-15, "branch 1 has sin q2 = {s2}");
                }
            }
        }
    }
}

#[test]
fn two_link_inverse_kinematics_round_trips_over_the_work_space() {
    two_link_round_trip(&Paper2::default());
    two_link_round_trip(&Unequal2::default());
}

fn two_link_recovers<A>(arm: &A, rng: &mut Rng)
where
    A: PlanarArm<2> + ClosedFormIk<2, Target = Point2<f64>>,
{
    for _ in 0..2000 {
        let q = rng.config::<2>();
        if q[1].sin().abs() < 1e-3 {
            continue;
        }
        let target = Point2::from(arm.tip_pose(&q).translation.vector);
        let solutions = arm.inverse_kinematics(&target).unwrap();
        let same = solutions[usize::from(q[1].sin() < 0.0)];
        let other = solutions[usize::from(q[1].sin() >= 0.0)];
        assert!(
            angle_gap(same[0], q[0]) < 1e-8 && angle_gap(same[1], q[1]) < 1e-8,
            "{q} came back as {same}"
        );
        // The other branch is the mirror image: q2 of opposite sign.
        assert!((other[1] + same[1]).abs() < 1e-8);
    }
}

#[test]
fn two_link_inverse_kinematics_recovers_configurations_by_branch() {
    let mut rng = Rng(1);
    two_link_recovers(&Paper2::default(), &mut rng);
    two_link_recovers(&Unequal2::default(), &mut rng);
}

fn boundary_branches_agree<A>(arm: &A)
where
    A: PlanarArm<2> + ClosedFormIk<2, Target = Point2<f64>>,
{
    let w = arm.workspace();
    let (inner, outer) = (w.inner_radius(), w.outer_radius());
    for j in 0..36 {
        let (s, c) = (f64::from(j) * TAU / 36.0).sin_cos();
        // On the outer circle: stretched (q2 = 0), one configuration.
        let [a, b] = arm
            .inverse_kinematics(&Point2::new(outer * c, outer * s))
            .unwrap();
        assert!(a[1].abs() < 1e-6 && angle_gap(a[0], b[0]) < 1e-6 && angle_gap(a[1], b[1]) < 1e-6);
        // Just outside, within the tolerance: clamped onto the circle, identical branches.
        let out = outer * (1.0 + 0.5 * REACH_TOLERANCE);
        let [a, b] = arm
            .inverse_kinematics(&Point2::new(out * c, out * s))
            .unwrap();
        assert_eq!(a, b);
        assert_eq!(a[1], 0.0);
        // Beyond it: unreachable.
        let far = outer * (1.0 + 1e-6);
        assert!(matches!(
            arm.inverse_kinematics(&Point2::new(far * c, far * s)),
            Err(ArmError::Unreachable { .. })
        ));
        // On the inner circle: folded (q2 = pi), one configuration.
        if inner > 0.0 {
            let [a, b] = arm
                .inverse_kinematics(&Point2::new(inner * c, inner * s))
                .unwrap();
            assert!(
                angle_gap(a[1], PI) < 1e-6
                    && angle_gap(a[0], b[0]) < 1e-6
                    && angle_gap(a[1], b[1]) < 1e-6
            );
            let r = inner * (1.0 - 1e-3);
            assert!(matches!(
                arm.inverse_kinematics(&Point2::new(r * c, r * s)),
                Err(ArmError::Unreachable { .. })
            ));
        }
    }
}

#[test]
fn two_link_boundary_gives_equal_configurations() {
    boundary_branches_agree(&Paper2::default());
    boundary_branches_agree(&Unequal2::default());
}

#[test]
fn two_equal_links_reach_the_origin() {
    let arm = Paper2::default();
    for origin in [Point2::origin(), Point2::new(-0.0, -0.0)] {
        let [a, b] = arm.inverse_kinematics(&origin).unwrap();
        assert_eq!(a, b);
        assert_eq!(a, Vector2::new(0.0, PI));
        assert!(arm.tip_pose(&a).translation.vector.norm() < 1e-15);
    }
    // Every q1 reaches it (the paper's singular point).
    for q1 in [-2.0, 0.0, 0.7, 3.0] {
        assert!(
            arm.tip_pose(&Vector2::new(q1, PI))
                .translation
                .vector
                .norm()
                < 1e-15
        );
    }
    // Unequal links cannot.
    assert!(matches!(
        Unequal2::default().inverse_kinematics(&Point2::origin()),
        Err(ArmError::Unreachable { .. })
    ));
}

fn three_link_round_trip<A>(arm: &A)
where
    A: PlanarArm<3> + ClosedFormIk<3, Target = Isometry2<f64>>,
{
    let l = lengths(arm);
    let (inner, outer) = ((l[0] - l[1]).abs(), l[0] + l[1]);
    let reach = l.iter().sum::<f64>();
    for i in 0..=24 {
        let rho = inner + (outer - inner) * f64::from(i) / 24.0;
        for j in 0..24 {
            let theta = (f64::from(j) + 0.25) * TAU / 24.0;
            let wrist = Vector2::new(rho * theta.cos(), rho * theta.sin());
            for k in 0..8 {
                let phi = -PI + (f64::from(k) + 0.5) * TAU / 8.0;
                let tip = wrist + Vector2::new(phi.cos(), phi.sin()) * l[2];
                let target = Isometry2::new(tip, phi);
                let solutions = arm.inverse_kinematics(&target).unwrap();
                for (branch, q) in solutions.iter().enumerate() {
                    let pose = arm.tip_pose(q);
                    let (independent, angle) = fk(&l, q);
                    assert!((pose.translation.vector - tip).norm() <= 1e-12 * reach);
                    assert!((independent - tip).norm() <= 1e-12 * reach);
                    assert!(angle_gap(pose.rotation.angle(), phi) <= 1e-12);
                    assert!(angle_gap(angle, phi) <= 1e-12);
                    // q3 = phi - q1 - q2 (the paper prints -q2 - q1).
                    assert!(angle_gap(q[2], phi - q[0] - q[1]) <= 1e-12);
                    // The wrist is joint 3, the end of link 2.
                    let joints = arm.joint_positions(q);
                    assert!((joints[2].coords - wrist).norm() <= 1e-12 * reach);
                    assert!(q.iter().all(|a| in_range(*a)));
                    let s2 = q[1].sin();
                    assert!(if branch == 0 {
                        s2 >= -1e-15
                    } else {
                        s2 <= 1e-15
                    });
                }
            }
        }
    }
    // A wrist outside the two-link annulus is refused.
    let phi: f64 = 0.4;
    let far = Vector2::new(phi.cos(), phi.sin()) * (outer + l[2] + 0.1);
    assert!(matches!(
        arm.inverse_kinematics(&Isometry2::new(far, phi)),
        Err(ArmError::Unreachable { .. })
    ));
}

#[test]
fn three_link_inverse_kinematics_round_trips() {
    three_link_round_trip(&Paper3::default());
    three_link_round_trip(&EqualShort3::default());
    three_link_round_trip(&Unequal3::default());
    three_link_round_trip(&Mixed3::default());
}

// ---------------------------------------------------------------------------------------------
// Jacobian, statics and virtual work.

fn jacobian_by_differences<A: PlanarArm<N>, const N: usize>(arm: &A, rng: &mut Rng) {
    let l = lengths(arm);
    let reach: f64 = l.iter().sum();
    for _ in 0..100 {
        let q = rng.config::<N>();
        let pose = arm.tip_pose(&q);
        let (tip, phi) = fk(&l, &q);
        assert!((pose.translation.vector - tip).norm() <= 1e-12 * reach);
        assert!(angle_gap(pose.rotation.angle(), phi) <= 1e-12);
        let j = arm.jacobian(&q);
        let h = 1e-6;
        for i in 0..N {
            let mut e = SVector::<f64, N>::zeros();
            e[i] = h;
            let d = (pose_vector(&arm.tip_pose(&(q + e)), &pose)
                - pose_vector(&arm.tip_pose(&(q - e)), &pose))
                / (2.0 * h);
            assert!(
                (d - j.column(i)).amax() <= 1e-8 * reach,
                "N = {N}, column {i}: {d} vs {}",
                j.column(i)
            );
        }
    }
}

#[test]
fn jacobian_matches_central_differences_of_tip_pose() {
    let mut rng = Rng(2);
    every_arm!(jacobian_by_differences, rng);
}

fn virtual_work<A: PlanarArm<N>, const N: usize>(arm: &A, rng: &mut Rng) {
    let l = lengths(arm);
    let reach: f64 = l.iter().sum();
    for _ in 0..100 {
        let q = rng.config::<N>();
        let force = Vector2::new(rng.range(-5.0, 5.0), rng.range(-5.0, 5.0));
        let torque = rng.range(-5.0, 5.0);
        let w = Vector3::new(force.x, force.y, torque);
        let tau = arm.joint_torques(&q, &force, torque);
        // The paper's statics, tau_i = T + (r_i + ... + r_N) x F.
        let paper = paper_torques(&l, &q, force, torque);
        assert!(
            (tau - paper).amax() <= 1e-12 * reach * 10.0,
            "{tau} vs {paper}"
        );
        // Virtual work: tau . dq = w . dx for a small displacement dq.
        let dq = SVector::<f64, N>::from_fn(|_, _| rng.range(-1.0, 1.0));
        let h = 1e-6;
        let pose = arm.tip_pose(&q);
        let dx = (pose_vector(&arm.tip_pose(&(q + dq * h)), &pose)
            - pose_vector(&arm.tip_pose(&(q - dq * h)), &pose))
            / (2.0 * h);
        let (work_joints, work_tip) = (tau.dot(&dq), w.dot(&dx));
        assert!(
            (work_joints - work_tip).abs() <= 1e-7 * reach * 10.0 * N as f64,
            "N = {N}: tau . dq = {work_joints}, w . dx = {work_tip}"
        );
    }
}

#[test]
fn joint_torques_do_the_virtual_work_of_the_tip_wrench() {
    let mut rng = Rng(3);
    every_arm!(virtual_work, rng);
}

fn tip_force_round_trip<A: PlanarArm<2> + TipForce>(arm: &A, rng: &mut Rng) {
    for _ in 0..500 {
        let q = rng.config::<2>();
        let s2 = q[1].sin();
        if s2.abs() < 0.05 {
            continue;
        }
        let force = Vector2::new(rng.range(-5.0, 5.0), rng.range(-5.0, 5.0));
        let tau = arm.joint_torques(&q, &force, 0.0);
        let back = arm.tip_force(&q, &tau).unwrap();
        assert!(
            (back - force).norm() <= 1e-12 * force.norm().max(1.0) / s2.abs() * 10.0,
            "{force} came back as {back}"
        );
    }
    for q2 in [0.0, PI, -PI, TAU, 1e-12] {
        let q = Vector2::new(0.3, q2);
        let tau = Vector2::new(1.0, -0.5);
        assert!(
            matches!(arm.tip_force(&q, &tau), Err(ArmError::Singular { .. })),
            "q2 = {q2}"
        );
    }
}

#[test]
fn tip_force_inverts_joint_torques_and_fails_when_singular() {
    let mut rng = Rng(4);
    tip_force_round_trip(&Paper2::default(), &mut rng);
    tip_force_round_trip(&Unequal2::default(), &mut rng);
}

fn tip_wrench_round_trip<A: PlanarArm<3> + TipWrench>(arm: &A, rng: &mut Rng) {
    for _ in 0..500 {
        let q = rng.config::<3>();
        let s2 = q[1].sin();
        if s2.abs() < 0.05 {
            continue;
        }
        let force = Vector2::new(rng.range(-5.0, 5.0), rng.range(-5.0, 5.0));
        let torque = rng.range(-5.0, 5.0);
        let tau = arm.joint_torques(&q, &force, torque);
        let w = arm.tip_wrench(&q, &tau).unwrap();
        let (f, t) = (w.force, w.torque);
        let tol = 1e-12 * force.norm().max(torque.abs()).max(1.0) / s2.abs() * 10.0;
        assert!(
            (f - force).norm() <= tol && (t - torque).abs() <= tol,
            "({force}, {torque}) came back as ({f}, {t})"
        );
    }
    for q2 in [0.0, PI, -PI, TAU] {
        let q = Vector3::new(0.3, q2, -1.1);
        let tau = Vector3::new(1.0, -0.5, 0.25);
        assert!(
            matches!(arm.tip_wrench(&q, &tau), Err(ArmError::Singular { .. })),
            "q2 = {q2}"
        );
    }
}

#[test]
fn tip_wrench_inverts_joint_torques_and_fails_when_singular() {
    let mut rng = Rng(5);
    tip_wrench_round_trip(&Paper3::default(), &mut rng);
    tip_wrench_round_trip(&EqualShort3::default(), &mut rng);
    tip_wrench_round_trip(&Unequal3::default(), &mut rng);
    tip_wrench_round_trip(&Mixed3::default(), &mut rng);
}

// ---------------------------------------------------------------------------------------------
// Work-spaces.

/// The extreme of `|tip|^2` over configurations (`sign = 1` for the minimum, `-1` for the
/// maximum): the best point of a grid of relative angles, then a pattern search.
fn extreme_radius<A: PlanarArm<N>, const N: usize>(arm: &A, sign: f64, steps: usize) -> f64 {
    let objective = |q: &SVector<f64, N>| sign * arm.tip_pose(q).translation.vector.norm_squared();
    let mut best = SVector::<f64, N>::zeros();
    let mut best_value = objective(&best);
    let cells = steps.pow(u32::try_from(N - 1).unwrap());
    #[allow(clippy::cast_precision_loss)]
    let step = TAU / steps as f64;
    for index in 0..cells {
        let mut rest = index;
        let mut q = SVector::<f64, N>::zeros();
        for k in 1..N {
            #[allow(clippy::cast_precision_loss)]
            let angle = (rest % steps) as f64 * step;
            q[k] = angle;
            rest /= steps;
        }
        let value = objective(&q);
        if value < best_value {
            best = q;
            best_value = value;
        }
    }
    let mut h = step;
    while h > 1e-10 {
        let mut improved = false;
        for k in 1..N {
            for delta in [h, -h] {
                let mut q = best;
                q[k] += delta;
                let value = objective(&q);
                if value < best_value {
                    best = q;
                    best_value = value;
                    improved = true;
                }
            }
        }
        if !improved {
            h *= 0.5;
        }
    }
    (sign * best_value).max(0.0).sqrt()
}

fn workspace_by_brute_force<A: PlanarArm<N>, const N: usize>(arm: &A, rng: &mut Rng) {
    let w = arm.workspace();
    let (inner, outer) = (w.inner_radius(), w.outer_radius());
    // Every configuration's tip lies in the annulus.
    for _ in 0..5000 {
        let q = rng.config::<N>();
        let p = Point2::from(arm.tip_pose(&q).translation.vector);
        assert!(w.contains(&p), "N = {N}: {q} reaches {p}, outside {w:?}");
    }
    // The radii reached form the interval [lo, hi]; q1 turns the tip about the base.
    let steps = if N <= 4 { 24 } else { 8 };
    let lo = extreme_radius(arm, 1.0, steps);
    let hi = extreme_radius(arm, -1.0, steps);
    assert!(
        (lo - inner).abs() <= 1e-6,
        "N = {N}: inner {inner}, sampled {lo}"
    );
    assert!(
        (hi - outer).abs() <= 1e-9,
        "N = {N}: outer {outer}, sampled {hi}"
    );
    // So a point is reachable exactly when lo <= |p| <= hi.
    let margin = 1e-4;
    let (mut inside, mut outside) = (0, 0);
    for _ in 0..2000 {
        let rho = rng.range(0.0, 1.2 * outer);
        if (rho - lo).abs() < margin || (rho - hi).abs() < margin {
            continue;
        }
        let theta = rng.angle();
        let p = Point2::new(rho * theta.cos(), rho * theta.sin());
        let reachable = lo <= rho && rho <= hi;
        assert_eq!(w.contains(&p), reachable, "N = {N}: {p}");
        if reachable {
            inside += 1;
        } else {
            outside += 1;
        }
    }
    assert!(inside > 100 && outside > 100);
}

#[test]
fn workspace_contains_exactly_the_sampled_reach() {
    let mut rng = Rng(6);
    every_arm!(workspace_by_brute_force, rng);
}

fn dexterous_by_brute_force<A>(arm: &A, rng: &mut Rng) -> DexterousWorkspace
where
    A: PlanarArm<3> + ClosedFormIk<3, Target = Isometry2<f64>>,
{
    let l = lengths(arm);
    let d = DexterousWorkspace::of_lengths(l[0], l[1], l[2]);
    let (a, b) = ((l[0] - l[1]).abs(), l[0] + l[1]);
    let all = arm.workspace();
    let orientations = 360;
    let (mut inside, mut outside) = (0, 0);
    for _ in 0..1500 {
        let rho = rng.range(0.0, l.iter().sum());
        // Stay clear of the boundary circles, where a finite set of orientations may miss.
        let margin = 2e-3;
        if (rho + l[2] - b).abs() < margin || ((rho - l[2]).abs() - a).abs() < margin {
            continue;
        }
        let theta = rng.angle();
        let p = Vector2::new(rho * theta.cos(), rho * theta.sin());
        let offset = rng.angle();
        let every = (0..orientations).all(|k| {
            let phi = offset + f64::from(k) * TAU / f64::from(orientations);
            arm.inverse_kinematics(&Isometry2::new(p, phi)).is_ok()
        });
        assert_eq!(d.contains(&Point2::from(p)), every, "{l:?} at {p}");
        if every {
            inside += 1;
            assert!(all.contains(&Point2::from(p)));
        } else {
            outside += 1;
        }
    }
    assert!(
        inside > 50 && outside > 50,
        "{inside} inside, {outside} outside"
    );
    d
}

#[test]
fn dexterous_workspace_matches_brute_force_over_orientations() {
    let mut rng = Rng(7);
    // Equal first links: one disk of radius 2 l - l3 (the paper's claim).
    for d in [
        dexterous_by_brute_force(&Paper3::default(), &mut rng),
        dexterous_by_brute_force(&EqualShort3::default(), &mut rng),
    ] {
        assert_eq!(d.annulus(), None);
        assert!(d.disk_radius().is_some());
    }
    assert_eq!(
        DexterousWorkspace::of_lengths(1.0, 1.0, 1.0).disk_radius(),
        Some(1.0)
    );
    assert!(
        (DexterousWorkspace::of_lengths(1.0, 1.0, 0.4)
            .disk_radius()
            .unwrap()
            - 1.6)
            .abs()
            < 1e-15
    );
    // l3 < |l1 - l2|: an annulus l3 + |l1 - l2| ..= l1 + l2 - l3.
    let d = dexterous_by_brute_force(&Unequal3::default(), &mut rng);
    assert_eq!(d.disk_radius(), None);
    let (i, o) = d.annulus().unwrap();
    assert!((i - 0.65).abs() < 1e-12 && (o - 1.35).abs() < 1e-12);
    // |l1 - l2| < l3 <= min(l1, l2): that annulus and a disk of radius l3 - |l1 - l2|.
    let d = dexterous_by_brute_force(&Mixed3::default(), &mut rng);
    assert!((d.disk_radius().unwrap() - 0.2).abs() < 1e-12);
    let (i, o) = d.annulus().unwrap();
    assert!((i - 0.8).abs() < 1e-12 && (o - 1.2).abs() < 1e-12);
}

// ---------------------------------------------------------------------------------------------
// Polar form, joint positions, manipulability.

fn polar_form<A: PlanarArm<N>, const N: usize>(arm: &A, rng: &mut Rng) {
    for _ in 0..200 {
        let q = rng.config::<N>();
        let (r, theta) = arm.tip_polar(&q);
        let tip = arm.tip_pose(&q).translation.vector;
        assert!((r - tip.norm()).abs() <= 1e-12 * (1.0 + r));
        if r > 1e-6 {
            assert!(angle_gap(theta, tip.y.atan2(tip.x)) <= 1e-9);
        }
        // r does not depend on q1; theta turns with it.
        let mut turned = q;
        let delta = rng.angle();
        turned[0] += delta;
        let (r2, theta2) = arm.tip_polar(&turned);
        assert!((r2 - r).abs() <= 1e-12 * (1.0 + r), "N = {N}: {r} vs {r2}");
        if r > 1e-6 {
            assert!(angle_gap(theta2, theta + delta) <= 1e-9);
        }
    }
}

#[test]
fn tip_polar_radius_is_independent_of_q1() {
    let mut rng = Rng(8);
    every_arm!(polar_form, rng);
}

fn joint_positions_chain<A: PlanarArm<N>, const N: usize>(arm: &A, rng: &mut Rng) {
    let l = lengths(arm);
    for _ in 0..200 {
        let q = rng.config::<N>();
        let joints = arm.joint_positions(&q);
        assert_eq!(joints[0], Point2::origin());
        let mut phi = 0.0;
        for k in 0..N {
            phi += q[k];
            let next = if k + 1 < N {
                joints[k + 1].coords
            } else {
                arm.tip_pose(&q).translation.vector
            };
            let link = next - joints[k].coords;
            assert!(
                (link - Vector2::new(phi.cos(), phi.sin()) * l[k]).norm() <= 1e-12 * (1.0 + l[k]),
                "N = {N}, link {k}"
            );
        }
        assert!(angle_gap(arm.tip_pose(&q).rotation.angle(), phi) <= 1e-12);
    }
}

#[test]
fn joint_positions_are_consistent_with_tip_pose() {
    let mut rng = Rng(9);
    every_arm!(joint_positions_chain, rng);
}

#[test]
fn manipulability_is_l1_l2_sin_q2() {
    let mut rng = Rng(10);
    fn check<A: PlanarArm<N>, const N: usize>(arm: &A, rng: &mut Rng) {
        let l = lengths(arm);
        for _ in 0..500 {
            let q = rng.config::<N>();
            let expected = (l[0] * l[1] * q[1].sin()).abs();
            assert!((arm.manipulability(&q) - expected).abs() <= 1e-12);
        }
        for q2 in [0.0, PI] {
            let mut q = rng.config::<N>();
            q[1] = q2;
            assert!(arm.manipulability(&q) <= 1e-12);
            assert!(arm.is_singular(&q, 1e-9));
        }
        let mut q = rng.config::<N>();
        q[1] = FRAC_PI_2;
        assert!((arm.manipulability(&q) - l[0] * l[1]).abs() <= 1e-12);
        assert!(!arm.is_singular(&q, 1e-9));
    }
    // Two links: sqrt(det J J^T) = |det J| = |l1 l2 s2|; three links: the paper's det A.
    check(&Paper2::default(), &mut rng);
    check(&Unequal2::default(), &mut rng);
    check(&Paper3::default(), &mut rng);
    check(&Unequal3::default(), &mut rng);
    check(&Mixed3::default(), &mut rng);
}

// ---------------------------------------------------------------------------------------------
// Damped least squares for redundant arms.

fn dls_converges<A: PlanarArm<N>, const N: usize>(arm: &A, rng: &mut Rng) {
    let options = DlsOptions::default();
    for pose in [false, true] {
        for _ in 0..40 {
            let truth = rng.config::<N>();
            let seed = truth + SVector::<f64, N>::from_fn(|_, _| rng.range(-0.2, 0.2));
            let goal = arm.tip_pose(&truth);
            let target = if pose {
                IkTarget::Pose(goal)
            } else {
                IkTarget::Position(Point2::from(goal.translation.vector))
            };
            let q = arm
                .inverse_kinematics_near(&target, &seed, &options)
                .unwrap_or_else(|e| panic!("N = {N}, pose {pose}: {e}"));
            let (tip, phi) = fk(&lengths(arm), &q);
            assert!((tip - goal.translation.vector).norm() <= 1e-10);
            if pose {
                assert!(angle_gap(phi, goal.rotation.angle()) <= 1e-10);
            }
            assert!(
                (q - seed).norm() <= 1.5 * (truth - seed).norm() + 1e-9,
                "N = {N}: wandered {} from the seed",
                (q - seed).norm()
            );
        }
    }
    // Beyond reach: refused before iterating, 0.5 beyond the outer circle.
    let outer = arm.workspace().outer_radius();
    let far = IkTarget::Position(Point2::new(0.0, outer + 0.5));
    let seed = SVector::<f64, N>::from_fn(|i, _| if i == 0 { 1.2 } else { 0.1 });
    match arm.inverse_kinematics_near(&far, &seed, &options) {
        Err(ArmError::Unreachable {
            target,
            distance,
            orientation: None,
            ..
        }) => {
            assert_eq!(target, [0.0, outer + 0.5]);
            assert!((distance - 0.5).abs() < 1e-12, "distance {distance}");
        }
        other => panic!("N = {N}: expected Unreachable, got {other:?}"),
    }
    // Inside the hole of an annulus: refused, by the distance to the inner circle.
    let inner = arm.workspace().inner_radius();
    if inner > 0.0 {
        let hole = IkTarget::Position(Point2::new(0.5 * inner, 0.0));
        match arm.inverse_kinematics_near(&hole, &seed, &options) {
            Err(ArmError::Unreachable { distance, .. }) => {
                assert!((distance - 0.5 * inner).abs() < 1e-12);
            }
            other => panic!("N = {N}: expected Unreachable, got {other:?}"),
        }
    }
    // A pose whose position is in reach but whose wrist (the last joint) is not.
    let l = lengths(arm);
    let wrist_reach = outer - l[N - 1];
    let pose = IkTarget::Pose(Isometry2::new(Vector2::new(wrist_reach + 0.1, 0.0), PI));
    match arm.inverse_kinematics_near(&pose, &seed, &options) {
        Err(ArmError::Unreachable {
            target,
            orientation: Some(phi),
            radius,
            ..
        }) => {
            assert_eq!(target, [wrist_reach + 0.1, 0.0]);
            assert!(angle_gap(phi, PI) < 1e-15);
            assert!((radius - (wrist_reach + 0.1 + l[N - 1])).abs() < 1e-12);
        }
        other => panic!("N = {N}: expected Unreachable, got {other:?}"),
    }
}

#[test]
fn damped_least_squares_for_four_and_six_links() {
    let mut rng = Rng(11);
    dls_converges(&Four::default(), &mut rng);
    dls_converges(&Six::default(), &mut rng);
}

/// The case: a six-link target at full reach (the arm stretched, the Jacobian singular
/// at the solution) stopped at a residual of 1.3e-10 against the default tolerance 1e-10.
fn dls_on_the_boundary<A: PlanarArm<N>, const N: usize>(arm: &A, rng: &mut Rng) -> usize {
    let options = DlsOptions::default();
    let outer = arm.workspace().outer_radius();
    let mut worst_iterations = 0;
    for k in 0..40 {
        let theta = rng.angle();
        // On the circle, and just outside it within the reach tolerance.
        let r = if k % 2 == 0 {
            outer
        } else {
            outer * (1.0 + 0.5 * REACH_TOLERANCE)
        };
        let goal = Point2::new(r * theta.cos(), r * theta.sin());
        let seed = SVector::<f64, N>::from_fn(|i, _| if i == 0 { theta } else { 0.0 })
            + rng.config::<N>() * 0.1;
        let q = arm
            .inverse_kinematics_near(&IkTarget::Position(goal), &seed, &options)
            .unwrap_or_else(|e| panic!("N = {N}, r = {r}: {e}"));
        let (tip, _) = fk(&lengths(arm), &q);
        let on_circle = goal.coords * (outer / r);
        assert!(
            (tip - on_circle).norm() <= 1e-10,
            "{}",
            (tip - on_circle).norm()
        );
        // Stretched: every relative angle a multiple of 2 pi, to within sqrt of the tolerance.
        assert!(q.iter().skip(1).all(|a| angle_gap(*a, 0.0) < 1e-4), "{q}");
        let mut counted = DlsOptions {
            max_iterations: 0,
            ..options
        };
        while arm
            .inverse_kinematics_near(&IkTarget::Position(goal), &seed, &counted)
            .is_err()
        {
            counted.max_iterations += 1;
        }
        worst_iterations = worst_iterations.max(counted.max_iterations);
        // A pose at full reach: the orientation must point along the radius.
        let pose = IkTarget::Pose(Isometry2::new(on_circle, theta));
        let q = arm
            .inverse_kinematics_near(&pose, &seed, &options)
            .unwrap_or_else(|e| panic!("N = {N}, pose: {e}"));
        let (tip, phi) = fk(&lengths(arm), &q);
        assert!((tip - on_circle).norm() <= 1e-10 && angle_gap(phi, theta) <= 1e-10);
    }
    worst_iterations
}

#[test]
fn damped_least_squares_converges_at_full_reach() {
    let mut rng = Rng(31);
    let four = dls_on_the_boundary(&Four::default(), &mut rng);
    let six = dls_on_the_boundary(&Six::default(), &mut rng);
    assert!(four <= 100 && six <= 100, "{four} {six}");
    println!("iterations at full reach, at most: four links {four}, six links {six}");
}

#[test]
fn damped_least_squares_respects_joint_limits() {
    let arm = Six::default();
    let l = lengths(&arm);
    let mut rng = Rng(32);
    let limits: [(f64, f64); 6] =
        core::array::from_fn(|i| if i == 0 { (-PI, PI) } else { (-0.1, 1.2) });
    let options = DlsOptions {
        limits: Some(limits),
        ..DlsOptions::default()
    };
    let inside = |q: &SVector<f64, 6>| {
        q.iter()
            .zip(&limits)
            .all(|(a, (lo, hi))| lo <= a && a <= hi)
    };
    let (mut solved, mut blocked) = (0, 0);
    for _ in 0..200 {
        // A target reached by some configuration within the limits.
        let truth = SVector::<f64, 6>::from_fn(|i, _| {
            let (lo, hi) = limits[i];
            rng.range(lo.max(-3.0), hi.min(3.0))
        });
        let goal = arm.tip_pose(&truth);
        let seed = SVector::<f64, 6>::from_fn(|i, _| if i == 0 { truth[0] } else { 0.5 });
        match arm.inverse_kinematics_near(
            &IkTarget::Position(Point2::from(goal.translation.vector)),
            &seed,
            &options,
        ) {
            Ok(q) => {
                solved += 1;
                assert!(inside(&q), "{q} outside the limits");
                let (tip, _) = fk(&l, &q);
                assert!((tip - goal.translation.vector).norm() <= 1e-10);
            }
            Err(ArmError::NoConvergence { .. }) => blocked += 1,
            Err(e) => panic!("{e}"),
        }
    }
    assert!(solved > 150, "{solved} solved, {blocked} blocked");
    // The seed is clamped into the limits, and a target reachable only by bending a joint
    // beyond its limit is not reached: the arm folded back on itself needs q2 = pi.
    let folded = IkTarget::Position(Point2::new(l[0] - l[1] - l[2] + 0.05, 0.0));
    let free = arm.inverse_kinematics_near(&folded, &SVector::repeat(0.5), &DlsOptions::default());
    assert!(free.is_ok());
    let limited = arm.inverse_kinematics_near(&folded, &SVector::repeat(2.0), &options);
    match limited {
        Err(ArmError::NoConvergence { .. }) => {}
        Ok(q) => assert!(inside(&q), "{q}"),
        other => panic!("{other:?}"),
    }
    // A joint held at a limit: only q1 free, the others pinned to [0.2, 0.2].
    let pinned: [(f64, f64); 6] =
        core::array::from_fn(|i| if i == 0 { (-10.0, 10.0) } else { (0.2, 0.2) });
    let q_pinned = SVector::<f64, 6>::from_fn(|i, _| if i == 0 { 1.0 } else { 0.2 });
    let goal = Point2::from(arm.tip_pose(&q_pinned).translation.vector);
    let q = arm
        .inverse_kinematics_near(
            &IkTarget::Position(goal),
            &SVector::zeros(),
            &DlsOptions {
                limits: Some(pinned),
                ..DlsOptions::default()
            },
        )
        .unwrap();
    assert!(
        q.iter().skip(1).all(|a| *a == 0.2) && angle_gap(q[0], 1.0) < 1e-9,
        "{q}"
    );
    // Bad limits are errors.
    let mut reversed = limits;
    reversed[2] = (1.0, -1.0);
    assert_eq!(
        arm.inverse_kinematics_near(
            &folded,
            &SVector::zeros(),
            &DlsOptions {
                limits: Some(reversed),
                ..DlsOptions::default()
            }
        ),
        Err(ArmError::OutOfRange {
            what: "joint limits",
            link: Some(2),
            value: 1.0
        })
    );
    let mut nan = limits;
    nan[4].1 = f64::NAN;
    assert_eq!(
        arm.inverse_kinematics_near(
            &folded,
            &SVector::zeros(),
            &DlsOptions {
                limits: Some(nan),
                ..DlsOptions::default()
            }
        ),
        Err(ArmError::NonFinite {
            argument: "options"
        })
    );
}

#[test]
fn dexterous_workspace_of_derived_arms() {
    use planar_arm::kinematics::DexterousWorkspaceExt;
    let mut rng = Rng(33);
    fn check<A>(arm: &A, rng: &mut Rng)
    where
        A: PlanarArm<3> + ClosedFormIk<3, Target = Isometry2<f64>>,
    {
        // The method agrees with the brute-force sampling over orientations.
        assert_eq!(
            arm.dexterous_workspace(),
            dexterous_by_brute_force(arm, rng)
        );
    }
    check(&Paper3::default(), &mut rng);
    check(&Unequal3::default(), &mut rng);
    check(&Mixed3::default(), &mut rng);
}

fn skeleton_chain<A: PlanarArm<N>, const N: usize>(arm: &A, rng: &mut Rng) {
    let l = lengths(arm);
    for _ in 0..100 {
        let q = rng.config::<N>();
        let skeleton = planar_arm::kinematics::Skeleton::of(arm, &q);
        let points: Vec<Point2<f64>> = skeleton.points().collect();
        assert_eq!(points.len(), N + 1);
        assert_eq!(skeleton.points().len(), N + 1);
        assert_eq!(points[0], Point2::origin());
        assert_eq!(&points[..N], &arm.joint_positions(&q)[..]);
        // The last point is the tip of the independent forward kinematics; each segment is a link.
        let (tip, _) = fk(&l, &q);
        assert!((points[N].coords - tip).norm() <= 1e-12);
        let mut phi = 0.0;
        for (k, (start, end)) in skeleton.links().enumerate() {
            phi += q[k];
            assert!(((end - start) - Vector2::new(phi.cos(), phi.sin()) * l[k]).norm() <= 1e-12);
            assert_eq!(
                (Some(start), Some(end)),
                (skeleton.get(k), skeleton.get(k + 1))
            );
        }
        assert_eq!(skeleton.get(N + 1), None);
        assert_eq!(skeleton.points().next_back(), Some(skeleton.tip));
    }
}

#[test]
fn skeleton_gives_every_joint_and_the_tip() {
    let mut rng = Rng(34);
    every_arm!(skeleton_chain, rng);
}

#[test]
fn arms_of_one_size_share_a_vec_of_trait_objects() {
    use planar_arm::kinematics::DynArm;
    let arms: Vec<Box<dyn DynArm<2>>> =
        vec![Box::new(Paper2::default()), Box::new(Unequal2::default())];
    let mut rng = Rng(35);
    let (paper, unequal) = (Paper2::default(), Unequal2::default());
    for _ in 0..50 {
        let (q, qd, qdd) = (rng.config::<2>(), rng.config::<2>(), rng.config::<2>());
        // Through the box: the same numbers as the concrete arm's own methods.
        assert_eq!(
            arms[0].inverse_dynamics(&q, &qd, &qdd),
            paper.inverse_dynamics(&q, &qd, &qdd)
        );
        assert_eq!(
            arms[1].inverse_dynamics(&q, &qd, &qdd),
            unequal.inverse_dynamics(&q, &qd, &qdd)
        );
        assert_eq!(arms[1].mass_matrix(&q), unequal.mass_matrix(&q));
        assert_eq!(arms[1].tip_pose(&q), unequal.tip_pose(&q));
        assert_eq!(arms[1].jacobian(&q), unequal.jacobian(&q));
        for arm in &arms {
            let tau = arm.inverse_dynamics(&q, &qd, &qdd);
            assert!((arm.forward_dynamics(&q, &qd, &tau) - qdd).norm() < 1e-9);
            let (tip, _) = fk(&arm.links().map(|l| l.length), &q);
            assert!((arm.tip_pose(&q).translation.vector - tip).norm() < 1e-12);
            assert_eq!(
                arm.skeleton(&q).tip,
                Point2::from(arm.tip_pose(&q).translation.vector)
            );
        }
    }
    assert_eq!(arms[1].workspace(), unequal.workspace());
    // Send + Sync arms box as such, for threads.
    let shared: Box<dyn DynArm<2> + Send + Sync> = Box::new(Paper2::default());
    assert_eq!(
        shared.gravity(&Vector2::zeros()),
        paper.gravity(&Vector2::zeros())
    );
}

#[test]
fn error_messages_name_the_target_with_rounded_numbers() {
    // Two links, 0.001 beyond the outer circle 2.3 (computed, so not exactly 0.001).
    let arm = Unequal2::default();
    let e = arm
        .inverse_kinematics(&Point2::new(2.301, 0.0))
        .unwrap_err();
    assert_eq!(
        e.to_string(),
        "target (2.301, 0) is 0.001 beyond the reachable annulus 0.7 ..= 2.3 (it lies 2.301 from the base)"
    );
    // Three links: the message names the tip pose asked for, then the wrist it implies.
    let arm = Unequal3::default();
    let e = arm
        .inverse_kinematics(&Isometry2::new(Vector2::new(1.9, 0.0), 0.0))
        .unwrap_err();
    match e {
        ArmError::Unreachable {
            target,
            orientation,
            radius,
            ..
        } => {
            assert_eq!((target, orientation), ([1.9, 0.0], Some(0.0)));
            assert!((radius - 1.65).abs() < 1e-12);
        }
        ref other => panic!("{other:?}"),
    }
    assert_eq!(
        e.to_string(),
        "target (1.9, 0) with the last link at 0 rad is unreachable: its wrist point lies 1.65 from \
         the base, 0.05 beyond the annulus 0.4 ..= 1.6 the links before the last reach"
    );
}

// ---------------------------------------------------------------------------------------------
// The paper's worked claims.

#[test]
fn paper_claims_about_two_links() {
    // Equal links: the work-space is a disk (inner radius 0) of radius 2 l.
    let w = Paper2::default().workspace();
    assert_eq!((w.inner_radius(), w.outer_radius()), (0.0, 2.0));
    // Unequal links: an annulus |l1 - l2| ..= l1 + l2 whose average radius is the longer link.
    let u = Unequal2::default().workspace();
    let (inner, outer) = (u.inner_radius(), u.outer_radius());
    assert!((inner - 0.7).abs() < 1e-15 && (outer - 2.3).abs() < 1e-15);
    assert!(((inner + outer) / 2.0 - 1.5).abs() < 1e-15);

    // Equal links: x = 2 l cos(q2/2) cos(q1 + q2/2), r = 2 l |cos(q2/2)|, theta = q1 + q2/2.
    let arm = Paper2::default();
    let mut rng = Rng(12);
    for _ in 0..200 {
        let q = rng.config::<2>();
        let tip = arm.tip_pose(&q).translation.vector;
        let (half, mid) = (q[1] / 2.0, q[0] + q[1] / 2.0);
        assert!((tip.x - 2.0 * half.cos() * mid.cos()).abs() < 1e-12);
        assert!((tip.y - 2.0 * half.cos() * mid.sin()).abs() < 1e-12);
        let (r, theta) = arm.tip_polar(&q);
        assert!((r - 2.0 * half.cos().abs()).abs() < 1e-12);
        if r > 1e-6 {
            // theta = q1 + q2/2, or q1 + q2/2 + pi when cos(q2/2) < 0.
            let shift = if half.cos() < 0.0 { PI } else { 0.0 };
            assert!(angle_gap(theta, mid + shift) < 1e-9);
        }
    }

    // Singular poses at q2 = 0 (outer boundary) and pi (inner boundary).
    fn singular_at<A: PlanarArm<2> + TipForce>(arm: &A) {
        let w = arm.workspace();
        for q1 in [-1.0, 0.0, 2.0] {
            let stretched = Vector2::new(q1, 0.0);
            let folded = Vector2::new(q1, PI);
            assert!((arm.tip_polar(&stretched).0 - w.outer_radius()).abs() < 1e-12);
            assert!((arm.tip_polar(&folded).0 - w.inner_radius()).abs() < 1e-12);
            for q in [stretched, folded] {
                assert!(arm.manipulability(&q) < 1e-12);
                assert!(matches!(
                    arm.tip_force(&q, &Vector2::new(1.0, 1.0)),
                    Err(ArmError::Singular { .. })
                ));
            }
        }
    }
    singular_at(&Paper2::default());
    singular_at(&Unequal2::default());
}
