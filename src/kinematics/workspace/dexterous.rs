//! The dexterous (usable) work-space of three links: the points the tip reaches with every
//! orientation of the last link.
//!
//! A region of its own kind, not a [`Workspace`](super::Workspace): it is described by its
//! pieces (a disk and an annulus about the base) and exists for three revolute links only.

use core::f64::consts::PI;
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use nalgebra::Point2;

use super::free_turn;
use super::geometry::annulus_area;
#[cfg(doc)]
use crate::kinematics::ik3;
use crate::kinematics::REACH_TOLERANCE;
use crate::Joint;

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
