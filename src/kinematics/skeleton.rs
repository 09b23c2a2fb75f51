//! All the points of an arm in one call, for drawing it.

use nalgebra::{Point2, SVector};

/// The arm as a polyline: the position of every joint and of the tip, `N + 1` points from
/// the base (joint 1, at the origin) to the tip.
///
/// Stable Rust cannot write `[Point2<f64>; N + 1]` for a generic `N`, so the joints and the
/// tip are two fields, and [`points`](Self::points) walks all of them in order.
///
/// # Example
/// ```
/// use planar_arm::kinematics::Skeleton;
/// use planar_arm::prelude::*;
///
/// #[derive(PlanarArm)]
/// struct Two {
///     #[arm(length = 1, mass = 1)] upper: Revolute,
///     #[arm(length = 0.5, mass = 1)] fore: Revolute,
/// }
/// let arm = Two { upper: Revolute, fore: Revolute };
/// let skeleton = Skeleton::of(&arm, &Vector2::new(0.0, std::f64::consts::FRAC_PI_2));
/// let points: Vec<Point2<f64>> = skeleton.points().collect();
/// assert_eq!(points.len(), 3);
/// assert!((points[1] - Point2::new(1.0, 0.0)).norm() < 1e-15);
/// assert!((points[2] - Point2::new(1.0, 0.5)).norm() < 1e-15);
/// // An SVG polyline of the arm.
/// let svg: Vec<String> = skeleton.points().map(|p| format!("{:.3},{:.3}", p.x, p.y)).collect();
/// assert_eq!(svg.join(" "), "0.000,0.000 1.000,0.000 1.000,0.500");
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Skeleton<const N: usize> {
    /// Joint `k + 1` at index `k`; `joints[0]` is the base, at the origin
    /// ([`joint_positions`](crate::PlanarArm::joint_positions)).
    pub joints: [Point2<f64>; N],
    /// The end of the last link ([`tip_pose`](crate::PlanarArm::tip_pose)'s translation).
    pub tip: Point2<f64>,
}

impl<const N: usize> Skeleton<N> {
    /// The joints and the tip of `arm` at `q`.
    #[must_use]
    pub fn of<A: crate::PlanarArm<N> + ?Sized>(arm: &A, q: &SVector<f64, N>) -> Self {
        Self {
            joints: arm.joint_positions(q),
            tip: Point2::from(arm.tip_pose(q).translation.vector),
        }
    }

    /// The joints and the tip of an arm of these links at `q`, computed from the links (any
    /// mix of joint kinds, by the rules of [`tip_pose_of`](super::tip_pose_of)). The point of
    /// a prismatic joint is where its link starts, `q_i` along the previous link from that
    /// link's end: for a first joint that is prismatic, `(q1, 0)` rather than the origin, and
    /// the segment from the previous point to it is the previous link with the slide.
    ///
    /// # Example
    /// ```
    /// use planar_arm::kinematics::Skeleton;
    /// use planar_arm::nalgebra::{Point2, Vector2};
    /// use planar_arm::{Joint, Link};
    ///
    /// let polar = [Link::rod(0.2, 1.0), Link::rod(0.5, 1.0).with_joint(Joint::Prismatic)];
    /// let s = Skeleton::of_links(&polar, &Vector2::new(0.0, 0.3));
    /// let points: Vec<Point2<f64>> = s.points().collect();
    /// assert_eq!(points, [Point2::new(0.0, 0.0), Point2::new(0.5, 0.0), Point2::new(1.0, 0.0)]);
    /// ```
    #[must_use]
    pub fn of_links(links: &[crate::Link; N], q: &SVector<f64, N>) -> Self {
        let (joints, tip) = super::chain::joint_origins(links, q);
        Self { joints, tip }
    }

    /// The `N + 1` points from the base to the tip.
    pub fn points(&self) -> impl DoubleEndedIterator<Item = Point2<f64>> + ExactSizeIterator + '_ {
        (0..N + 1).map(move |k| self.point(k))
    }

    /// The `N` links as (start, end) segments, base first.
    pub fn links(
        &self,
    ) -> impl DoubleEndedIterator<Item = (Point2<f64>, Point2<f64>)> + ExactSizeIterator + '_ {
        (0..N).map(move |k| (self.joints[k], self.point(k + 1)))
    }

    /// Point `k` of [`points`](Self::points): joint `k + 1` for `k < N`, the tip for `k = N`;
    /// `None` beyond.
    #[must_use]
    pub fn get(&self, k: usize) -> Option<Point2<f64>> {
        (k <= N).then(|| self.point(k))
    }

    fn point(&self, k: usize) -> Point2<f64> {
        if k < N {
            self.joints[k]
        } else {
            self.tip
        }
    }
}
