//! Work-spaces of two and three revolute links with joint ranges: `contains` against the
//! inverse kinematics on grids, the region against configurations sampled inside the ranges
//! (brute force), its radii and areas against sampling and against closed forms.

use core::f64::consts::PI;

use planar_arm::kinematics::{ik2_in_ranges, ik3_position, ClosedFormIk, Workspace};
use planar_arm::nalgebra::{Isometry2, Point2, Vector2};
use planar_arm::prelude::*;
use planar_arm::{ArmError, Joint, Link};

/// An elbow that bends one way only.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct Elbow {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 0.7, mass = 1, range = (0.3, 2.2))]
    fore: Revolute,
}

/// Both joints limited, the elbow's range across pi.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct Both {
    #[arm(length = 0.8, mass = 1, range = (-1, 1.5))]
    upper: Revolute,
    #[arm(length = 0.6, mass = 1, range = (2.5, 4))]
    fore: Revolute,
}

/// Only the shoulder limited.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct Shoulder {
    #[arm(length = 0.5, mass = 1, range = (0, 2))]
    upper: Revolute,
    #[arm(length = 0.9, mass = 1)]
    fore: Revolute,
}

/// Three links, each limited.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct Three {
    #[arm(length = 1, mass = 1, range = (-0.5, 2))]
    upper: Revolute,
    #[arm(length = 0.8, mass = 1, range = (0.2, 2.4))]
    fore: Revolute,
    #[arm(length = 0.5, mass = 1, range = (-1.5, 0.5))]
    hand: Revolute,
}

/// Three links, the last two limited, the first free.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct Wrist {
    #[arm(length = 0.6, mass = 1)]
    upper: Revolute,
    #[arm(length = 0.6, mass = 1, range = (-2.8, 2.8))]
    fore: Revolute,
    #[arm(length = 0.9, mass = 1, range = (0.5, 1.5))]
    hand: Revolute,
}

struct Rng(u64);

impl Rng {
    fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }

    fn within(&mut self, (lo, hi): (f64, f64)) -> f64 {
        lo + (hi - lo) * self.unit()
    }
}

fn range_or_turn(link: &Link) -> (f64, f64) {
    link.range.unwrap_or((-PI, PI))
}

/// The tip of revolute links at `q`, summed independently of the crate.
fn tip(links: &[Link], q: &[f64]) -> Vector2<f64> {
    let (mut p, mut angle) = (Vector2::zeros(), 0.0);
    for (l, qi) in links.iter().zip(q) {
        angle += qi;
        p += Vector2::new(angle.cos(), angle.sin()) * l.length;
    }
    p
}

/// Whether `v` lies in `range` up to a multiple of 2 pi (with a little slack).
fn fits(v: f64, range: Option<(f64, f64)>) -> bool {
    let Some((lo, hi)) = range else { return true };
    let k = ((lo - 1e-9 - v) / (2.0 * PI)).ceil();
    v + 2.0 * PI * k <= hi + 1e-9
}

/// Points on a grid over the square that holds the work-space.
fn grid(reach: f64, steps: usize) -> impl Iterator<Item = Point2<f64>> {
    let h = 2.2 * reach / steps as f64;
    (0..=steps).flat_map(move |i| {
        (0..=steps).map(move |j| {
            // Off the lattice by an irrational fraction, so that no point sits on a boundary
            // by construction.
            Point2::new(
                -1.1 * reach + h * (i as f64 + 0.3137),
                -1.1 * reach + h * (j as f64 + 0.271),
            )
        })
    })
}

fn two_link_agrees<A: PlanarArm<2> + ClosedFormIk<2, Target = Point2<f64>>>(arm: &A) -> usize {
    let w = arm.workspace();
    assert!(w.is_exact());
    let links = arm.links();
    let mut inside = 0;
    for p in grid(links[0].length + links[1].length, 120) {
        let ik = arm.inverse_kinematics(&p);
        assert_eq!(w.contains(&p), ik.is_ok(), "{p}: {ik:?}");
        if let Ok(solutions) = ik {
            inside += 1;
            for q in solutions {
                assert!(
                    (tip(&links, q.as_slice()) - p.coords).norm() < 1e-9,
                    "{p}: {q}"
                );
                for (i, l) in links.iter().enumerate() {
                    let (lo, hi) = l.range.unwrap_or((-PI, PI));
                    assert!(q[i] >= lo - 1e-9 && q[i] <= hi + 1e-9, "{p}: {q}");
                }
            }
        }
    }
    inside
}

#[test]
fn two_link_contains_is_what_the_inverse_kinematics_reach() {
    // Each arm has points inside and outside its region within the annulus of free joints.
    for inside in [
        two_link_agrees(&Elbow::default()),
        two_link_agrees(&Both::default()),
        two_link_agrees(&Shoulder::default()),
    ] {
        assert!(inside > 500, "{inside}");
    }
}

/// Configurations sampled within the ranges reach only contained points.
fn sampled_tips_are_contained(links: &[Link], rng: &mut Rng) {
    let w = Workspace::of_links(links);
    for _ in 0..3000 {
        let q: Vec<f64> = links.iter().map(|l| rng.within(range_or_turn(l))).collect();
        let p = Point2::from(tip(links, &q));
        assert!(w.contains(&p), "{q:?} -> {p}");
    }
}

#[test]
fn ranged_regions_hold_every_sampled_configuration() {
    let mut rng = Rng(3);
    sampled_tips_are_contained(&Elbow::default().links(), &mut rng);
    sampled_tips_are_contained(&Both::default().links(), &mut rng);
    sampled_tips_are_contained(&Shoulder::default().links(), &mut rng);
    sampled_tips_are_contained(&Three::default().links(), &mut rng);
    sampled_tips_are_contained(&Wrist::default().links(), &mut rng);
}

/// Whether some `q1` (of `samples` in its range) leaves the point within the last two links'
/// reach and ranges: a brute-force answer to the three-link position problem.
fn brute_force_three(links: &[Link; 3], p: &Point2<f64>, samples: usize) -> bool {
    let (lo, hi) = range_or_turn(&links[0]);
    (0..=samples).any(|k| {
        let q1 = lo + (hi - lo) * k as f64 / samples as f64;
        let v = Vector2::new(
            p.x * q1.cos() + p.y * q1.sin(),
            p.y * q1.cos() - p.x * q1.sin(),
        ) - Vector2::new(links[0].length, 0.0);
        ik2_in_ranges(
            links[1].length,
            links[2].length,
            [links[1].range, links[2].range],
            &v.into(),
        )
        .is_ok()
    })
}

fn three_link_agrees<A: PlanarArm<3> + ClosedFormIk<3, Target = Isometry2<f64>>>(
    arm: &A,
    rng: &mut Rng,
) {
    let links = arm.links();
    let w = arm.workspace();
    assert!(w.is_exact());
    let ranges = links.map(|l| l.range);
    let reach: f64 = links.iter().map(|l| l.length).sum();
    let (mut inside, mut outside) = (0, 0);
    for p in grid(reach, 60) {
        let ik = ik3_position(
            links[0].length,
            links[1].length,
            links[2].length,
            ranges,
            &p,
        );
        assert_eq!(w.contains(&p), ik.is_ok(), "{p}");
        match ik {
            Ok(q) => {
                inside += 1;
                assert!(
                    (tip(&links, q.as_slice()) - p.coords).norm() < 1e-9,
                    "{p}: {q}"
                );
                for i in 0..3 {
                    assert!(fits(q[i], ranges[i]), "{p}: {q}");
                    if let Some((lo, hi)) = ranges[i] {
                        assert!(q[i] >= lo && q[i] <= hi, "{p}: {q} not the representative");
                    }
                }
            }
            Err(e) => {
                outside += 1;
                assert!(!brute_force_three(&links, &p, 2000), "{p}: {e}");
            }
        }
    }
    assert!(inside > 300 && outside > 300, "{inside} {outside}");
    // A pose the closed form reaches has its position in the region.
    let mut poses = 0;
    for _ in 0..2000 {
        let pose = Isometry2::new(
            Vector2::new(rng.within((-reach, reach)), rng.within((-reach, reach))),
            rng.within((-PI, PI)),
        );
        if arm.inverse_kinematics(&pose).is_ok() {
            poses += 1;
            assert!(w.contains(&Point2::from(pose.translation.vector)), "{pose}");
        }
    }
    assert!(poses > 20, "{poses}");
}

#[test]
fn three_link_contains_is_what_the_position_inverse_kinematics_reach() {
    let mut rng = Rng(11);
    three_link_agrees(&Three::default(), &mut rng);
    three_link_agrees(&Wrist::default(), &mut rng);
}

/// `(min, max)` of `|tip|` over a grid of the joints after the first (which alone set the
/// distance from the base), the ends of each range included.
fn grid_radii(links: &[Link], steps: usize) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, 0.0_f64);
    let value = |l: &Link, k: usize| {
        let (a, b) = range_or_turn(l);
        a + (b - a) * k as f64 / steps as f64
    };
    let count = if links.len() == 3 { steps + 1 } else { 1 };
    for i in 0..=steps {
        for j in 0..count {
            let mut q = vec![0.0, value(&links[1], i)];
            if links.len() == 3 {
                q.push(value(&links[2], j));
            }
            let r = tip(links, &q).norm();
            lo = lo.min(r);
            hi = hi.max(r);
        }
    }
    (lo, hi)
}

#[test]
fn ranged_radii_are_attained() {
    for links in [
        Elbow::default().links().to_vec(),
        Both::default().links().to_vec(),
        Shoulder::default().links().to_vec(),
        Three::default().links().to_vec(),
        Wrist::default().links().to_vec(),
    ] {
        let w = Workspace::of_links(&links);
        let (lo, hi) = grid_radii(&links, 1500);
        assert!(
            lo >= w.inner_radius() - 1e-12 && hi <= w.outer_radius() + 1e-12,
            "{links:?}"
        );
        assert!(
            lo - w.inner_radius() < 1e-5 && w.outer_radius() - hi < 1e-5,
            "{lo} {hi} {w:?}"
        );
    }
}

#[test]
fn ranged_areas_match_closed_forms() {
    // A one-way elbow whose range lies in (0, pi) and a limited shoulder: no configuration is
    // reached twice, so the area is the integral of |det J| = l1 l2 |sin q2| over the box:
    // w l1 l2 (cos a - cos b).
    let links = [
        Link::rod(1.0, 1.0).with_range(-0.4, 1.1),
        Link::rod(0.7, 1.0).with_range(0.3, 2.2),
    ];
    let exact = 1.5 * 0.7 * (0.3_f64.cos() - 2.2_f64.cos());
    let area = Workspace::of_links(&links).area();
    assert!((area - exact).abs() < 1e-9 * exact, "{area} {exact}");
    // A free shoulder sweeps the elbow's annulus, whatever the elbow's range.
    let w = Workspace::of_links(&Elbow::default().links());
    let (r1, r2) = (w.inner_radius(), w.outer_radius());
    let exact = PI * (r2 * r2 - r1 * r1);
    assert!(
        (w.area() - exact).abs() < 1e-9 * exact,
        "{} {exact}",
        w.area()
    );
    // The radii of that annulus, from the law of cosines at the range's ends.
    let law = |q: f64| (1.0 + 0.49 + 1.4 * q.cos()).sqrt();
    assert!((r1 - law(2.2)).abs() < 1e-12 && (r2 - law(0.3)).abs() < 1e-12);
}

/// The fraction of random points in the square about the base that `w` contains, times the
/// square's area: an estimate of the area within a few standard errors.
fn monte_carlo_area(w: &Workspace, reach: f64, rng: &mut Rng, n: usize) -> (f64, f64) {
    let hits = (0..n)
        .filter(|_| {
            w.contains(&Point2::new(
                rng.within((-reach, reach)),
                rng.within((-reach, reach)),
            ))
        })
        .count();
    let square = 4.0 * reach * reach;
    let p = hits as f64 / n as f64;
    (square * p, square * (p * (1.0 - p) / n as f64).sqrt())
}

#[test]
fn ranged_areas_match_sampling() {
    let mut rng = Rng(17);
    for links in [
        Both::default().links().to_vec(),
        Shoulder::default().links().to_vec(),
        Three::default().links().to_vec(),
        Wrist::default().links().to_vec(),
    ] {
        let w = Workspace::of_links(&links);
        let reach: f64 = links.iter().map(|l| l.length).sum();
        let (estimate, error) = monte_carlo_area(&w, reach, &mut rng, 40_000);
        assert!(
            (w.area() - estimate).abs() < 4.0 * error,
            "{links:?}: {} vs {estimate} +- {error}",
            w.area()
        );
    }
}

#[test]
fn a_range_miss_names_the_joint_and_its_unit() {
    let arm = Elbow::default();
    // Straight out along +x needs the elbow at 0, below its range's 0.3 rad.
    let e = arm.inverse_kinematics(&Point2::new(1.7, 0.0)).unwrap_err();
    let ArmError::BeyondJointRange {
        joint,
        kind,
        excess,
        ..
    } = e
    else {
        panic!("{e:?}");
    };
    assert_eq!((joint, kind), (1, Joint::Revolute));
    assert!((excess - 0.3).abs() < 1e-6, "{excess}");
    let text = e.to_string();
    assert!(
        text.contains("q[1] (the 2nd joint, a hinge) 0.3 rad outside its range"),
        "{text}"
    );
    // The same point through the work-space and the numeric solver.
    assert!(!arm.workspace().contains(&Point2::new(1.7, 0.0)));
    let seed = planar_arm::nalgebra::Vector2::new(0.1, 1.0);
    let target = planar_arm::kinematics::IkTarget::Position(Point2::new(1.7, 0.0));
    let near = arm.inverse_kinematics_near(&target, &seed, &Default::default());
    assert!(
        matches!(near, Err(ArmError::BeyondJointRange { joint: 1, .. })),
        "{near:?}"
    );
}

#[test]
fn the_three_link_miss_is_the_nearest_configuration() {
    let links = Three::default().links();
    let ranges = links.map(|l| l.range);
    let mut rng = Rng(23);
    let mut checked = 0;
    while checked < 40 {
        let p = Point2::new(rng.within((-2.3, 2.3)), rng.within((-2.3, 2.3)));
        let Err(ArmError::BeyondJointRange { excess, .. }) =
            ik3_position(1.0, 0.8, 0.5, ranges, &p)
        else {
            continue;
        };
        checked += 1;
        // Brute force: the smallest largest excess over q1 on a fine grid and both elbows.
        let excess_of = |v: f64, range: Option<(f64, f64)>| {
            let (lo, hi) = range.unwrap_or((-PI, PI));
            (0..3)
                .map(|k| {
                    let v = v + 2.0 * PI * (k as f64 - 1.0);
                    (lo - v).max(v - hi).max(0.0)
                })
                .fold(f64::INFINITY, f64::min)
        };
        let mut best = f64::INFINITY;
        for k in 0..100_000 {
            let q1 = -PI + 2.0 * PI * k as f64 / 100_000.0;
            let v = Vector2::new(
                p.x * q1.cos() + p.y * q1.sin(),
                p.y * q1.cos() - p.x * q1.sin(),
            ) - Vector2::new(1.0, 0.0);
            if let Ok(branches) = planar_arm::kinematics::ik2(0.8, 0.5, &v.into()) {
                for q in branches {
                    let worst = excess_of(q1, ranges[0])
                        .max(excess_of(q[0], ranges[1]))
                        .max(excess_of(q[1], ranges[2]));
                    best = best.min(worst);
                }
            }
        }
        assert!(
            excess <= best + 1e-6 && excess >= best - 1e-3,
            "{p}: {excess} vs {best}"
        );
    }
}
