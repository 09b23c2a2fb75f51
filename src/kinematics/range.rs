//! Joint ranges in the closed forms: checking them, and fitting a branch's joint values into
//! them.

use core::f64::consts::TAU;
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use super::REACH_TOLERANCE;
use crate::{ArmError, Joint};

/// A joint range as the closed forms take it: `None` for a free joint, `Some((lower, upper))`
/// in radians or metres, an infinite bound no bound.
pub(super) type Range = Option<(f64, f64)>;

/// `Err` for a range holding NaN (`NonFinite`, `"ranges"`) or with `lower > upper`
/// (`OutOfRange`, `"range"`, the 0-based joint, the lower bound).
pub(super) fn check_ranges(ranges: &[Range]) -> Result<(), ArmError> {
    for (joint, range) in ranges.iter().enumerate() {
        if let Some((lower, upper)) = *range {
            if lower.is_nan() || upper.is_nan() {
                return Err(ArmError::NonFinite { argument: "ranges" });
            }
            if lower > upper {
                return Err(ArmError::OutOfRange {
                    what: "range",
                    link: Some(joint),
                    value: lower,
                });
            }
        }
    }
    Ok(())
}

/// The slack of a prismatic range: [`REACH_TOLERANCE`] times the arm's scale, the sum of
/// `|l|` and of the larger finite `|bound|` of each of the (prismatic) `ranges`.
pub(super) fn slide_slack(lengths: &[f64], ranges: &[Range]) -> f64 {
    let mut scale: f64 = lengths.iter().map(|l| l.abs()).sum();
    for (lower, upper) in ranges.iter().flatten() {
        let finite = |b: &f64| if b.is_finite() { b.abs() } else { 0.0 };
        scale += finite(lower).max(finite(upper));
    }
    REACH_TOLERANCE * scale
}

/// The value within `range` that joint `kind` takes for `value`, or how far outside the range
/// every representative of `value` lies (always more than the slack).
///
/// A prismatic value counts as inside when it lies within `slack` of the range, and is then
/// clamped into it. A revolute angle `value` (finite, in practice in (-pi, pi]) stands for every
/// `value + 2 pi k`: it is returned as it is when it lies in the range (within
/// [`REACH_TOLERANCE`] radians), else the representative nearest the range side it lies
/// beyond, clamped into the range; its excess is the angle to the nearer end of the range.
pub(crate) fn fit(kind: Joint, value: f64, range: Range, slack: f64) -> Result<f64, f64> {
    // Positive even when a bound near f64::MAX overflows the arithmetic below.
    fit_unchecked(kind, value, range, slack).map_err(|e| e.max(f64::MIN_POSITIVE))
}

fn fit_unchecked(kind: Joint, value: f64, range: Range, slack: f64) -> Result<f64, f64> {
    let Some((lower, upper)) = range else {
        return Ok(value);
    };
    let slack = match kind {
        Joint::Prismatic => slack,
        Joint::Revolute => REACH_TOLERANCE,
    };
    if value >= lower - slack && value <= upper + slack {
        return Ok(value.max(lower).min(upper));
    }
    if kind == Joint::Prismatic {
        return Err((lower - value).max(value - upper));
    }
    // Neither difference below is infinite: `value < lower` means `lower` is finite, and
    // `value > upper` that `upper` is.
    if value < lower {
        // The smallest representative at or above `lower`, and the one before it.
        let above = value + TAU * ((lower - value) / TAU).ceil();
        if !above.is_finite() {
            return Err(f64::INFINITY);
        }
        if above <= upper + slack {
            return Ok(above.max(lower).min(upper));
        }
        if above - TAU >= lower - slack {
            return Ok(lower);
        }
        Err((above - upper).min(lower - (above - TAU)))
    } else {
        let below = value - TAU * ((value - upper) / TAU).ceil();
        if !below.is_finite() {
            return Err(f64::INFINITY);
        }
        if below >= lower - slack {
            return Ok(below.max(lower).min(upper));
        }
        if below + TAU <= upper + slack {
            return Ok(upper);
        }
        Err((lower - below).min(below + TAU - upper))
    }
}

/// `Err(NonFinite { argument: "result" })` when finite input overflowed a joint value.
pub(super) fn finite<const N: usize>(branches: [[f64; N]; 2]) -> Result<[[f64; N]; 2], ArmError> {
    if branches.iter().flatten().all(|v| v.is_finite()) {
        Ok(branches)
    } else {
        Err(ArmError::NonFinite { argument: "result" })
    }
}

/// Fits every joint value of each branch into its range: the branches that fit, in their
/// order (one surviving branch fills both entries), or the nearer branch's [`RangeMiss`].
pub(super) fn fit_branches<const N: usize>(
    kinds: &[Joint; N],
    ranges: &[Range; N],
    slack: f64,
    branches: [[f64; N]; 2],
) -> Result<[[f64; N]; 2], RangeMiss> {
    let fitted = branches.map(|branch| {
        let mut out = [0.0; N];
        let mut worst: Option<RangeMiss> = None;
        for i in 0..N {
            match fit(kinds[i], branch[i], ranges[i], slack) {
                Ok(v) => out[i] = v,
                Err(excess) if worst.is_none_or(|w| excess > w.excess) => {
                    worst = Some(RangeMiss {
                        joint: i,
                        kind: kinds[i],
                        excess,
                    });
                }
                Err(_) => {}
            }
        }
        worst.map_or(Ok(out), Err)
    });
    match fitted {
        [Ok(a), Ok(b)] => Ok([a, b]),
        [Ok(a), Err(_)] | [Err(_), Ok(a)] => Ok([a, a]),
        [Err(a), Err(b)] => Err(if b.excess < a.excess { b } else { a }),
    }
}

/// Why no branch fits the ranges: in the branch that comes nearest (the smaller largest
/// excess), the joint that lies farthest outside its range and by how much (always > 0).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct RangeMiss {
    pub joint: usize,
    pub kind: Joint,
    pub excess: f64,
}

impl RangeMiss {
    /// As an [`ArmError`].
    pub fn error(self) -> ArmError {
        ArmError::BeyondJointRange {
            joint: self.joint,
            kind: self.kind,
            excess: self.excess,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f64::consts::PI;

    #[test]
    fn revolute_representatives() {
        let r = |v, range| fit(Joint::Revolute, v, Some(range), 0.0);
        assert_eq!(r(0.5, (0.0, 1.0)), Ok(0.5));
        // 3 rad is also 3 - 2 pi = -3.28: inside (-4, -3).
        assert_eq!(r(3.0, (-4.0, -3.0)), Ok(3.0 - TAU));
        // -3 rad is also -3 + 2 pi = 3.28: inside (3, 4).
        assert_eq!(r(-3.0, (3.0, 4.0)), Ok(-3.0 + TAU));
        // More than a turn: the value itself.
        assert_eq!(r(1.0, (-10.0, 10.0)), Ok(1.0));
        // Outside: the excess is the angle to the nearer end.
        let e = r(PI / 2.0, (-0.5, 0.5)).unwrap_err();
        assert!((e - (PI / 2.0 - 0.5)).abs() < 1e-15);
        let e = r(-3.0, (-0.5, 0.5)).unwrap_err();
        assert!((e - 2.5).abs() < 1e-15);
        let e = r(3.0, (-0.5, 0.5)).unwrap_err();
        assert!((e - 2.5).abs() < 1e-15);
        // Half-infinite ranges always hold a representative.
        assert_eq!(r(3.0, (f64::NEG_INFINITY, 0.0)), Ok(3.0 - TAU));
        assert_eq!(r(-3.0, (0.0, f64::INFINITY)), Ok(-3.0 + TAU));
        // Within the tolerance of an end: clamped onto it.
        assert_eq!(r(1.0 + 0.5 * REACH_TOLERANCE, (0.0, 1.0)), Ok(1.0));
        assert!(r(1.0 + 2.0 * REACH_TOLERANCE, (0.0, 1.0)).is_err());
    }

    #[test]
    fn prismatic_values() {
        let p = |v, range| fit(Joint::Prismatic, v, Some(range), 1e-9);
        assert_eq!(p(0.3, (0.0, 1.0)), Ok(0.3));
        assert_eq!(p(1.0 + 1e-10, (0.0, 1.0)), Ok(1.0));
        assert_eq!(p(-0.25, (0.0, 1.0)), Err(0.25));
        // Not periodic.
        assert!(p(TAU + 0.5, (0.0, 1.0)).is_err());
        assert_eq!(fit(Joint::Prismatic, 7.0, None, 0.0), Ok(7.0));
    }

    #[test]
    fn ranges_are_checked() {
        assert_eq!(check_ranges(&[None, Some((0.0, 1.0))]), Ok(()));
        assert_eq!(
            check_ranges(&[None, Some((f64::NAN, 1.0))]),
            Err(ArmError::NonFinite { argument: "ranges" })
        );
        assert_eq!(
            check_ranges(&[None, Some((2.0, 1.0))]),
            Err(ArmError::OutOfRange {
                what: "range",
                link: Some(1),
                value: 2.0
            })
        );
        assert_eq!(check_ranges(&[Some((f64::NEG_INFINITY, 1.0))]), Ok(()));
    }

    #[test]
    fn branches_that_survive() {
        let kinds = [Joint::Revolute, Joint::Prismatic];
        let ranges = [None, Some((0.0, 1.0))];
        let both = [[0.1, 0.5], [0.2, 0.7]];
        assert_eq!(fit_branches(&kinds, &ranges, 0.0, both), Ok(both));
        let one = [[0.1, 1.5], [0.2, 0.7]];
        assert_eq!(
            fit_branches(&kinds, &ranges, 0.0, one),
            Ok([[0.2, 0.7], [0.2, 0.7]])
        );
        let none = [[0.1, 1.5], [0.2, -0.25]];
        let miss = RangeMiss {
            joint: 1,
            kind: Joint::Prismatic,
            excess: 0.25,
        };
        assert_eq!(fit_branches(&kinds, &ranges, 0.0, none), Err(miss));
        // The nearer branch names its own worst joint.
        let ranges = [Some((0.0, 0.5)), Some((0.0, 1.0))];
        let none = [[0.9, 0.5], [0.1, 1.25]];
        let miss = RangeMiss {
            joint: 1,
            kind: Joint::Prismatic,
            excess: 0.25,
        };
        assert_eq!(fit_branches(&kinds, &ranges, 0.0, none), Err(miss));
    }
}
