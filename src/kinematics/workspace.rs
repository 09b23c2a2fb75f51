//! Work-spaces: the region any arm reaches and the dexterous work-space of three links.

use core::f64::consts::{FRAC_PI_2, PI, TAU};
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use nalgebra::Point2;

use super::range::{slide_slack, Range};
use super::{annulus_check, ik_pr, ik_rp, REACH_TOLERANCE};
#[cfg(doc)]
use super::{ik2, ik3};
use crate::{Joint, Link};

/// The work-space of a serial arm: the points its tip can reach.
///
/// For revolute links without ranges, [`of_lengths`](Self::of_lengths), it is the closed
/// annulus `inner ..= outer` about joint 1: for lengths `l_k`, `outer = sum l_k` and
/// `inner = max(0, 2 max l_k - sum l_k)`, the tip coming no closer than the longest link
/// minus all the others.
///
/// [`of_links`](Self::of_links) also takes the joints' kinds and ranges, and describes the
/// region exactly ([`is_exact`](Self::is_exact)) for these arms:
///
/// - revolute links without ranges (a range of a full turn or more counts as none): the
///   annulus above, exactly as [`of_lengths`](Self::of_lengths) gives it;
/// - the polar arm (revolute, then prismatic), and one revolute link with a range: the points
///   `s (cos q1, sin q1)` with `s = l1 + q2 + l2` in the slide's range and `q1` in the
///   revolute range, both signs of `s` counted (an annulus, or two opposite sectors of one);
/// - a slider carrying a link (prismatic, then revolute): the circles of radius `|l2|` about
///   the carriage positions `(q1 + l1, 0)`, or the arcs the revolute range allows;
/// - a slider carrying revolute links without ranges (prismatic, then any number of
///   revolute, PRR among them), or a slider alone: the annulus of the revolute links swept
///   along the carriage's segment of the x axis.
///
/// A prismatic joint without a range slides without end: the region is then unbounded
/// (outer radius and area infinite). For every other arm the description is conservative:
/// only the annulus `inner ..= outer` about the base that holds every reachable point is
/// known (from the triangle inequality over the links and slides), and
/// [`contains`](Self::contains) and [`area`](Self::area) answer for that annulus.
///
/// # Example
/// ```
/// use planar_arm::kinematics::Workspace;
/// use planar_arm::nalgebra::Point2;
/// use planar_arm::{Joint, Link};
///
/// let w = Workspace::of_lengths(&[1.0, 0.5]);
/// assert_eq!((w.inner_radius(), w.outer_radius()), (0.5, 1.5));
/// assert!(w.contains(&Point2::new(0.0, 1.0)) && !w.contains(&Point2::new(0.2, 0.0)));
///
/// // A polar arm whose slide travels 0.1 ..= 0.6 m: the annulus 0.8 ..= 1.3 m.
/// let polar = [
///     Link::rod(0.2, 1.0),
///     Link::rod(0.5, 1.0).with_joint(Joint::Prismatic).with_range(0.1, 0.6),
/// ];
/// let w = Workspace::of_links(&polar);
/// assert!(w.is_exact() && (w.inner_radius() - 0.8).abs() < 1e-15);
/// assert!(w.contains(&Point2::new(0.0, -1.0)) && !w.contains(&Point2::new(0.5, 0.0)));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Workspace {
    inner: f64,
    outer: f64,
    region: Region,
}

/// The region of a [`Workspace`].
#[derive(Debug, Clone, Copy, PartialEq)]
enum Region {
    /// The points whose distance from some point `(c, 0)`, `c` in `from ..= to`, lies in
    /// `inner ..= outer` (up to `slack`): the base's annulus when `from == to == 0`.
    Swept {
        from: f64,
        to: f64,
        inner: f64,
        outer: f64,
        slack: f64,
    },
    /// What [`ik_rp`] reaches with these lengths and ranges.
    Polar {
        l1: f64,
        l2: f64,
        range1: Range,
        range2: Range,
    },
    /// What [`ik_pr`] reaches with these lengths and ranges.
    Slider {
        l1: f64,
        l2: f64,
        range1: Range,
        range2: Range,
    },
    /// Only the annulus of the [`Workspace`] is known.
    Bounds,
}

/// The radii about the base of the region [`Region::Swept`] describes, without its slack:
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

/// A revolute range that does not restrict the joint (none, or a full turn or more).
fn free_turn(link: &Link) -> bool {
    link.range.is_none_or(|(lo, hi)| hi - lo >= TAU)
}

/// `range` if it is a range (no NaN, `lower <= upper`), else `None`: a range that is not one
/// restricts nothing the work-space can describe.
fn valid(range: Option<(f64, f64)>) -> Range {
    range.filter(|(lo, hi)| lo <= hi)
}

impl Workspace {
    /// The work-space of revolute links of the given lengths, base first. Lengths count by
    /// absolute value (a link of negative length sweeps the same circle); NaN and infinite
    /// lengths are skipped. No links give the single point at the origin.
    #[must_use]
    pub fn of_lengths(lengths: &[f64]) -> Self {
        let (inner, outer) = ring(lengths.iter().copied());
        Self::annulus(inner, outer)
    }

    /// The annulus `inner ..= outer` about the base, with the slack of [`ik2`].
    fn annulus(inner: f64, outer: f64) -> Self {
        Self {
            inner,
            outer,
            region: Region::Swept {
                from: 0.0,
                to: 0.0,
                inner,
                outer,
                slack: REACH_TOLERANCE * outer,
            },
        }
    }

    /// The work-space of an arm with these links, base first (a derived arm's
    /// [`links`](crate::PlanarArm::links)): their lengths, joint kinds and ranges. See the type's
    /// docs for the arms it describes exactly; for revolute links without ranges it equals
    /// [`of_lengths`](Self::of_lengths) of their lengths.
    ///
    /// NaN and infinite lengths are skipped, and a range holding NaN or with `lower > upper`
    /// counts as no range ([`Model::check`](crate::Model::check) refuses both).
    #[must_use]
    pub fn of_links(links: &[Link]) -> Self {
        let revolute = |l: &Link| l.joint == Joint::Revolute;
        if links.iter().all(|l| revolute(l) && free_turn(l)) {
            let (inner, outer) = ring(links.iter().map(|l| l.length));
            return Self::annulus(inner, outer);
        }
        let length = |l: &Link| if l.length.is_finite() { l.length } else { 0.0 };
        let region = match links {
            [a, b] if revolute(a) && !revolute(b) => Region::Polar {
                l1: length(a),
                l2: length(b),
                range1: valid(a.range),
                range2: valid(b.range),
            },
            [a] if revolute(a) => Region::Polar {
                l1: length(a),
                l2: 0.0,
                range1: valid(a.range),
                range2: Some((0.0, 0.0)),
            },
            [a, b] if !revolute(a) && revolute(b) => Region::Slider {
                l1: length(a),
                l2: length(b),
                range1: valid(a.range),
                range2: valid(b.range),
            },
            [a, rest @ ..] if !revolute(a) && rest.iter().all(|l| revolute(l) && free_turn(l)) => {
                let (inner, outer) = ring(rest.iter().map(length));
                let (from, to) = valid(a.range).map_or((f64::NEG_INFINITY, f64::INFINITY), |r| {
                    (length(a) + r.0, length(a) + r.1)
                });
                let sum: f64 = links.iter().map(|l| length(l).abs()).sum();
                Region::Swept {
                    from,
                    to,
                    inner,
                    outer,
                    slack: REACH_TOLERANCE * sum + slide_slack(&[], &[valid(a.range)]),
                }
            }
            _ => Region::Bounds,
        };
        let (inner, outer) = match region {
            Region::Swept {
                from,
                to,
                inner,
                outer,
                ..
            } => swept_radii(from, to, inner, outer),
            Region::Polar { l1, l2, range2, .. } => {
                let (lo, hi) = range2.unwrap_or((f64::NEG_INFINITY, f64::INFINITY));
                polar_radii(l1 + l2 + lo, l1 + l2 + hi)
            }
            Region::Slider { l1, l2, range1, .. } => {
                let (lo, hi) = range1.unwrap_or((f64::NEG_INFINITY, f64::INFINITY));
                swept_radii(l1 + lo, l1 + hi, l2.abs(), l2.abs())
            }
            Region::Bounds => bounds(links),
        };
        Self {
            inner,
            outer,
            region,
        }
    }

    /// Whether the region is described exactly (see the type's docs); `false` when only the
    /// annulus `inner_radius ..= outer_radius` that holds it is known.
    #[must_use]
    pub fn is_exact(&self) -> bool {
        !matches!(self.region, Region::Bounds)
    }

    /// The inner radius about the base: no reachable point is nearer. For revolute links
    /// without ranges `max(0, 2 max l - sum l)`; for the exact regions the nearest reachable
    /// distance, except a slider carrying a link with a revolute range, where it is that of
    /// the link without the range (a lower bound).
    #[must_use]
    pub fn inner_radius(&self) -> f64 {
        self.inner
    }

    /// The outer radius about the base: no reachable point is farther. For revolute links
    /// without ranges `sum l`; infinite for a prismatic joint without a range; attained by the
    /// exact regions, except a slider carrying a link with a revolute range (an upper bound).
    #[must_use]
    pub fn outer_radius(&self) -> f64 {
        self.outer
    }

    /// Whether the tip can reach `point`. Points holding NaN or infinities are not contained.
    ///
    /// For revolute links without ranges: its distance from the base lies in
    /// `inner ..= outer`, widened on both sides by [`REACH_TOLERANCE`]` * outer` (the slack
    /// [`ik2`] allows). For the polar arm and the slider carrying a link: what [`ik_rp`] and
    /// [`ik_pr`] reach, with their tolerances. For a slider carrying revolute links: some
    /// carriage position lies within `inner ..= outer` of the point, up to [`REACH_TOLERANCE`]
    /// times the arm's scale. When the region is not exact ([`is_exact`](Self::is_exact)), the
    /// answer is for the annulus that holds it: `false` is certain, `true` only possible.
    #[must_use]
    pub fn contains(&self, point: &Point2<f64>) -> bool {
        if !(point.x.is_finite() && point.y.is_finite()) {
            return false;
        }
        match self.region {
            Region::Swept {
                from,
                to,
                inner,
                outer,
                slack,
            } => {
                let (x, y) = (point.x, point.y);
                if from == 0.0 && to == 0.0 {
                    return annulus_check_slack(x.hypot(y), inner, outer, slack);
                }
                // The distances to the nearest and to the farthest carriage position.
                let gap = (from - x).max(x - to).max(0.0);
                let near = gap.hypot(y);
                let far = (x - from).abs().max((x - to).abs()).hypot(y);
                near - outer <= slack && inner - far <= slack
            }
            Region::Polar {
                l1,
                l2,
                range1,
                range2,
            } => ik_rp(l1, l2, range1, range2, point).is_ok(),
            Region::Slider {
                l1,
                l2,
                range1,
                range2,
            } => ik_pr(l1, l2, range1, range2, point).is_ok(),
            Region::Bounds => annulus_check(
                point.x.hypot(point.y),
                self.inner,
                self.outer,
                [point.x, point.y],
            )
            .is_ok(),
        }
    }

    /// `None` when [`contains`](Self::contains) holds, else how far outside the point lies:
    /// the distance to the annulus or swept annulus (exact), or what [`ik_rp`] and [`ik_pr`]
    /// report. The point must be finite.
    pub(super) fn miss(&self, point: &Point2<f64>) -> Option<f64> {
        if self.contains(point) {
            return None;
        }
        let distance = match self.region {
            Region::Swept {
                from,
                to,
                inner,
                outer,
                ..
            } => {
                let (x, y) = (point.x, point.y);
                let gap = (from - x).max(x - to).max(0.0);
                let near = gap.hypot(y);
                let far = (x - from).abs().max((x - to).abs()).hypot(y);
                (near - outer).max(inner - far)
            }
            Region::Polar {
                l1,
                l2,
                range1,
                range2,
            } => unreachable_distance(ik_rp(l1, l2, range1, range2, point).err()),
            Region::Slider {
                l1,
                l2,
                range1,
                range2,
            } => unreachable_distance(ik_pr(l1, l2, range1, range2, point).err()),
            Region::Bounds => {
                let r = point.x.hypot(point.y);
                (r - self.outer).max(self.inner - r)
            }
        };
        // Positive, as `ArmError::Unreachable` promises, even should rounding say otherwise.
        Some(distance.max(f64::MIN_POSITIVE))
    }

    /// The area, m^2: `pi (outer^2 - inner^2)` for revolute links without ranges, the exact
    /// area for the other exact regions (infinite when a prismatic joint has no range and the
    /// region is not a line), and for a region that is not exact the area of the annulus that
    /// holds it (an upper bound).
    #[must_use]
    pub fn area(&self) -> f64 {
        match self.region {
            Region::Swept {
                from,
                to,
                inner,
                outer,
                ..
            } => overflowed(swept_area(from, to, inner, outer)),
            Region::Polar {
                l1,
                l2,
                range1,
                range2,
            } => overflowed(polar_area(l1 + l2, range1, range2)),
            Region::Slider {
                l2, range1, range2, ..
            } => overflowed(slider_area(l2, range1, range2)),
            Region::Bounds => annulus_area(self.inner, self.outer),
        }
    }
}

/// The distance of an [`ArmError::Unreachable`], else (never, for the callers) infinity.
fn unreachable_distance(error: Option<crate::ArmError>) -> f64 {
    match error {
        Some(crate::ArmError::Unreachable { distance, .. }) => distance,
        _ => f64::INFINITY,
    }
}

/// An area whose terms overflowed (`inf - inf`) is beyond `f64::MAX`: infinity, not NaN.
fn overflowed(area: f64) -> f64 {
    if area.is_nan() {
        f64::INFINITY
    } else {
        area.max(0.0)
    }
}

/// `annulus_check` as a bool, with the given slack.
fn annulus_check_slack(radius: f64, inner: f64, outer: f64, slack: f64) -> bool {
    (radius - outer).max(inner - radius) <= slack
}

/// `(inner, outer)` of the annulus revolute links of these lengths reach; non-finite lengths
/// skipped.
fn ring(lengths: impl Iterator<Item = f64>) -> (f64, f64) {
    let (mut sum, mut longest) = (0.0_f64, 0.0_f64);
    for length in lengths.filter(|l| l.is_finite()) {
        sum += length.abs();
        longest = longest.max(length.abs());
    }
    // The longest minus the others, not `2 longest - sum`, whose `2 longest` overflows for
    // lengths near f64::MAX (an inner radius of infinity); `max` also maps the NaN of an
    // overflowing inf - inf to 0.
    ((longest - (sum - longest)).max(0.0), sum)
}

/// The conservative annulus of any arm. Only revolute joints turn: the links between two of
/// them point the same way, and with the slides of the prismatic joints among them (a first
/// joint that is prismatic slides along +x, the way link 1 then points) they make one term
/// `s_k u_k` of the tip, `s_k` in an interval. Then `|tip| <= sum max |s_k|` and
/// `|tip| >= min |s_k| - sum_{j != k} max |s_j|` for every k.
fn bounds(links: &[Link]) -> (f64, f64) {
    let (mut outer, mut nearest, mut nearest_far) = (0.0_f64, 0.0_f64, 0.0_f64);
    let mut group = (0.0_f64, 0.0_f64);
    let mut close = |(lo, hi): (f64, f64)| {
        let far = lo.abs().max(hi.abs());
        outer += far;
        let near = 0.0_f64.max(lo).max(-hi);
        if near > nearest {
            (nearest, nearest_far) = (near, far);
        }
    };
    for (i, link) in links.iter().enumerate() {
        if link.joint == Joint::Revolute && i > 0 {
            close(group);
            group = (0.0, 0.0);
        }
        if link.joint == Joint::Prismatic {
            let (lo, hi) = valid(link.range).unwrap_or((f64::NEG_INFINITY, f64::INFINITY));
            group = (group.0 + lo, group.1 + hi);
        }
        if link.length.is_finite() {
            group = (group.0 + link.length, group.1 + link.length);
        }
    }
    close(group);
    let others = outer - nearest_far;
    // `others` is NaN only when `outer` is infinite, and then so is some other term.
    let inner = if others.is_finite() {
        (nearest - others).max(0.0)
    } else {
        0.0
    };
    (inner, outer)
}

/// `pi (outer^2 - inner^2)`, 0 for a circle (also when the sum of the radii overflows).
fn annulus_area(inner: f64, outer: f64) -> f64 {
    if outer > inner {
        PI * (outer - inner) * (outer + inner)
    } else {
        0.0
    }
}

/// The area of [`Region::Swept`]: at height `y` the points are the carriage segment widened
/// by `[-ho, -hi]` and `[hi, ho]` (`ho = sqrt(outer^2 - y^2)`, `hi = sqrt(inner^2 - y^2)` or
/// 0), two intervals of length `L + ho - hi` (`L = to - from`) that overlap by
/// `max(0, L - 2 hi)`. Integrated over `y`:
/// `pi (outer^2 - inner^2) + 4 L outer - 2 L (outer - inner) - K(L, inner)`, with
/// `K(L, r) = integral of max(0, L - 2 sqrt(r^2 - y^2)) over |y| <= r`.
fn swept_area(from: f64, to: f64, inner: f64, outer: f64) -> f64 {
    let length = to - from;
    if length == 0.0 {
        return annulus_area(inner, outer);
    }
    if outer == 0.0 {
        return 0.0;
    }
    if length.is_infinite() {
        return f64::INFINITY;
    }
    annulus_area(inner, outer) + 4.0 * length * outer
        - 2.0 * length * (outer - inner)
        - overlap_integral(length, inner)
}

/// `K(L, r)`, the integral of `max(0, L - 2 sqrt(r^2 - y^2))` over `|y| <= r`: with
/// `sin a = L / 2r`, the integrand is positive for `|y| > r cos a`, and
/// `K = 2 L r (1 - cos a) - 2 r^2 (a - sin a cos a)` (`2 L r - pi r^2` once `L >= 2 r`).
fn overlap_integral(length: f64, r: f64) -> f64 {
    if r == 0.0 {
        return 0.0;
    }
    if length >= 2.0 * r {
        return 2.0 * length * r - PI * r * r;
    }
    let s = length / (2.0 * r);
    let a = s.asin();
    let c = (1.0 - s) * (1.0 + s);
    let c = c.sqrt();
    // 1 - cos a = s^2 / (1 + cos a), without cancellation for small L.
    2.0 * length * r * (s * s / (1.0 + c)) - 2.0 * r * r * (a - s * c)
}

/// The sub-intervals of `lo ..= hi` (`hi - lo <= 2 pi`) that the arc `range` covers, as angles
/// between `lo` and `hi`; none, one or two.
fn clip(range: Range, lo: f64, hi: f64) -> [Option<(f64, f64)>; 2] {
    let Some((a, b)) = range else {
        return [Some((lo, hi)), None];
    };
    if b - a >= TAU {
        return [Some((lo, hi)), None];
    }
    // The copy of the arc that starts in lo - 2 pi .. lo, and the next one.
    let start = a - TAU * ((a - lo) / TAU).floor() - TAU;
    let width = b - a;
    let part = |s: f64| {
        let (p, q) = (s.max(lo), (s + width).min(hi));
        (p <= q).then_some((p, q))
    };
    [part(start), part(start + TAU)]
}

/// The area of the polar arm's region: `s (cos t, sin t)` with `s` in `reach + range2` and
/// `t` in `range1`. The part with `s >= 0` is a sector of width `w` between the radii of the
/// positive slides, the part with `s <= 0` the opposite sector between those of the negative
/// ones; they overlap between the common radii over `2 max(0, w - pi)` of angle.
fn polar_area(reach: f64, range1: Range, range2: Range) -> f64 {
    let width = range1.map_or(TAU, |(lo, hi)| (hi - lo).min(TAU));
    let (from, to) = range2.map_or((f64::NEG_INFINITY, f64::INFINITY), |(lo, hi)| {
        (reach + lo, reach + hi)
    });
    if width == 0.0 || from == to {
        return 0.0;
    }
    if from.is_infinite() || to.is_infinite() {
        return f64::INFINITY;
    }
    let ring = |r1: f64, r2: f64| {
        if r2 > r1 {
            (r2 - r1) * (r2 + r1) / 2.0
        } else {
            0.0
        }
    };
    let positive = (to >= 0.0).then(|| (from.max(0.0), to));
    let negative = (from <= 0.0).then(|| ((-to).max(0.0), -from));
    let sector = |piece: Option<(f64, f64)>| piece.map_or(0.0, |(r1, r2)| width * ring(r1, r2));
    let overlap = match (positive, negative) {
        (Some((a1, a2)), Some((b1, b2))) => {
            2.0 * (width - PI).max(0.0) * ring(a1.max(b1), a2.min(b2))
        }
        _ => 0.0,
    };
    sector(positive) + sector(negative) - overlap
}

/// The area of the slider's region: `(c + r cos t, r sin t)` for `c` in `l1 + range1`, `t`
/// in `range2` (turned by pi for a negative `l2`), `r = |l2|`. At the height `y = r sin t`
/// (`|t| <= pi / 2`) the link pointing forward (angle `t`, if allowed) covers the segment
/// shifted by `r cos t`, the one pointing back (angle `pi - t`) the segment shifted by
/// `-r cos t`; each has the segment's length `L`, and they overlap by `max(0, L - 2 r cos t)`.
/// With `dy = r cos t dt`, the area is the integral over the allowed `t` of
/// `L r cos t` for each direction, less `r cos t max(0, L - 2 r cos t)` where both are.
fn slider_area(l2: f64, range1: Range, range2: Range) -> f64 {
    let r = l2.abs();
    let length = range1.map_or(f64::INFINITY, |(lo, hi)| hi - lo);
    if r == 0.0 || length == 0.0 {
        return 0.0;
    }
    let turn = if l2 < 0.0 { PI } else { 0.0 };
    let forward = range2.map(|(lo, hi)| (lo + turn, hi + turn));
    // t such that pi - t is allowed: the arc reflected.
    let backward = range2.map(|(lo, hi)| (PI - hi - turn, PI - lo - turn));
    let (lo, hi) = (-FRAC_PI_2, FRAC_PI_2);
    let sines = |parts: [Option<(f64, f64)>; 2]| -> f64 {
        parts
            .iter()
            .flatten()
            .map(|(a, b)| r * (b.sin() - a.sin()))
            .sum()
    };
    let ahead = clip(forward, lo, hi);
    let behind = clip(backward, lo, hi);
    let covered = sines(ahead) + sines(behind);
    if length.is_infinite() {
        return if covered > 0.0 { f64::INFINITY } else { 0.0 };
    }
    // Where both directions are allowed, the overlap's integral: positive where
    // cos t < L / 2r, that is |t| > t0.
    let t0 = (length / (2.0 * r)).min(1.0).acos();
    let antiderivative = |t: f64| length * r * t.sin() - r * r * (t + t.sin() * t.cos());
    let mut overlap = 0.0;
    for (a, b) in ahead.iter().flatten() {
        for (c, d) in clip(backward, *a, *b).iter().flatten() {
            for (p, q) in [(c.max(lo), d.min(-t0)), (c.max(t0), d.min(hi))] {
                if p < q {
                    overlap += antiderivative(q) - antiderivative(p);
                }
            }
        }
    }
    length * covered - overlap
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
            return Self::empty();
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

    /// The region that holds no point.
    fn empty() -> Self {
        Self {
            inner2: 0.0,
            outer2: 0.0,
            last: f64::INFINITY,
            disk: None,
            annulus: None,
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
    /// That is the region of three revolute joints without ranges (a range of a full turn or
    /// more counts as none). For an arm with a prismatic joint, or a revolute range of less
    /// than a turn, this does not compute the region and returns the empty one instead
    /// ([`is_empty`](DexterousWorkspace::is_empty)): it never claims a point that the arm
    /// cannot reach with every orientation.
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
    ///
    /// // A slider carrying two links: not computed, so empty.
    /// #[derive(PlanarArm)]
    /// struct Slider {
    ///     #[arm(length = 0.2, mass = 1, range = (-0.5, 0.5))] carriage: Prismatic,
    ///     #[arm(length = 1, mass = 1)] fore: Revolute,
    ///     #[arm(length = 0.25, mass = 1)] hand: Revolute,
    /// }
    /// let slider = Slider { carriage: Prismatic, fore: Revolute, hand: Revolute };
    /// assert!(slider.dexterous_workspace().is_empty());
    /// ```
    fn dexterous_workspace(&self) -> DexterousWorkspace;
}

impl<A: crate::PlanarArm<3> + ?Sized> DexterousWorkspaceExt for A {
    fn dexterous_workspace(&self) -> DexterousWorkspace {
        let links = self.links();
        if !links
            .iter()
            .all(|l| l.joint == Joint::Revolute && free_turn(l))
        {
            return DexterousWorkspace::empty();
        }
        let [l1, l2, l3] = links.map(|l| l.length);
        DexterousWorkspace::of_lengths(l1, l2, l3)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::test_support::{fk, fk_joints, Rng, PAIRS};
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
        // A narrower range: the same radii, no longer exact.
        let ranged = [
            Link::rod(1.0, 1.0).with_range(0.0, 1.0),
            Link::rod(0.5, 1.0),
        ];
        let w = Workspace::of_links(&ranged);
        assert!(!w.is_exact());
        assert_eq!((w.inner_radius(), w.outer_radius()), (0.5, 1.5));
        assert_eq!(w.area(), Workspace::of_lengths(&[1.0, 0.5]).area());
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
}
