//! [`SpatialIk`]: the closed-form inverse kinematics of six-joint arms whose geometry decouples
//! position from orientation.
//!
//! The arm is described by its joint axes at `q = 0` (a point and a unit direction each) and the
//! tool pose there, `home`: by the product of exponentials, the tool at `q` is
//! `exp(xi_1 q_1) ... exp(xi_6 q_6) home`, whatever convention wrote the arm. Three classes
//! cover industry:
//!
//! - [`IkClass::SphericalWrist`]: joints 1-3 revolute with axes 2 and 3 parallel (PUMA, KUKA,
//!   ABB, Fanuc, Staubli), axes 4, 5, 6 meeting in the wrist centre `c`;
//! - [`IkClass::SlidingWrist`]: joints 1 and 2 revolute with intersecting axes, joint 3
//!   prismatic (the Stanford arm), axes 4, 5, 6 meeting in `c`;
//! - [`IkClass::ParallelTriple`]: all revolute, axes 2, 3, 4 parallel, axes 5 and 6 meeting in
//!   `c` (the UR family).
//!
//! `c` is fixed in the tool's frame, so the target gives its position. Joint 1 is found from
//! the plane that joints 2-4 move in (parallel axes) or from the distance to the shoulder
//! (intersecting axes); the next joints by planar geometry or two rotations about
//! intersecting axes; the wrist by two rotations about intersecting axes and one about the
//! last. Every branch is returned: up to 2 x 2 x 2 = 8 solutions.

use nalgebra::{Isometry3, Matrix3, Point3, Vector3};

use super::IkSolutions;
use crate::kinematics::REACH_TOLERANCE;
use crate::{ArmError, Joint};

/// Which decoupling a six-joint arm allows (see the module's docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum IkClass {
    /// Revolute 1-3 with axes 2 and 3 parallel, axes 4-6 meeting in a point.
    SphericalWrist,
    /// Revolute 1 and 2 with intersecting axes, prismatic 3, axes 4-6 meeting in a point.
    SlidingWrist,
    /// Revolute 1-6 with axes 2, 3, 4 parallel and axes 5 and 6 meeting in a point.
    ParallelTriple,
}

/// A six-joint arm as its closed-form inverse kinematics sees it: joint axes at `q = 0`, the
/// tool pose there and the point `c` the decoupling turns on (see the module's docs).
///
/// `#[derive(SpatialArm)]` builds it with constants for arms it classifies from their exact
/// geometry; [`SpatialIk::of_model`] classifies a numeric model.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpatialIk {
    /// The class.
    pub class: IkClass,
    /// A point on each joint's axis at `q = 0`, base frame.
    pub points: [Vector3<f64>; 6],
    /// Each joint's unit axis at `q = 0`, base frame.
    pub axes: [Vector3<f64>; 6],
    /// The tool pose at `q = 0`.
    pub home: Isometry3<f64>,
    /// The wrist centre (axes 4-6) or the meeting point of axes 5 and 6, at `q = 0`.
    pub centre: Vector3<f64>,
    /// The arm's scale (the largest distance of a point above from the base): the reach
    /// tolerances are [`REACH_TOLERANCE`] times it.
    pub scale: f64,
}

impl SpatialIk {
    /// Every solution for the tool pose `target`, each angle in (-pi, pi] or the representative
    /// in its range, solutions outside `ranges` dropped.
    ///
    /// # Errors
    /// [`ArmError::NonFinite`] for a target holding NaN or infinities;
    /// [`ArmError::OutOfReach`] when the point `c` or (for the parallel class) the tool axis
    /// cannot be placed, by how much; [`ArmError::BeyondJointRange`] when solutions exist but
    /// none lies within the ranges.
    pub fn solve(
        &self,
        target: &Isometry3<f64>,
        ranges: &[Option<(f64, f64)>; 6],
    ) -> Result<IkSolutions<6>, ArmError> {
        let finite = target.translation.vector.iter().all(|x| x.is_finite())
            && target.rotation.coords.iter().all(|x| x.is_finite());
        if !finite {
            return Err(ArmError::NonFinite { argument: "target" });
        }
        let mut all = IkSolutions::new();
        let goal = Goal {
            centre: target
                .transform_point(
                    &self
                        .home
                        .inverse_transform_point(&Point3::from(self.centre)),
                )
                .coords,
            rest: (target.rotation * self.home.rotation.inverse())
                .to_rotation_matrix()
                .into_inner(),
        };
        let reach = match self.class {
            IkClass::SphericalWrist => self.spherical(&goal, &mut all),
            IkClass::SlidingWrist => self.sliding(&goal, &mut all),
            IkClass::ParallelTriple => self.parallel(&goal, &mut all),
        };
        if let Err(miss) = reach {
            let t = target.translation.vector;
            return Err(ArmError::OutOfReach {
                target: [t.x, t.y, t.z],
                what: miss.what,
                distance: miss.distance,
                unit: miss.unit,
            });
        }
        let kinds = self.kinds();
        super::ranges::keep_within(&mut all, &kinds, ranges, self.slack())?;
        Ok(all)
    }

    /// The kinds of the six joints the class implies.
    #[must_use]
    pub fn kinds(&self) -> [Joint; 6] {
        let mut kinds = [Joint::Revolute; 6];
        if self.class == IkClass::SlidingWrist {
            kinds[2] = Joint::Prismatic;
        }
        kinds
    }

    /// How far (metres) a point may miss and count as reached.
    pub(crate) fn slack(&self) -> f64 {
        REACH_TOLERANCE * self.scale.max(f64::MIN_POSITIVE)
    }
}

/// What the target asks of the arm: where the point `c` must go, and the rotation the joints
/// must make, `R_1 ... R_6 = rest` (the target's rotation after the home pose's).
pub(crate) struct Goal {
    pub centre: Vector3<f64>,
    pub rest: Matrix3<f64>,
}

/// Why a target is out of reach, before it is an [`ArmError`].
#[derive(Debug, Clone, Copy)]
pub(crate) struct Miss {
    what: &'static str,
    distance: f64,
    unit: &'static str,
}

impl Miss {
    pub(crate) fn metres(what: &'static str, distance: f64) -> Self {
        Self {
            what,
            distance: distance.max(f64::MIN_POSITIVE),
            unit: "m",
        }
    }
    pub(crate) fn radians(what: &'static str, distance: f64) -> Self {
        Self {
            what,
            distance: distance.max(f64::MIN_POSITIVE),
            unit: "rad",
        }
    }
}

/// A unit vector across `w` (unit).
pub(crate) fn any_across(w: &Vector3<f64>) -> Vector3<f64> {
    let e = if w.x.abs() < 0.6 {
        Vector3::x()
    } else {
        Vector3::y()
    };
    w.cross(&e).normalize()
}

/// The point of line `(p1, w1)` nearest line `(p2, w2)`; for intersecting lines, where they
/// meet. Parallel lines give `p1`.
pub(crate) fn closest_point(
    p1: &Vector3<f64>,
    w1: &Vector3<f64>,
    p2: &Vector3<f64>,
    w2: &Vector3<f64>,
) -> Vector3<f64> {
    let k = w1.dot(w2);
    let d = p2 - p1;
    let denominator = 1.0 - k * k;
    if denominator.abs() < 1e-15 {
        return *p1;
    }
    let s = (w1.dot(&d) - k * w2.dot(&d)) / denominator;
    p1 + w1 * s
}
