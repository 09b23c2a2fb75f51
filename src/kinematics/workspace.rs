//! Work-spaces: the region any arm reaches and the dexterous work-space of three links.
//!
//! This file says what a [`Workspace`] is: the regions it tells apart, how links or lengths
//! pick one, and the answers (radii, containment, area) that dispatch on the region. The
//! formulas behind those answers, the areas above all, whose derivations are most of their
//! text, live in `geometry`, so that the constructors read as the list of arms described
//! exactly. The dexterous work-space (`dexterous`) is another kind of region, of three
//! revolute links only, and shares nothing with these but the annulus area.

use core::f64::consts::TAU;
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use nalgebra::Point2;

#[cfg(doc)]
use super::ik2;
use super::range::{slide_slack, Range, RangeMiss};
use super::{annulus_check, ik2_in_ranges, ik3_position, ik_pr, ik_rp, REACH_TOLERANCE};
use crate::{Joint, Link};

mod dexterous;
mod geometry;
pub(super) mod ranged;
#[cfg(test)]
mod tests;

pub use dexterous::{DexterousWorkspace, DexterousWorkspaceExt};
use geometry::{
    annulus_area, annulus_check_slack, overflowed, polar_area, slider_area, swept_area,
    unreachable_distance,
};
use ranged::RangedChain;

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
/// - two or three revolute links with ranges on any of them: the points
///   [`ik2_in_ranges`] or [`ik3_position`] reach, so that [`contains`](Self::contains) and
///   the arm's inverse kinematics always agree (tested on grids). Its radii are exact, and its
///   area is the integral over the distance from the base of the polar angles reached there
///   (exact arcs, integrated numerically to about 1e-10 relative);
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
/// (outer radius and area infinite). For every other arm (four or more links with a range, or
/// mixes of joints not listed) the description is conservative:
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
    /// What [`ik2_in_ranges`] or [`ik3_position`] reaches: two or three revolute links, some
    /// with ranges.
    Ranged(RangedChain),
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
fn polar_radii(from: f64, to: f64) -> (f64, f64) {
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
    /// [`of_lengths`](Self::of_lengths) of their lengths, offsets and reversed joints
    /// notwithstanding (every angle is reached either way). Otherwise an arm with a joint
    /// offset or reversed ([`Link::offset`], [`Link::reversed`]) gets the bounding annulus
    /// `0 ..= sum of the links' lengths and slides`.
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
        if links.iter().any(|l| l.offset != 0.0 || l.reversed) {
            // The exact regions and the grouped bounds are written for plain joints (a slide
            // continuing its link's line, ranges in the links' own angles): a turned or
            // reversed joint gets the annulus of the triangle inequality alone.
            let outer = links
                .iter()
                .map(|l| {
                    let slide = match (l.joint, valid(l.range)) {
                        (Joint::Revolute, _) => 0.0,
                        (Joint::Prismatic, Some((lo, hi))) => lo.abs().max(hi.abs()),
                        (Joint::Prismatic, None) => f64::INFINITY,
                    };
                    length(l).abs() + slide
                })
                .sum();
            return Self {
                inner: 0.0,
                outer,
                region: Region::Bounds,
            };
        }
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
            [a, b] if revolute(a) && revolute(b) => Region::Ranged(RangedChain {
                lengths: [length(a), length(b), 0.0],
                ranges: [valid(a.range), valid(b.range), None],
                three: false,
            }),
            [a, b, c] if revolute(a) && revolute(b) && revolute(c) => Region::Ranged(RangedChain {
                lengths: [length(a), length(b), length(c)],
                ranges: [valid(a.range), valid(b.range), valid(c.range)],
                three: true,
            }),
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
            Region::Ranged(chain) => chain.radii(),
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
    /// [`ik2`] allows). For the polar arm, the slider carrying a link and two or three ranged
    /// revolute links: what [`ik_rp`], [`ik_pr`], [`ik2_in_ranges`] and [`ik3_position`]
    /// reach, with their tolerances. For a slider carrying revolute links: some
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
            Region::Ranged(chain) => ranged_ik(&chain, point).is_ok(),
            Region::Bounds => annulus_check(
                point.x.hypot(point.y),
                self.inner,
                self.outer,
                [point.x, point.y],
            )
            .is_ok(),
        }
    }

    /// `None` when [`contains`](Self::contains) holds, else why not: how far outside the
    /// annulus or swept annulus the point lies (exact), or what the closed form behind an
    /// exact region reports. The point must be finite.
    pub(super) fn miss(&self, point: &Point2<f64>) -> Option<Miss> {
        if self.contains(point) {
            return None;
        }
        let miss = match self.region {
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
                Miss::Distance((near - outer).max(inner - far))
            }
            Region::Polar {
                l1,
                l2,
                range1,
                range2,
            } => miss_of(ik_rp(l1, l2, range1, range2, point).err()),
            Region::Slider {
                l1,
                l2,
                range1,
                range2,
            } => miss_of(ik_pr(l1, l2, range1, range2, point).err()),
            Region::Ranged(chain) => miss_of(ranged_ik(&chain, point).err()),
            Region::Bounds => {
                let r = point.x.hypot(point.y);
                Miss::Distance((r - self.outer).max(self.inner - r))
            }
        };
        // Positive, as `ArmError::Unreachable` promises, even should rounding say otherwise.
        Some(match miss {
            Miss::Distance(d) => Miss::Distance(d.max(f64::MIN_POSITIVE)),
            joint @ Miss::Joint(_) => joint,
        })
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
            Region::Ranged(chain) => chain.area(self.inner, self.outer),
            Region::Bounds => annulus_area(self.inner, self.outer),
        }
    }
}

/// Why a point lies outside a [`Workspace`]: its distance from the region, or the joint whose
/// range excludes it (for the regions that joint ranges cut out of what free joints reach).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Miss {
    Distance(f64),
    Joint(RangeMiss),
}

/// What an inverse kinematics error says about a miss.
fn miss_of(error: Option<crate::ArmError>) -> Miss {
    match error {
        Some(crate::ArmError::BeyondJointRange {
            joint,
            kind,
            excess,
            ..
        }) => Miss::Joint(RangeMiss {
            joint,
            kind,
            excess,
        }),
        other => Miss::Distance(unreachable_distance(other)),
    }
}

/// The closed form behind [`Region::Ranged`]: its `Ok` is the reach.
fn ranged_ik(chain: &RangedChain, point: &Point2<f64>) -> Result<(), crate::ArmError> {
    let [l1, l2, l3] = chain.lengths;
    let [r1, r2, r3] = chain.ranges;
    if chain.three {
        ik3_position(l1, l2, l3, [r1, r2, r3], point).map(|_| ())
    } else {
        ik2_in_ranges(l1, l2, [r1, r2], point).map(|_| ())
    }
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
