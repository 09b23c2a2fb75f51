//! Work-spaces: the annulus any arm reaches and the dexterous work-space of three links.

use core::f64::consts::PI;
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use nalgebra::Point2;

use super::{annulus_check, REACH_TOLERANCE};
#[cfg(doc)]
use super::{ik2, ik3};

/// The work-space of a serial arm of revolute links: the closed annulus of the points the tip
/// can reach, `inner ..= outer` about joint 1.
///
/// For lengths `l_k`, `outer = sum l_k` and `inner = max(0, 2 max l_k - sum l_k)`: the tip can
/// come no closer than the longest link minus all the others.
///
/// # Example
/// ```
/// use planar_arm::kinematics::Workspace;
/// use planar_arm::nalgebra::Point2;
///
/// let w = Workspace::of_lengths(&[1.0, 0.5]);
/// assert_eq!((w.inner_radius(), w.outer_radius()), (0.5, 1.5));
/// assert!(w.contains(&Point2::new(0.0, 1.0)) && !w.contains(&Point2::new(0.2, 0.0)));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Workspace {
    inner: f64,
    outer: f64,
}

impl Workspace {
    /// The work-space of links of the given lengths, base first. Lengths count by absolute
    /// value (a link of negative length sweeps the same circle); NaN and infinite lengths are
    /// skipped. No links give the single point at the origin.
    #[must_use]
    pub fn of_lengths(lengths: &[f64]) -> Self {
        let (mut sum, mut longest) = (0.0_f64, 0.0_f64);
        for length in lengths.iter().filter(|l| l.is_finite()) {
            sum += length.abs();
            longest = longest.max(length.abs());
        }
        Self {
            // The longest minus the others, not `2 longest - sum`, whose `2 longest` overflows
            // for lengths near f64::MAX (an inner radius of infinity); `max` also maps the NaN
            // of an overflowing inf - inf to 0.
            inner: (longest - (sum - longest)).max(0.0),
            outer: sum,
        }
    }

    /// The inner radius, `max(0, 2 max l - sum l)`.
    #[must_use]
    pub fn inner_radius(&self) -> f64 {
        self.inner
    }

    /// The outer radius, `sum l`.
    #[must_use]
    pub fn outer_radius(&self) -> f64 {
        self.outer
    }

    /// Whether the tip can reach `point`: its distance from the base lies in
    /// `inner ..= outer`, widened on both sides by [`REACH_TOLERANCE`]` * outer` (the slack
    /// [`ik2`] allows). Points holding NaN or infinities are not contained.
    #[must_use]
    pub fn contains(&self, point: &Point2<f64>) -> bool {
        point.x.is_finite()
            && point.y.is_finite()
            && annulus_check(
                point.x.hypot(point.y),
                self.inner,
                self.outer,
                [point.x, point.y],
            )
            .is_ok()
    }

    /// The area, `pi (outer^2 - inner^2)`.
    #[must_use]
    pub fn area(&self) -> f64 {
        annulus_area(self.inner, self.outer)
    }
}

/// The radii about the base of the region a slider's carriage segment `from ..= to` on the x axis with the annulus `inner ..= outer` about each of its points, without its slack:
/// `(min |p|, max |p|)` over it.
pub(super) fn swept_radii(from: f64, to: f64, inner: f64, outer: f64) -> (f64, f64) {
    // The nearest and farthest carriage positions from the base.
    let near = 0.0_f64.max(from).max(-to);
    let far = from.abs().max(to.abs());
    (0.0_f64.max(inner - far).max(near - outer), far + outer)
}

/// `(min |s|, max |s|)` for `s` in `from ..= to`.
pub(super) fn polar_radii(from: f64, to: f64) -> (f64, f64) {
    (0.0_f64.max(from).max(-to), from.abs().max(to.abs()))
}

/// `pi (outer^2 - inner^2)`, 0 for a circle (also when the sum of the radii overflows).
fn annulus_area(inner: f64, outer: f64) -> f64 {
    if outer > inner {
        PI * (outer - inner) * (outer + inner)
    } else {
        0.0
    }
}

/// The dexterous (usable) work-space of a three-link arm: the points the tip reaches with
/// every orientation of the last link.
///
/// A point `p` belongs to it when the circle of radius `l3` about `p` (the wrist positions)
/// lies inside the two-link annulus `a = |l1 - l2| ..= b = l1 + l2`, that is when
/// `|p| + l3 <= b` and `| |p| - l3 | >= a`. That region has up to two pieces:
///
/// - the annulus `l3 + a ..= b - l3`, present when `l3 <= min(l1, l2)`;
/// - the disk about the origin of radius `min(l3 - a, b - l3)`, present when `a <= l3 <= b`
///   (a single point when the radius is 0).
///
/// When `l1 == l2` the two touch and are stored merged as one disk of radius `2 l - l3`, as
/// the paper says. When `l3 > l1 + l2`, or `min(l1, l2) < l3 < |l1 - l2|`, the region is
/// empty.
///
/// # Example
/// ```
/// use planar_arm::kinematics::DexterousWorkspace;
///
/// let equal = DexterousWorkspace::of_lengths(1.0, 1.0, 0.5);
/// assert_eq!((equal.disk_radius(), equal.annulus()), (Some(1.5), None));
/// let unequal = DexterousWorkspace::of_lengths(1.0, 0.6, 0.3);
/// assert_eq!(unequal.disk_radius(), None);
/// let (inner, outer) = unequal.annulus().unwrap();
/// assert!((inner - 0.7).abs() < 1e-12 && (outer - 1.3).abs() < 1e-12);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DexterousWorkspace {
    /// Inner radius of the two-link annulus, `|l1 - l2|`.
    inner2: f64,
    /// Outer radius of the two-link annulus, `l1 + l2`.
    outer2: f64,
    /// `|l3|`.
    last: f64,
    disk: Option<f64>,
    annulus: Option<(f64, f64)>,
}

impl DexterousWorkspace {
    /// The dexterous work-space of links of lengths `l1`, `l2`, `l3` (by absolute value). Any
    /// NaN or infinite length gives the empty region.
    #[must_use]
    pub fn of_lengths(l1: f64, l2: f64, l3: f64) -> Self {
        if !(l1.is_finite() && l2.is_finite() && l3.is_finite()) {
            return Self {
                inner2: 0.0,
                outer2: 0.0,
                last: f64::INFINITY,
                disk: None,
                annulus: None,
            };
        }
        let (a1, a2, c) = (l1.abs(), l2.abs(), l3.abs());
        let (a, b) = ((a1 - a2).abs(), a1 + a2);
        let mut annulus = (c + a <= b - c).then_some((c + a, b - c));
        let mut disk = (a <= c && c <= b).then(|| (c - a).min(b - c));
        if let (Some(radius), Some((inner, outer))) = (disk, annulus) {
            if radius >= inner {
                disk = Some(outer);
                annulus = None;
            }
        }
        Self {
            inner2: a,
            outer2: b,
            last: c,
            disk,
            annulus,
        }
    }

    /// The radius of the disk about the origin, if there is one (0 for the origin alone).
    #[must_use]
    pub fn disk_radius(&self) -> Option<f64> {
        self.disk
    }

    /// The `(inner, outer)` radii of the annulus piece, if there is one that is not merged
    /// into the disk.
    #[must_use]
    pub fn annulus(&self) -> Option<(f64, f64)> {
        self.annulus
    }

    /// Whether no point is reachable with every orientation.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.disk.is_none() && self.annulus.is_none()
    }

    /// The total area of the pieces.
    #[must_use]
    pub fn area(&self) -> f64 {
        let disk = self.disk.map_or(0.0, |r| PI * r * r);
        let annulus = self.annulus.map_or(0.0, |(i, o)| annulus_area(i, o));
        disk + annulus
    }

    /// Whether `point` is reachable with every orientation of the last link: the circle of
    /// wrist positions about it lies in the two-link annulus widened by
    /// [`REACH_TOLERANCE`]` * (l1 + l2)`, the slack [`ik3`] allows. Points holding NaN or
    /// infinities are not contained.
    #[must_use]
    pub fn contains(&self, point: &Point2<f64>) -> bool {
        if !(point.x.is_finite() && point.y.is_finite()) {
            return false;
        }
        let rho = point.x.hypot(point.y);
        let slack = REACH_TOLERANCE * self.outer2;
        rho + self.last - self.outer2 <= slack && self.inner2 - (rho - self.last).abs() <= slack
    }
}

/// [`DexterousWorkspace`] of a derived three-link arm from its own link lengths: implemented for
/// every [`PlanarArm<3>`](crate::PlanarArm).
pub trait DexterousWorkspaceExt {
    /// The points the tip reaches with every orientation of the last link:
    /// [`DexterousWorkspace::of_lengths`] of the lengths in
    /// [`links`](crate::PlanarArm::links), read at the call (run-time lengths included).
    ///
    /// # Example
    /// ```
    /// use planar_arm::kinematics::DexterousWorkspaceExt;
    /// use planar_arm::prelude::*;
    ///
    /// #[derive(PlanarArm)]
    /// struct Three {
    ///     #[arm(length = 1, mass = 1)] upper: Revolute,
    ///     #[arm(length = self.l2, mass = 1)] fore: Revolute,
    ///     #[arm(length = 0.25, mass = 1)] hand: Revolute,
    ///     l2: f64,
    /// }
    /// let mut arm = Three { upper: Revolute, fore: Revolute, hand: Revolute, l2: 1.0 };
    /// assert_eq!(arm.dexterous_workspace().disk_radius(), Some(1.75)); // 2 l - l3
    /// arm.l2 = 0.5;
    /// let (inner, outer) = arm.dexterous_workspace().annulus().unwrap(); // l3 < |l1 - l2|
    /// assert!((inner - 0.75).abs() < 1e-15 && (outer - 1.25).abs() < 1e-15);
    /// ```
    fn dexterous_workspace(&self) -> DexterousWorkspace;
}

impl<A: crate::PlanarArm<3> + ?Sized> DexterousWorkspaceExt for A {
    fn dexterous_workspace(&self) -> DexterousWorkspace {
        let [l1, l2, l3] = self.links().map(|l| l.length);
        DexterousWorkspace::of_lengths(l1, l2, l3)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::test_support::{fk, Rng, PAIRS};
    use crate::kinematics::{ik2, ik3};
    use core::f64::consts::TAU;
    use nalgebra::Isometry2;

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
            assert!(
                (w.area() - PI * (outer * outer - inner * inner)).abs() < 1e-12 * outer * outer
            );
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
}
