//! Two and three revolute links within joint ranges: the polar angles the tip reaches at each
//! distance from the base, and from them the region's area and the three-link position
//! inverse kinematics.
//!
//! Link 1 turns everything after it. Turn the tip `p` back by `q1`: `w = R(-q1) p` lies on the
//! circle `|w| = rho = |p|`, at the polar angle `psi = theta - q1` (`theta` the tip's). The
//! tip is reached with this `q1` exactly when `w - l1 x` lies in the region `S` that the later
//! links reach about joint 2 within their ranges. So the tip's polar angles at distance `rho`
//! are `Psi(rho) + range1`, `Psi(rho)` the angles `psi` with `rho u(psi) - l1 x` in `S`.
//!
//! For one later link, `S` is an arc of the circle of radius `|l2|` about joint 2, and
//! `Psi(rho)` at most two points. For two, the boundary of `S` lies on known circles: about
//! joint 2, those through the arm stretched and folded (`q3 = 0`, `pi`) and through the ends of
//! `q3`'s range; about the elbow at each end of `q2`'s range, the circle of radius `|l3|`. The
//! circle `|w| = rho` crosses them at computable angles, which cut it into arcs each wholly in
//! `S` or wholly out, told apart by [`ik2_in_ranges`] at one point of each.

use core::f64::consts::TAU;
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use nalgebra::{Point2, Vector2};

use crate::kinematics::range::{fit, Range};
use crate::kinematics::{ik2_in_ranges, turn_angle, REACH_TOLERANCE};
use crate::Joint;

/// At most six boundary circles, two crossings each.
const MAX_CUTS: usize = 12;
/// An arc between each pair of neighbouring cuts, and each cut on its own.
const MAX_ARCS: usize = 2 * MAX_CUTS;

/// Two or three revolute links, base first, with their ranges (`lengths[2]` and `ranges[2]`
/// unused for two).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct RangedChain {
    pub lengths: [f64; 3],
    pub ranges: [Range; 3],
    pub three: bool,
}

/// A circle in link 1's frame, relative to joint 2.
#[derive(Clone, Copy)]
struct Circle {
    centre: Vector2<f64>,
    radius: f64,
}

/// Arcs `[start, end]` of polar angle (`end - start` in `0 ..= 2 pi`; a point when equal).
#[derive(Clone, Copy)]
pub(crate) struct Arcs {
    arcs: [(f64, f64); MAX_ARCS],
    len: usize,
}

impl Arcs {
    const fn new() -> Self {
        Self {
            arcs: [(0.0, 0.0); MAX_ARCS],
            len: 0,
        }
    }

    fn push(&mut self, start: f64, end: f64) {
        if self.len < MAX_ARCS {
            self.arcs[self.len] = (start, end);
            self.len += 1;
        }
    }

    pub(crate) fn iter(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.arcs[..self.len].iter().copied()
    }

    pub(crate) fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Each arc widened by `range` (the tip's angles `psi + q1`), or the whole circle when
    /// the range allows a full turn.
    fn widened(&self, range: Range) -> Self {
        let mut out = Self::new();
        if self.is_empty() {
            return out;
        }
        match range {
            Some((lo, hi)) if hi - lo < TAU => {
                for (s, e) in self.iter() {
                    out.push(s + lo, (e + hi).min(s + lo + TAU));
                }
            }
            _ => out.push(0.0, TAU),
        }
        out
    }

    /// The angle these arcs cover on the circle, overlaps counted once.
    fn measure(&self) -> f64 {
        // Starts in [0, 2 pi); an arc then ends before 4 pi. The circle's measure is that of
        // the union with its copy shifted back by 2 pi, within [0, 2 pi).
        let mut pieces = [(0.0, 0.0); 2 * MAX_ARCS];
        let mut n = 0;
        for (s, e) in self.iter() {
            let start = turn_angle(s);
            let end = start + (e - s);
            pieces[n] = (start, end.min(TAU));
            n += 1;
            if end > TAU {
                pieces[n] = (0.0, end - TAU);
                n += 1;
            }
        }
        let pieces = &mut pieces[..n];
        sort_by_start(pieces);
        let mut total = 0.0;
        let mut current: Option<(f64, f64)> = None;
        for &(s, e) in pieces.iter() {
            current = match current {
                Some((cs, ce)) if s <= ce => Some((cs, ce.max(e))),
                Some((cs, ce)) => {
                    total += ce - cs;
                    Some((s, e))
                }
                None => Some((s, e)),
            };
        }
        if let Some((cs, ce)) = current {
            total += ce - cs;
        }
        total.min(TAU)
    }
}

fn sort_by_start(pieces: &mut [(f64, f64)]) {
    // Insertion sort: a few dozen entries, and `core` has no allocation-free sort of floats
    // by a key that is not `Ord`.
    for i in 1..pieces.len() {
        let mut j = i;
        while j > 0 && pieces[j - 1].0 > pieces[j].0 {
            pieces.swap(j - 1, j);
            j -= 1;
        }
    }
}

fn sort(values: &mut [f64]) {
    for i in 1..values.len() {
        let mut j = i;
        while j > 0 && values[j - 1] > values[j] {
            values.swap(j - 1, j);
            j -= 1;
        }
    }
}

impl RangedChain {
    /// The scale of the arm, `sum |l|`, for tolerances.
    fn scale(&self) -> f64 {
        let n = if self.three { 3 } else { 2 };
        self.lengths[..n].iter().map(|l| l.abs()).sum()
    }

    /// The circles on which the boundary of `S` lies, and how many.
    fn circles(&self) -> ([Circle; 6], usize) {
        let [_, l2, l3] = self.lengths;
        let mut out = [Circle {
            centre: Vector2::zeros(),
            radius: 0.0,
        }; 6];
        let mut n = 0;
        let mut push = |centre: Vector2<f64>, radius: f64| {
            out[n] = Circle { centre, radius };
            n += 1;
        };
        if !self.three {
            push(Vector2::zeros(), l2.abs());
            return (out, n);
        }
        // |l2 + l3 e^(i q3)|, the distance of the tip from joint 2.
        let reach = |q3: f64| (l2 + l3 * q3.cos()).hypot(l3 * q3.sin());
        push(Vector2::zeros(), (l2.abs() + l3.abs()).abs());
        push(Vector2::zeros(), (l2.abs() - l3.abs()).abs());
        if let Some((lo, hi)) = self.ranges[2].filter(|(lo, hi)| hi - lo < TAU) {
            push(Vector2::zeros(), reach(lo));
            push(Vector2::zeros(), reach(hi));
        }
        if let Some((lo, hi)) = self.ranges[1].filter(|(lo, hi)| hi - lo < TAU) {
            push(Vector2::new(lo.cos(), lo.sin()) * l2, l3.abs());
            push(Vector2::new(hi.cos(), hi.sin()) * l2, l3.abs());
        }
        (out, n)
    }

    /// Whether `v` (relative to joint 2, in link 1's frame) lies in `S`.
    fn in_later_region(&self, v: Vector2<f64>) -> bool {
        let [_, l2, l3] = self.lengths;
        if self.three {
            let ranges = [self.ranges[1], self.ranges[2]];
            return ik2_in_ranges(l2, l3, ranges, &Point2::from(v)).is_ok();
        }
        if (v.norm() - l2.abs()).abs() > REACH_TOLERANCE * self.scale() {
            return false;
        }
        let angle = if l2 < 0.0 {
            (-v.y).atan2(-v.x)
        } else {
            v.y.atan2(v.x)
        };
        fit(Joint::Revolute, angle, self.ranges[1], 0.0).is_ok()
    }

    /// The point of the circle `|w| = rho` at polar angle `psi`, relative to joint 2.
    fn later_point(&self, rho: f64, psi: f64) -> Vector2<f64> {
        let (s, c) = psi.sin_cos();
        Vector2::new(rho * c - self.lengths[0], rho * s)
    }

    /// The angles `psi` at which the circle `|w| = rho` crosses the boundary circles, sorted in
    /// `[0, 2 pi)`.
    fn cuts(&self, rho: f64) -> ([f64; MAX_CUTS], usize) {
        let mut cuts = [0.0; MAX_CUTS];
        let mut n = 0;
        let (circles, count) = self.circles();
        for circle in &circles[..count] {
            // |rho u(psi) - d| = r with d the circle's centre from joint 1:
            // d . u(psi) = (rho^2 + |d|^2 - r^2) / (2 rho) = k, so cos(psi - delta) = k / |d|.
            let d = circle.centre + Vector2::new(self.lengths[0], 0.0);
            let (dn, r) = (d.norm(), circle.radius);
            if rho == 0.0 || dn == 0.0 {
                continue;
            }
            let cosine = ((rho - r) * (rho + r) + dn * dn) / (2.0 * rho * dn);
            // A tangency that rounding pushes just outside still counts.
            if cosine.is_nan() || cosine.abs() > 1.0 + 1e-9 {
                continue;
            }
            let (delta, alpha) = (d.y.atan2(d.x), cosine.clamp(-1.0, 1.0).acos());
            for psi in [delta - alpha, delta + alpha] {
                if n < MAX_CUTS {
                    cuts[n] = turn_angle(psi);
                    n += 1;
                }
            }
        }
        sort(&mut cuts[..n]);
        (cuts, n)
    }

    /// `Psi(rho)`: the polar angles `psi` of the circle `|w| = rho` at which the later links
    /// reach `w - l1 x` within their ranges.
    pub(crate) fn later_angles(&self, rho: f64) -> Arcs {
        let mut arcs = Arcs::new();
        let inside = |psi: f64| self.in_later_region(self.later_point(rho, psi));
        let (cuts, n) = self.cuts(rho);
        if n == 0 {
            // No crossing: the circle lies wholly in S or wholly out (or is the point at the
            // origin).
            if self.three && inside(0.0) {
                arcs.push(0.0, TAU);
            }
            return arcs;
        }
        for i in 0..n {
            let a = cuts[i];
            if inside(a) {
                arcs.push(a, a);
            }
            if self.three {
                let b = if i + 1 < n {
                    cuts[i + 1]
                } else {
                    cuts[0] + TAU
                };
                if b > a && inside(0.5 * (a + b)) {
                    arcs.push(a, b);
                }
            }
        }
        arcs
    }

    /// The tip's polar angles at distance `rho` from the base.
    pub(crate) fn tip_angles(&self, rho: f64) -> Arcs {
        self.later_angles(rho).widened(self.ranges[0])
    }

    /// The radii at which the arcs can appear, vanish or jump: where the circle `|w| = rho`
    /// touches a boundary circle, passes through two at once (a corner of `S`), or for one
    /// later link reaches the ends of its range.
    fn breakpoints(&self, out: &mut [f64; 64]) -> usize {
        let (circles, count) = self.circles();
        let joint1 = Vector2::new(self.lengths[0], 0.0);
        let mut n = 0;
        let mut push = |rho: f64| {
            if n < out.len() && rho.is_finite() {
                out[n] = rho.abs();
                n += 1;
            }
        };
        for (i, a) in circles[..count].iter().enumerate() {
            let d = (a.centre + joint1).norm();
            push(d - a.radius);
            push(d + a.radius);
            for b in &circles[i + 1..count] {
                let offset = b.centre - a.centre;
                let gap = offset.norm();
                if gap == 0.0 {
                    continue;
                }
                // Where the two circles meet: along `offset` by `x`, across by `h`.
                let x = (gap * gap + (a.radius - b.radius) * (a.radius + b.radius)) / (2.0 * gap);
                let h2 = (a.radius - x) * (a.radius + x);
                if h2 < 0.0 {
                    continue;
                }
                let (along, across) = (offset / gap, Vector2::new(-offset.y, offset.x) / gap);
                for h in [-h2.sqrt(), h2.sqrt()] {
                    push((a.centre + along * x + across * h + joint1).norm());
                }
            }
        }
        if !self.three {
            let [l1, l2, _] = self.lengths;
            if let Some((lo, hi)) = self.ranges[1] {
                for q2 in [lo, hi] {
                    push((l1 + l2 * q2.cos()).hypot(l2 * q2.sin()));
                }
            }
        }
        n
    }

    /// `(min |tip|, max |tip|)` over the ranges of the joints after the first (which alone
    /// set the tip's distance from the base). `|tip|^2` is smooth in `(q2, q3)`, so its
    /// extremes over the box of ranges lie where its gradient vanishes inside the box (the
    /// links after the first straight or folded, and collinear with link 1), on an edge where
    /// its derivative along the edge vanishes (the free link or pair collinear with the fixed
    /// part), or at a corner: finitely many candidates, each checked against the ranges.
    pub(crate) fn radii(&self) -> (f64, f64) {
        let [l1, l2, l3] = self.lengths;
        let (mut lo, mut hi) = (f64::INFINITY, 0.0_f64);
        // |tip|^2 has a vanishing gradient wherever the tip is at the base, too.
        if self.three && self.in_later_region(Vector2::new(-l1, 0.0)) {
            lo = 0.0;
        }
        let mut consider = |q2: f64, q3: f64| {
            let b = Vector2::new(l2 + l3 * q3.cos(), l3 * q3.sin());
            let (s, c) = q2.sin_cos();
            let r = (l1 + c * b.x - s * b.y).hypot(s * b.x + c * b.y);
            lo = lo.min(r);
            hi = hi.max(r);
        };
        let fits = |v: f64, range: Range| fit(Joint::Revolute, v, range, 0.0).is_ok();
        let ends = |range: Range| match range.filter(|(lo, hi)| hi - lo < TAU) {
            Some((lo, hi)) => [Some(lo), Some(hi)],
            None => [None, None],
        };
        if !self.three {
            for q2 in [0.0, core::f64::consts::PI] {
                if fits(q2, self.ranges[1]) {
                    consider(q2, 0.0);
                }
            }
            for q2 in ends(self.ranges[1]).into_iter().flatten() {
                consider(q2, 0.0);
            }
            // With one later link, `l3` is not part of the arm.
            return (lo, hi);
        }
        let (r2, r3) = (self.ranges[1], self.ranges[2]);
        let straight = [0.0, core::f64::consts::PI];
        // Inside: the later pair straight or folded, and collinear with link 1.
        for q3 in straight {
            for q2 in straight {
                if fits(q2, r2) && fits(q3, r3) {
                    consider(q2, q3);
                }
            }
        }
        for q2 in ends(r2).into_iter().flatten() {
            // q2 fixed: the last link points along or against the rest, `A = l1 x + l2 u(q2)`.
            let a = Vector2::new(l1 + l2 * q2.cos(), l2 * q2.sin());
            for turn in straight {
                let q3 = a.y.atan2(a.x) + turn - q2;
                if fits(q3, r3) {
                    consider(q2, q3);
                }
            }
            for q3 in ends(r3).into_iter().flatten() {
                consider(q2, q3);
            }
        }
        for q3 in ends(r3).into_iter().flatten() {
            // q3 fixed: the pair `B = l2 x + l3 u(q3)` turned by q2 along or against link 1.
            let b = Vector2::new(l2 + l3 * q3.cos(), l3 * q3.sin());
            for turn in straight {
                let q2 = turn - b.y.atan2(b.x);
                if fits(q2, r2) {
                    consider(q2, q3);
                }
            }
        }
        (lo, hi)
    }

    /// The area the tip reaches, by integrating `rho` times the measure of
    /// [`tip_angles`](Self::tip_angles) over `rho` between `inner` and `outer` (bounds on the
    /// radius), piece by piece between the breakpoints, to a relative error of about 1e-10.
    pub(crate) fn area(&self, inner: f64, outer: f64) -> f64 {
        if outer.is_nan() || inner.is_nan() || outer <= inner || !outer.is_finite() {
            return 0.0;
        }
        let mut points = [0.0; 64];
        let n = self.breakpoints(&mut points);
        let points = &mut points[..n];
        sort(points);
        let tolerance = 1e-11 * outer * outer;
        let f = |rho: f64| rho * self.tip_angles(rho).measure();
        let mut total = 0.0;
        let mut from = inner;
        for &p in points.iter().chain([outer].iter()) {
            let to = p.min(outer);
            if to > from {
                total += simpson(&f, from, to, tolerance);
                from = to;
            }
        }
        total
    }
}

/// Adaptive Simpson quadrature of `f` over `[a, b]` to about `tolerance`.
fn simpson(f: &impl Fn(f64) -> f64, a: f64, b: f64, tolerance: f64) -> f64 {
    let (fa, fb, fm) = (f(a), f(b), f(0.5 * (a + b)));
    let whole = (b - a) / 6.0 * (fa + 4.0 * fm + fb);
    refine(f, (a, fa), (b, fb), fm, whole, tolerance, 48)
}

fn refine(
    f: &impl Fn(f64) -> f64,
    (a, fa): (f64, f64),
    (b, fb): (f64, f64),
    fm: f64,
    whole: f64,
    tolerance: f64,
    depth: u32,
) -> f64 {
    let m = 0.5 * (a + b);
    let (lm, rm) = (0.5 * (a + m), 0.5 * (m + b));
    let (flm, frm) = (f(lm), f(rm));
    let left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
    let right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
    let change = left + right - whole;
    if depth == 0 || change.abs() <= 15.0 * tolerance {
        return left + right + change / 15.0;
    }
    refine(f, (a, fa), (m, fm), flm, left, 0.5 * tolerance, depth - 1)
        + refine(f, (m, fm), (b, fb), frm, right, 0.5 * tolerance, depth - 1)
}
