//! Which class (if any) a numeric model's geometry puts a six-joint arm in, within a tolerance:
//! for models built at run time. `#[derive(SpatialArm)]` decides from the exact geometry.

use nalgebra::{SVector, Vector3};

use super::solver::{closest_point, IkClass, SpatialIk};
use crate::reference::spatial::{joint_axes, tip_pose};
use crate::spatial::SpatialModel;
use crate::Joint;

/// Directions within this angle (radians) count as parallel; lines within this fraction of the
/// arm's scale count as meeting.
const TOLERANCE: f64 = 1e-9;

fn parallel(a: &Vector3<f64>, b: &Vector3<f64>) -> bool {
    a.cross(b).norm() <= TOLERANCE
}

/// The point where two lines meet, if they are not parallel and pass within `tol` of each
/// other.
fn meet(
    p1: &Vector3<f64>,
    w1: &Vector3<f64>,
    p2: &Vector3<f64>,
    w2: &Vector3<f64>,
    tol: f64,
) -> Option<Vector3<f64>> {
    if parallel(w1, w2) {
        return None;
    }
    let a = closest_point(p1, w1, p2, w2);
    let b = closest_point(p2, w2, p1, w1);
    ((a - b).norm() <= tol).then_some((a + b) * 0.5)
}

/// The distance of point `c` from the line `(p, w)`.
fn off_line(c: &Vector3<f64>, p: &Vector3<f64>, w: &Vector3<f64>) -> f64 {
    let d = c - p;
    (d - w * w.dot(&d)).norm()
}

impl SpatialIk {
    /// The closed-form description of a numeric six-joint model, if its geometry at `q = 0`
    /// puts it in one of the [`IkClass`]es (axes parallel within 1e-9 rad, lines meeting within
    /// 1e-9 of the arm's scale); `None` otherwise.
    ///
    /// # Example
    /// ```
    /// use core::f64::consts::FRAC_PI_2;
    /// use planar_arm::spatial::{IkClass, JointGeometry, SpatialIk, SpatialJoint, SpatialLink, SpatialModel};
    /// use planar_arm::nalgebra::{Isometry3, Vector3};
    /// use planar_arm::Joint;
    ///
    /// // The PUMA 560's kinematics (Corke's standard DH parameters).
    /// let dh = |a, alpha, d| SpatialJoint::new(JointGeometry::Dh { a, alpha, d, theta: 0.0 }, Joint::Revolute);
    /// let puma = SpatialModel {
    ///     joints: [
    ///         dh(0.0, FRAC_PI_2, 0.0), dh(0.4318, 0.0, 0.0), dh(0.0203, -FRAC_PI_2, 0.15005),
    ///         dh(0.0, FRAC_PI_2, 0.4318), dh(0.0, -FRAC_PI_2, 0.0), dh(0.0, 0.0, 0.0),
    ///     ],
    ///     links: [SpatialLink::MASSLESS; 6],
    ///     gravity: Vector3::new(0.0, 0.0, -9.81),
    ///     tool: Isometry3::identity(),
    ///     payload: None,
    /// };
    /// assert_eq!(SpatialIk::of_model(&puma).map(|ik| ik.class), Some(IkClass::SphericalWrist));
    /// ```
    #[must_use]
    pub fn of_model(model: &SpatialModel<6>) -> Option<Self> {
        let zero = SVector::<f64, 6>::zeros();
        let lines = joint_axes(model, &zero);
        let home = tip_pose(model, &zero);
        let points = lines.map(|(p, _)| p);
        let axes = lines.map(|(_, w)| w);
        let scale = points
            .iter()
            .map(Vector3::norm)
            .fold(home.translation.vector.norm(), f64::max)
            .max(f64::MIN_POSITIVE);
        let tol = TOLERANCE * scale;
        let kinds = model.joints.map(|j| j.kind);
        let revolute = |r: core::ops::Range<usize>| kinds[r].iter().all(|k| *k == Joint::Revolute);
        let wrist = || {
            let c = meet(&points[3], &axes[3], &points[4], &axes[4], tol)?;
            (off_line(&c, &points[5], &axes[5]) <= tol && !parallel(&axes[4], &axes[5]))
                .then_some(c)
        };
        let make = |class, centre| Self {
            class,
            points,
            axes,
            home,
            centre,
            scale,
        };
        if revolute(0..6) && parallel(&axes[1], &axes[2]) && !parallel(&axes[0], &axes[1]) {
            if let Some(c) = wrist() {
                return Some(make(IkClass::SphericalWrist, c));
            }
            let five_six = meet(&points[4], &axes[4], &points[5], &axes[5], tol);
            if let (true, Some(c)) = (
                parallel(&axes[1], &axes[3]) && !parallel(&axes[4], &axes[1]),
                five_six,
            ) {
                return Some(make(IkClass::ParallelTriple, c));
            }
        }
        let sliding = revolute(0..2)
            && kinds[2] == Joint::Prismatic
            && revolute(3..6)
            && meet(&points[0], &axes[0], &points[1], &axes[1], tol).is_some();
        if sliding {
            if let Some(c) = wrist() {
                return Some(make(IkClass::SlidingWrist, c));
            }
        }
        None
    }
}
