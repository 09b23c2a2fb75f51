//! Unit tests of the work-spaces: every region against brute force (tips of sampled
//! configurations, Monte Carlo areas) and against the reach of the closed forms.

use super::*;
use crate::kinematics::test_support::{fk, fk_joints, Rng, PAIRS};
use crate::kinematics::{ik2, ik3};
use core::f64::consts::{PI, TAU};
use nalgebra::{Isometry2, Point2};

/// Every configuration on a grid of joint angles (multiples of pi / 6, which include the
/// extreme ones) for the joints after the first.
fn grid_radii(lengths: &[f64]) -> Vec<(f64, f64)> {
    let n = lengths.len();
    let mut tips = Vec::new();
    let count = 12usize.pow(u32::try_from(n - 1).unwrap());
    for code in 0..count {
        let mut q = vec![0.37 * code as f64];
        let mut c = code;
        for _ in 1..n {
            q.push((c % 12) as f64 * PI / 6.0);
            c /= 12;
        }
        let (x, y, _) = fk(lengths, &q);
        tips.push((x, y));
    }
    tips
}

#[test]
fn workspace_matches_brute_force() {
    let mut rng = Rng(8);
    let arms: [&[f64]; 9] = [
        &[1.0],
        &[1.0, 0.5],
        &[0.5, 1.0],
        &[1.0, 1.0],
        &[3.0, 1.0, 0.5],
        &[1.0, 1.0, 1.0],
        &[0.2, 2.0, 0.5, 0.3],
        &[1.0, 2.0, 3.0, 4.0],
        &[0.4, 0.3, 5.0, 0.2, 0.1],
    ];
    for lengths in arms {
        let w = Workspace::of_lengths(lengths);
        let (inner, outer) = (w.inner_radius(), w.outer_radius());
        let tips = grid_radii(lengths);
        let (mut lo, mut hi) = (f64::INFINITY, 0.0_f64);
        for &(x, y) in &tips {
            assert!(w.contains(&Point2::new(x, y)), "{lengths:?}: ({x}, {y})");
            lo = lo.min(x.hypot(y));
            hi = hi.max(x.hypot(y));
        }
        // The radii are attained, so they are not too generous either.
        assert!(
            (lo - inner).abs() < 1e-12 && (hi - outer).abs() < 1e-12,
            "{lengths:?}"
        );
        for _ in 0..2000 {
            let q: Vec<f64> = lengths.iter().map(|_| rng.angle()).collect();
            let (x, y, _) = fk(lengths, &q);
            assert!(w.contains(&Point2::new(x, y)));
            let theta = rng.angle();
            let (s, c) = theta.sin_cos();
            let beyond = outer + rng.range(1e-6, 1.0);
            assert!(!w.contains(&Point2::new(beyond * c, beyond * s)));
            if inner > 1e-6 {
                let short = inner - rng.range(1e-6, inner);
                assert!(!w.contains(&Point2::new(short * c, short * s)));
            }
        }
        assert!((w.area() - PI * (outer * outer - inner * inner)).abs() < 1e-12 * outer * outer);
    }
    assert_eq!(
        Workspace::of_lengths(&[-1.0, 0.5]),
        Workspace::of_lengths(&[1.0, 0.5])
    );
    assert_eq!(Workspace::of_lengths(&[]).outer_radius(), 0.0);
}

#[test]
fn workspace_agrees_with_ik2() {
    let mut rng = Rng(9);
    for (l1, l2) in PAIRS {
        let w = Workspace::of_lengths(&[l1, l2]);
        let outer = l1 + l2;
        for k in 0..4000 {
            // Half the points within a few tolerances of a boundary circle.
            let r = match k % 4 {
                0 => outer * (1.0 + rng.range(-3e-9, 3e-9)),
                1 => (l1 - l2).abs() + outer * rng.range(-3e-9, 3e-9),
                _ => outer * rng.range(0.0, 1.2),
            };
            let theta = rng.angle();
            let p = Point2::new(r * theta.cos(), r * theta.sin());
            assert_eq!(
                w.contains(&p),
                ik2(l1, l2, &p).is_ok(),
                "({l1}, {l2}) at {p}"
            );
        }
    }
}

/// A link by its joint, length and range.
type Spec = (Joint, f64, Option<(f64, f64)>);

fn arm(spec: &[Spec]) -> Vec<Link> {
    spec.iter()
        .map(|&(joint, length, range)| Link {
            range,
            ..Link::rod(length, 1.0).with_joint(joint)
        })
        .collect()
}

const R: Joint = Joint::Revolute;
const P: Joint = Joint::Prismatic;

#[test]
fn revolute_links_give_the_annulus_of_their_lengths() {
    for lengths in [&[1.0, 0.5][..], &[0.2, 2.0, 0.5, 0.3], &[1.0; 12], &[]] {
        let links: Vec<Link> = lengths.iter().map(|l| Link::rod(*l, 1.0)).collect();
        assert_eq!(Workspace::of_links(&links), Workspace::of_lengths(lengths));
        // A range of a full turn restricts nothing.
        let turned: Vec<Link> = links.iter().map(|l| l.with_range(-PI, PI)).collect();
        assert_eq!(Workspace::of_links(&turned), Workspace::of_lengths(lengths));
        assert!(Workspace::of_links(&links).is_exact());
    }
    // A narrower range on the first joint: the same radii, a sector of the annulus.
    let ranged = [
        Link::rod(1.0, 1.0).with_range(0.0, 1.0),
        Link::rod(0.5, 1.0),
    ];
    let w = Workspace::of_links(&ranged);
    assert!(w.is_exact());
    assert_eq!((w.inner_radius(), w.outer_radius()), (0.5, 1.5));
    assert!(w.area() < Workspace::of_lengths(&[1.0, 0.5]).area());
    // Four links with a range: only the annulus is known.
    let four = [ranged[0], ranged[1], ranged[1], ranged[1]];
    let w = Workspace::of_links(&four);
    assert!(!w.is_exact());
    assert_eq!(
        w.area(),
        Workspace::of_lengths(&[1.0, 0.5, 0.5, 0.5]).area()
    );
}

/// The cells of a `2 n x 2 n` grid over `-half ..= half` squared that tips of random
/// configurations within the ranges land in, and the tips.
fn raster(
    links: &[Link],
    half: f64,
    n: usize,
    samples: usize,
    rng: &mut Rng,
) -> (Vec<bool>, Vec<(f64, f64)>) {
    let kinds: Vec<Joint> = links.iter().map(|l| l.joint).collect();
    let lengths: Vec<f64> = links.iter().map(|l| l.length).collect();
    let mut cells = vec![false; 4 * n * n];
    let mut tips = Vec::new();
    for _ in 0..samples {
        let q: Vec<f64> = links
            .iter()
            .map(|l| match (l.joint, l.range) {
                (_, Some((lo, hi))) => rng.range(lo, hi),
                (Joint::Revolute, None) => rng.angle(),
                (Joint::Prismatic, None) => rng.range(-2.0 * half, 2.0 * half),
            })
            .collect();
        let (x, y, _) = fk_joints(&kinds, &lengths, &q);
        if let Some(c) = cell(x, y, half, n) {
            cells[c] = true;
        }
        tips.push((x, y));
    }
    (cells, tips)
}

fn cell(x: f64, y: f64, half: f64, n: usize) -> Option<usize> {
    let size = half / n as f64;
    let (i, j) = ((x + half) / size, (y + half) / size);
    let inside = (0.0..(2 * n) as f64).contains(&i) && (0.0..(2 * n) as f64).contains(&j);
    inside.then(|| (i as usize) * 2 * n + j as usize)
}

/// Whether the cell of `(x, y)` or one of its eight neighbours holds a tip.
fn near_tip(cells: &[bool], x: f64, y: f64, half: f64, n: usize) -> bool {
    let size = half / n as f64;
    (-1..=1).any(|di| {
        (-1..=1).any(|dj| {
            cell(x + f64::from(di) * size, y + f64::from(dj) * size, half, n)
                .is_some_and(|c| cells[c])
        })
    })
}

/// Brute force for an exact work-space: every tip within the ranges is contained, every
/// contained point lies next to a cell that tips reach (and so every point away from the
/// tips is not contained), and the area agrees with Monte Carlo over the grid's square.
fn check_against_sampling(links: &[Link], half: f64, rng: &mut Rng) -> f64 {
    let w = Workspace::of_links(links);
    assert!(w.is_exact(), "{links:?}");
    let n = 60;
    let (cells, tips) = raster(links, half, n, 400_000, rng);
    for &(x, y) in &tips {
        assert!(
            w.contains(&Point2::new(x, y)),
            "{links:?}: tip ({x}, {y}) not contained"
        );
        let r = x.hypot(y);
        assert!(r >= w.inner_radius() - 1e-12 && r <= w.outer_radius() + 1e-12);
    }
    let (mut inside, total) = (0, 200_000);
    for _ in 0..total {
        let (x, y) = (rng.range(-half, half), rng.range(-half, half));
        if w.contains(&Point2::new(x, y)) {
            inside += 1;
            assert!(
                near_tip(&cells, x, y, half, n),
                "{links:?}: ({x}, {y}) contained, no tip near"
            );
        }
    }
    let estimate = f64::from(inside) / f64::from(total) * 4.0 * half * half;
    let area = w.area();
    assert!(
        (estimate - area).abs() < 0.02 * area + 1e-3,
        "{links:?}: area {area}, Monte Carlo {estimate}"
    );
    area
}

#[test]
fn prismatic_work_spaces_match_brute_force() {
    let mut rng = Rng(25);
    let arms: [&[Spec]; 10] = [
        // Polar arms: an annulus, two opposite sectors, a sector wider than pi.
        &[(R, 0.2, None), (P, 0.5, Some((0.1, 0.6)))],
        &[(R, 0.2, Some((-0.5, 1.0))), (P, 0.5, Some((-1.5, 0.3)))],
        &[(R, 0.2, Some((0.0, 4.0))), (P, 0.5, Some((-1.2, 0.3)))],
        // One hinge with a range: an arc (area 0).
        &[(R, 1.0, Some((0.0, 2.0)))],
        // Sliders carrying a link: long and short travel, with and without a hinge range.
        &[(P, 0.3, Some((0.0, 1.5))), (R, 0.5, None)],
        &[(P, 0.3, Some((0.0, 0.4))), (R, 0.5, None)],
        &[(P, 0.3, Some((-0.5, 0.5))), (R, 0.5, Some((-1.0, 2.0)))],
        &[(P, 0.3, Some((-0.5, 0.1))), (R, -0.6, Some((0.5, 4.0)))],
        // PRR and a longer slider arm.
        &[(P, 0.2, Some((-0.5, 0.6))), (R, 0.6, None), (R, 0.3, None)],
        &[
            (P, 0.2, Some((-0.2, 0.3))),
            (R, 0.5, None),
            (R, 0.4, None),
            (R, 0.2, None),
        ],
    ];
    for spec in arms {
        let links = arm(spec);
        let half = 1.05 * Workspace::of_links(&links).outer_radius();
        check_against_sampling(&links, half, &mut rng);
    }
}

#[test]
fn areas_by_hand() {
    let area = |spec: &[Spec]| Workspace::of_links(&arm(spec)).area();
    let close = |a: f64, b: f64| (a - b).abs() < 1e-12 * b.abs().max(1.0);
    // The polar annulus 0.8 ..= 1.3.
    assert!(close(
        area(&[(R, 0.2, None), (P, 0.5, Some((0.1, 0.6)))]),
        PI * (1.69 - 0.64)
    ));
    // A sector of 1 rad of it.
    assert!(close(
        area(&[(R, 0.2, Some((0.0, 1.0))), (P, 0.5, Some((0.1, 0.6)))]),
        0.5 * (1.69 - 0.64)
    ));
    // Both signs: the slide reaches -0.3 ..= 0.2 about the base, sectors of 1 rad.
    assert!(close(
        area(&[(R, 0.2, Some((0.0, 1.0))), (P, 0.5, Some((-1.0, -0.5)))]),
        0.5 * (0.09 + 0.04)
    ));
    // A slider with travel 1.5 carrying a 0.5 link: the stadium 2 L r + pi r^2.
    assert!(close(
        area(&[(P, 0.3, Some((0.0, 1.5))), (R, 0.5, None)]),
        1.5 + PI * 0.25
    ));
    // Its upper half when the hinge points up: L 2r ... the half stadium.
    assert!(close(
        area(&[(P, 0.3, Some((0.0, 1.5))), (R, 0.5, Some((0.0, PI)))]),
        0.75 + PI * 0.125
    ));
    // Travel 0 and no range: a circle.
    assert_eq!(area(&[(P, 0.3, Some((0.2, 0.2))), (R, 0.5, None)]), 0.0);
    // PRR with travel L >= 2 inner: the annulus swept, pi (o^2 - i^2) + 2 L o + ... by
    // the strip formula with inner 0.3, outer 0.9, L = 1.1: the hole is closed.
    assert!(close(
        area(&[(P, 0.2, Some((-0.5, 0.6))), (R, 0.6, None), (R, 0.3, None)]),
        2.0 * 1.1 * 0.9 + PI * 0.81
    ));
    // No range on a slide: unbounded.
    let w = Workspace::of_links(&arm(&[(P, 0.3, None), (R, 0.5, None)]));
    assert_eq!((w.outer_radius(), w.area()), (f64::INFINITY, f64::INFINITY));
    assert!(w.contains(&Point2::new(1e6, 0.4)) && !w.contains(&Point2::new(0.0, 0.6)));
    let polar = Workspace::of_links(&arm(&[(R, 0.2, None), (P, 0.5, None)]));
    assert_eq!(polar.area(), f64::INFINITY);
    assert!(polar.contains(&Point2::new(-3.0, 7.0)));
}

#[test]
fn other_mixes_are_bounded_conservatively() {
    let mut rng = Rng(26);
    let arms: [&[Spec]; 4] = [
        &[(R, 1.0, None), (R, 0.5, None), (P, 0.3, Some((0.0, 0.4)))],
        &[(P, 0.5, Some((0.0, 1.0))), (P, 0.2, Some((-0.1, 0.3)))],
        &[(R, 0.4, None), (P, 1.0, Some((0.5, 1.0))), (R, 0.3, None)],
        &[
            (P, 0.2, Some((0.0, 0.5))),
            (R, 0.6, Some((0.0, 1.0))),
            (R, 0.3, None),
        ],
    ];
    for spec in arms {
        let links = arm(spec);
        let w = Workspace::of_links(&links);
        assert!(!w.is_exact());
        let (_, tips) = raster(&links, 4.0, 10, 20_000, &mut rng);
        let (mut lo, mut hi) = (f64::INFINITY, 0.0_f64);
        for (x, y) in tips {
            assert!(w.contains(&Point2::new(x, y)));
            lo = lo.min(x.hypot(y));
            hi = hi.max(x.hypot(y));
        }
        assert!(w.inner_radius() <= lo && hi <= w.outer_radius(), "{spec:?}");
    }
    // The third one: the first two links point the same way, 1.9 ..= 2.4 from the base,
    // and the last link turns 0.3 about their end.
    let w = Workspace::of_links(&arm(arms[2]));
    assert!((w.inner_radius() - 1.6).abs() < 1e-12 && (w.outer_radius() - 2.7).abs() < 1e-12);
}

#[test]
fn dexterous_pieces() {
    let pieces = |l1, l2, l3| {
        let d = DexterousWorkspace::of_lengths(l1, l2, l3);
        (d.disk_radius(), d.annulus())
    };
    // Equal links: one disk of radius 2 l - l3 (the paper).
    assert_eq!(pieces(1.0, 1.0, 0.5), (Some(1.5), None));
    // ... also when l3 > l, where the paper's l3 - |l1 - l2| = 1.5 would be wrong.
    assert_eq!(pieces(1.0, 1.0, 1.5), (Some(0.5), None));
    // l3 < |l1 - l2|: annulus only.
    assert_eq!(pieces(1.0, 0.5, 0.25), (None, Some((0.75, 1.25))));
    // |l1 - l2| < l3 <= min: disk and annulus.
    let (disk, annulus) = pieces(1.0, 0.6, 0.5);
    assert!((disk.unwrap() - 0.1).abs() < 1e-12);
    let (i, o) = annulus.unwrap();
    assert!((i - 0.9).abs() < 1e-12 && (o - 1.1).abs() < 1e-12);
    // min < l3 <= max: disk of radius l3 - |l1 - l2|.
    assert_eq!(pieces(1.0, 0.5, 0.75), (Some(0.25), None));
    // max < l3 <= l1 + l2: disk of radius l1 + l2 - l3.
    assert_eq!(pieces(1.0, 0.5, 1.25), (Some(0.25), None));
    // l3 = l1 + l2: the origin alone.
    let point = DexterousWorkspace::of_lengths(1.0, 0.5, 1.5);
    assert_eq!(point.disk_radius(), Some(0.0));
    assert!(point.contains(&Point2::origin()) && !point.contains(&Point2::new(1e-6, 0.0)));
    // Empty: min < l3 < |l1 - l2| with no room, and l3 > l1 + l2.
    assert!(DexterousWorkspace::of_lengths(10.0, 1.0, 5.0).is_empty());
    assert!(DexterousWorkspace::of_lengths(1.0, 0.5, 2.0).is_empty());
    assert_eq!(DexterousWorkspace::of_lengths(1.0, 0.5, 2.0).area(), 0.0);
    let d = DexterousWorkspace::of_lengths(1.0, 0.6, 0.5);
    assert!((d.area() - PI * (0.01 + 1.21 - 0.81)).abs() < 1e-12);
}

#[test]
fn dexterous_workspace_matches_brute_force() {
    let mut rng = Rng(10);
    let triples = [
        (1.0, 0.5, 0.3),
        (1.0, 0.5, 0.2),
        (1.0, 1.0, 0.4),
        (1.0, 0.6, 0.5),
        (1.0, 0.5, 0.75),
        (1.0, 0.5, 1.25),
        (1.0, 1.0, 1.5),
        (10.0, 1.0, 5.0),
    ];
    let orientations = 240;
    for (l1, l2, l3) in triples {
        let d = DexterousWorkspace::of_lengths(l1, l2, l3);
        let all = Workspace::of_lengths(&[l1, l2, l3]);
        let (a, b) = ((l1 - l2).abs(), l1 + l2);
        let (mut inside, mut outside) = (0, 0);
        for _ in 0..1500 {
            let rho = rng.range(0.0, l1 + l2 + l3);
            // Stay clear of the region's boundary circles, which sampling might miss.
            let margin = 1e-3;
            if (rho + l3 - b).abs() < margin || ((rho - l3).abs() - a).abs() < margin {
                continue;
            }
            let theta = rng.angle();
            let p = Point2::new(rho * theta.cos(), rho * theta.sin());
            let offset = rng.angle();
            let every = (0..orientations).all(|k| {
                let phi = offset + f64::from(k) * TAU / f64::from(orientations);
                ik3(l1, l2, l3, &Isometry2::new(p.coords, phi)).is_ok()
            });
            assert_eq!(d.contains(&p), every, "{l1}, {l2}, {l3} at {p}");
            let in_pieces = d.disk_radius().is_some_and(|r| rho <= r)
                || d.annulus().is_some_and(|(i, o)| i <= rho && rho <= o);
            assert_eq!(in_pieces, every, "pieces of {l1}, {l2}, {l3} at {p}");
            if every {
                inside += 1;
                assert!(all.contains(&p));
            } else {
                outside += 1;
            }
        }
        assert!(
            d.is_empty() || inside > 20,
            "{l1}, {l2}, {l3}: {inside} inside"
        );
        assert!(outside > 20);
    }
}
