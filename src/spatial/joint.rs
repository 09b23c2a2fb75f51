//! One joint of a spatial arm as its convention writes it: standard or modified
//! Denavit-Hartenberg parameters, or URDF's origin and axis.

use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};

use crate::Joint;

/// Where a joint sits and how it moves, in one of the three conventions users know. Lengths in
/// metres, angles in radians.
///
/// With `T(i-1, i)` the transformation from link `i-1`'s frame to link `i`'s (the base frame
/// for `i = 1`) and `q` the joint's value:
///
/// | convention | revolute | prismatic | link `i`'s frame |
/// | --- | --- | --- | --- |
/// | [`Dh`](Self::Dh) (Paul, Corke's `DHRobot`) | `Rz(q + theta) Tz(d) Tx(a) Rx(alpha)` | `Rz(theta) Tz(q + d) Tx(a) Rx(alpha)` | at the link's distal end |
/// | [`Mdh`](Self::Mdh) (Craig) | `Rx(alpha) Tx(a) Rz(q + theta) Tz(d)` | `Rx(alpha) Tx(a) Rz(theta) Tz(q + d)` | on joint `i`'s axis |
/// | [`Urdf`](Self::Urdf) | `Txyz Rz(y) Ry(p) Rx(r) Rot(axis, q)` | `Txyz Rz(y) Ry(p) Rx(r) Trans(axis, q)` | the joint's child frame |
///
/// # Example
/// ```
/// use planar_arm::spatial::JointGeometry;
/// use planar_arm::Joint;
///
/// // A hinge with a 0.4318 m link: at q = 0 the next frame is 0.4318 m along x.
/// let dh = JointGeometry::Dh { a: 0.4318, alpha: 0.0, d: 0.0, theta: 0.0 };
/// let t = dh.transform(Joint::Revolute, 0.0);
/// assert!((t.translation.vector.x - 0.4318).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum JointGeometry {
    /// Standard (distal) Denavit-Hartenberg parameters.
    Dh {
        /// Link length, along `x_i`.
        a: f64,
        /// Link twist, about `x_i`.
        alpha: f64,
        /// Link offset, along `z_{i-1}`.
        d: f64,
        /// Joint angle offset, about `z_{i-1}`.
        theta: f64,
    },
    /// Modified (proximal) Denavit-Hartenberg parameters.
    Mdh {
        /// Link length, along `x_{i-1}`.
        a: f64,
        /// Link twist, about `x_{i-1}`.
        alpha: f64,
        /// Link offset, along `z_i`.
        d: f64,
        /// Joint angle offset, about `z_i`.
        theta: f64,
    },
    /// URDF's `<origin xyz rpy>` and `<axis>` (normalised when used; a zero axis moves
    /// nothing).
    Urdf {
        /// The joint frame's origin in the parent frame.
        xyz: Vector3<f64>,
        /// Roll, pitch, yaw about the parent's fixed x, y, z axes: `Rz(y) Ry(p) Rx(r)`.
        rpy: Vector3<f64>,
        /// The axis in the joint frame.
        axis: Vector3<f64>,
    },
}

fn rot_x(a: f64) -> Isometry3<f64> {
    Isometry3::from_parts(
        Translation3::identity(),
        UnitQuaternion::from_axis_angle(&Vector3::x_axis(), a),
    )
}

fn rot_z(a: f64) -> Isometry3<f64> {
    Isometry3::from_parts(
        Translation3::identity(),
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), a),
    )
}

fn shift(x: f64, y: f64, z: f64) -> Isometry3<f64> {
    Isometry3::translation(x, y, z)
}

impl JointGeometry {
    /// `T(i-1, i)` at joint value `q` (radians for a hinge, metres for a slide).
    #[must_use]
    pub fn transform(&self, kind: Joint, q: f64) -> Isometry3<f64> {
        let (spin, slide) = match kind {
            Joint::Revolute => (q, 0.0),
            Joint::Prismatic => (0.0, q),
        };
        match *self {
            Self::Dh { a, alpha, d, theta } => {
                rot_z(spin + theta) * shift(0.0, 0.0, slide + d) * shift(a, 0.0, 0.0) * rot_x(alpha)
            }
            Self::Mdh { a, alpha, d, theta } => {
                rot_x(alpha) * shift(a, 0.0, 0.0) * rot_z(spin + theta) * shift(0.0, 0.0, slide + d)
            }
            Self::Urdf { xyz, rpy, axis } => {
                let origin = Isometry3::from_parts(
                    Translation3::from(xyz),
                    UnitQuaternion::from_euler_angles(rpy.x, rpy.y, rpy.z),
                );
                let axis = axis.try_normalize(0.0).unwrap_or_else(Vector3::zeros);
                let motion = match kind {
                    Joint::Revolute => Isometry3::from_parts(
                        Translation3::identity(),
                        UnitQuaternion::from_scaled_axis(axis * q),
                    ),
                    Joint::Prismatic => Isometry3::from_parts(
                        Translation3::from(axis * q),
                        UnitQuaternion::identity(),
                    ),
                };
                origin * motion
            }
        }
    }

    /// The joint's axis in the parent frame (link `i-1`'s), as a point on it and a unit
    /// direction: where the joint turns about or slides along, which its value does not move.
    #[must_use]
    pub fn axis_in_parent(&self) -> (Vector3<f64>, Vector3<f64>) {
        match *self {
            // Rz(theta) (and Tz(d) for a slide) precede the motion, and keep z through the
            // origin where it was.
            Self::Dh { .. } => (Vector3::zeros(), Vector3::z()),
            Self::Mdh { a, alpha, .. } => {
                let pre = rot_x(alpha) * shift(a, 0.0, 0.0);
                (pre.translation.vector, pre.rotation * Vector3::z())
            }
            Self::Urdf { xyz, rpy, axis } => {
                let rotation = UnitQuaternion::from_euler_angles(rpy.x, rpy.y, rpy.z);
                let axis = axis.try_normalize(0.0).unwrap_or_else(Vector3::zeros);
                (xyz, rotation * axis)
            }
        }
    }
}
