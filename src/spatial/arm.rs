//! [`SpatialArm`]: what `#[derive(SpatialArm)]` generates for a 3-D serial arm.

use nalgebra::{Isometry3, SMatrix, SVector, Vector3};

use super::{numeric, IkSolutions, SpatialModel};
use crate::exact::SpatialDerivation;
use crate::kinematics::DlsOptions;
use crate::{ArmError, Dynamics, Real};

/// A spatial serial arm of `N` joints, revolute or prismatic, whose kinematics, statics and
/// dynamics were derived at compile time by `#[derive(SpatialArm)]`. The equations of motion
/// (`mass_matrix`, `inverse_dynamics`, `gravity`, ...) are its supertrait
/// [`Dynamics`](crate::Dynamics), shared with planar arms.
///
/// Conventions: `q[i]` is joint `i`'s angle (radians) or slide (metres); link `i`'s frame is
/// the one its convention defines ([`JointGeometry`](super::JointGeometry)); the tool frame is
/// the `tool` offset from the last link's frame. Poses are in the base frame. The Jacobian's
/// rows 0-2 are the tool origin's linear velocity and rows 3-5 the angular velocity, both in
/// base coordinates (Pinocchio's `LOCAL_WORLD_ALIGNED`). Gravity torques `g = dV/dq` are what
/// the joints apply to hold the arm still.
pub trait SpatialArm<const N: usize>: Dynamics<N> {
    /// The exact tool pose and gravity, as `const` data with `Display` and LaTeX.
    const EXACT: SpatialDerivation<N>;

    /// The joints' names, base first, in the order of `q`: the joint fields' names, or for an
    /// arm read from a model file the file's joint names (MuJoCo's `qpos` order).
    const JOINT_NAMES: [&'static str; N];

    /// The tool frame in the base frame.
    fn tip_pose(&self, q: &SVector<f64, N>) -> Isometry3<f64>;

    /// Each link's frame in the base frame, base first.
    fn link_poses(&self, q: &SVector<f64, N>) -> [Isometry3<f64>; N];

    /// The geometric Jacobian of the tool frame: rows 0-2 the linear velocity of its origin,
    /// rows 3-5 the angular velocity, both in base coordinates.
    fn jacobian<T: Real>(&self, q: &SVector<T, N>) -> SMatrix<T, 6, N>;

    /// The numeric description of the arm now (run-time parameters read from their fields).
    fn model(&self) -> SpatialModel<N>;

    /// The arm with its current values as MJCF, which MuJoCo loads and this derive reads back
    /// to the same dynamics (`#[arm(mjcf = "..")]`, `q` equal to MuJoCo's `qpos`): one body per
    /// link named `JOINT_NAME_link`, the tool frame as a body `tool`, a payload merged into the
    /// last link. Right-angle twists are written as whole degrees and read back exactly.
    /// Inertias that break the triangle inequality (which MuJoCo refuses) set
    /// `balanceinertia`, and the file says which: MuJoCo then uses their mean moment.
    ///
    /// ```
    /// use planar_arm::prelude::*;
    ///
    /// #[derive(SpatialArm)]
    /// struct PanTilt {
    ///     #[arm(dh(d = 0.1, alpha = pi/2), mass = 1.0, inertia(xx = 0.01, yy = 0.01, zz = 0.01))]
    ///     pan: Revolute,
    ///     #[arm(dh(a = 0.3), mass = 0.5, com = (-0.15, 0, 0), inertia(xx = 0.001, yy = 0.004, zz = 0.004))]
    ///     tilt: Revolute,
    /// }
    ///
    /// let text = PanTilt { pan: Revolute, tilt: Revolute }.to_mjcf();
    /// assert!(text.contains(r#"<joint name="tilt" type="hinge" axis="0 0 1"/>"#));
    /// // The pan link's twist, as the tilt body's orientation: exactly 90 degrees about x.
    /// assert!(text.contains(r#"<body name="tilt_link" pos="0 0 0.1" euler="0 0 90">"#));
    /// ```
    #[cfg(feature = "std")]
    #[must_use]
    fn to_mjcf(&self) -> std::string::String
    where
        Self: Sized,
    {
        super::export::mjcf(
            &self.model(),
            &Self::JOINT_NAMES,
            super::export::short_name::<Self>(),
        )
    }

    /// The arm with its current values as URDF, which Pinocchio and ROS load and this derive
    /// reads back: links `base`, `JOINT_NAME_link` and `tool`. URDF holds neither armature nor
    /// gravity; the file says in comments what of them it left out.
    #[cfg(feature = "std")]
    #[must_use]
    fn to_urdf(&self) -> std::string::String
    where
        Self: Sized,
    {
        super::export::urdf(
            &self.model(),
            &Self::JOINT_NAMES,
            super::export::short_name::<Self>(),
        )
    }

    /// Every joint configuration that puts the tool at `target`, in closed form, for six-joint
    /// arms of the classes of [`SpatialIk`](super::SpatialIk): each angle in (-pi, pi] or the
    /// representative inside its `range`, solutions outside the ranges dropped.
    ///
    /// # Errors
    /// [`ArmError::NonFinite`] for a NaN or infinite target; [`ArmError::OutOfReach`] saying
    /// what misses and by how much; [`ArmError::BeyondJointRange`] when ranges exclude every
    /// solution; [`ArmError::NoClosedForm`] for arms of other geometries (use
    /// [`inverse_kinematics_near`](Self::inverse_kinematics_near)).
    fn inverse_kinematics(&self, target: &Isometry3<f64>) -> Result<IkSolutions<N>, ArmError>;

    /// Damped-least-squares inverse kinematics from `seed`, for any arm: the 6-D pose error
    /// (position in metres, rotation vector in radians, base coordinates) driven below
    /// `options.tolerance`, within the joints' ranges and `options.limits`.
    ///
    /// # Errors
    /// As [`solve_dls`](crate::kinematics::solve_dls): [`ArmError::NonFinite`],
    /// [`ArmError::OutOfRange`] for bad limits, [`ArmError::NoConvergence`].
    fn inverse_kinematics_near(
        &self,
        target: &Isometry3<f64>,
        seed: &SVector<f64, N>,
        options: &DlsOptions<N>,
    ) -> Result<SVector<f64, N>, ArmError> {
        numeric::inverse_kinematics_near(self, target, seed, options)
    }

    /// The joint torques (forces for slides) that hold the force `force` and the torque
    /// `torque` applied at the tool origin, both in base coordinates: `J^T [f; n]`.
    fn joint_torques(
        &self,
        q: &SVector<f64, N>,
        force: &Vector3<f64>,
        torque: &Vector3<f64>,
    ) -> SVector<f64, N> {
        let mut wrench = SVector::<f64, 6>::zeros();
        wrench.fixed_rows_mut::<3>(0).copy_from(force);
        wrench.fixed_rows_mut::<3>(3).copy_from(torque);
        self.jacobian(q).transpose() * wrench
    }

    /// The force and torque at the tool origin (base coordinates) that the joint torques `tau`
    /// hold, the inverse of [`joint_torques`](Self::joint_torques): for six joints, the solution
    /// of `J^T w = tau`.
    ///
    /// # Errors
    /// [`ArmError::NonFinite`] for NaN or infinite input; [`ArmError::Singular`] where
    /// `|det J|` is below [`SINGULAR_THRESHOLD`](crate::kinematics::SINGULAR_THRESHOLD) times
    /// the product of its columns' norms (Hadamard's bound); [`ArmError::NoClosedForm`] for
    /// arms of other than six joints, whose `J^T w = tau` is not square.
    fn tip_wrench(
        &self,
        q: &SVector<f64, N>,
        tau: &SVector<f64, N>,
    ) -> Result<(Vector3<f64>, Vector3<f64>), ArmError> {
        super::statics::tip_wrench(&self.jacobian(q), q, tau)
    }
}
