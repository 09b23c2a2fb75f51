//! The trait `#[derive(PlanarArm)]` implements: the dynamics, kinematics and statics of a
//! planar serial arm.

use nalgebra::{Isometry2, Point2, SMatrix, SVector, Vector2};

use crate::kinematics::{self, DlsOptions, IkTarget, Workspace};
use crate::{exact, ArmError, Dynamics, Link, Model, Real};

/// A planar serial arm of `N` links, revolute or prismatic, whose dynamics, kinematics and
/// statics were derived at compile time by `#[derive(PlanarArm)]`.
///
/// Conventions: `q[0]` is link 1's angle from +x, `q[i]` (i > 0) is link i+1's angle relative to
/// link i, or for a [`Prismatic`](crate::Prismatic) joint its displacement along the previous
/// link (metres, and its entry of `tau` a force); all zeros is the arm stretched along +x.
/// Gravity acts along -y. The equations of motion are `tau = M(q) qdd + c(q, qd) + g(q) + f(qd)`,
/// f the joint friction.
///
/// # Numeric range
///
/// No method panics, whatever its input. For an arm with positive masses every method returns
/// finite values for every state with `|q|, |qd|, |qdd| <= 1e6` and `|tau| <= 1e12`;
/// `forward_dynamics` in particular stays finite (M is positive definite by construction and
/// its factorisation is guarded against rounding). Beyond that range the methods are IEEE
/// arithmetic on the exact formulas: a torque that exceeds `f64::MAX` (velocity terms grow as
/// `qd^2`) is infinite or NaN (NaN where two overflowed terms of opposite sign meet, as at
/// `qd = 1e154`). The infallible methods pass NaN through; use the `try_` methods, which
/// answer NaN or infinite input, and an overflowed result, with [`ArmError::NonFinite`].
///
/// # Run-time parameters out of range
///
/// A value written `self.NAME` is read from its field at every call and cannot be checked at
/// compile time. Nothing panics whatever it holds, but the promises above hold only for a
/// physical arm: positive lengths and masses, non-negative inertias, armatures, damping and
/// frictionloss. With a non-physical value (a negative mass, say) M may be indefinite and
/// `forward_dynamics` meaningless (finite wherever the pivot floor of its factorisation
/// applies); a NaN parameter makes the results that depend on it NaN, which the `try_`
/// methods report as [`ArmError::NonFinite`] with argument `"result"`. Check identified or
/// loaded values before use; [`Model::check`] does.
pub trait PlanarArm<const N: usize>: Dynamics<N> {
    /// The exact symbolic result the generated code evaluates. Coefficients that involve
    /// run-time parameters carry them by name ([`exact::Term::params`]).
    const EXACT: exact::Derivation<N>;

    /// The joints' names, base first, in the order of `q`: the link fields' names.
    const JOINT_NAMES: [&'static str; N];

    /// The arm's numeric description now: links, gravity and payload, with every run-time
    /// parameter read from its field. This is what the [`reference`](mod@crate::reference)
    /// implementations and a simulator take to model the same arm.
    fn model(&self) -> Model<N>;

    /// The arm with its current values as MJCF, which MuJoCo loads and
    /// `#[derive(SpatialArm)]` reads back to the same dynamics: the plane is MuJoCo's x-y
    /// plane, each hinge turns about `+z`, each slide moves along its link's `x`, gravity is
    /// `0 -g 0`, and `q` is `qpos`. The link's moment `inertia` is its `izz`; the
    /// out-of-plane moments, which a planar motion never feels, are written equal to it, so
    /// that the tensor meets the triangle inequality MuJoCo requires (as its `balanceinertia`
    /// would make a planar rod's). See [`Model::to_spatial`] for the spatial arm it writes.
    ///
    /// ```
    /// use planar_arm::prelude::*;
    ///
    /// #[derive(PlanarArm, Default)]
    /// #[arm(gravity = 9.81)]
    /// struct Pendulum {
    ///     #[arm(length = 0.5, mass = 1.0, damping = 0.1)]
    ///     rod: Revolute,
    /// }
    ///
    /// let text = Pendulum::default().to_mjcf();
    /// assert!(text.contains(r#"<option gravity="0 -9.81 0"/>"#));
    /// assert!(text.contains(r#"<joint name="rod" type="hinge" axis="0 0 1" damping="0.1"/>"#));
    /// ```
    #[cfg(feature = "std")]
    #[must_use]
    fn to_mjcf(&self) -> std::string::String
    where
        Self: Sized,
    {
        crate::spatial::export::mjcf(
            &self.model().to_spatial(),
            &Self::JOINT_NAMES,
            crate::spatial::export::short_name::<Self>(),
        )
    }

    /// The arm with its current values as URDF (the plane as in [`to_mjcf`](Self::to_mjcf)),
    /// which Pinocchio and ROS load; URDF holds neither armature nor a gravity of its own, and
    /// the file says which of them it left out.
    #[cfg(feature = "std")]
    #[must_use]
    fn to_urdf(&self) -> std::string::String
    where
        Self: Sized,
    {
        crate::spatial::export::urdf(
            &self.model().to_spatial(),
            &Self::JOINT_NAMES,
            crate::spatial::export::short_name::<Self>(),
        )
    }

    /// The numeric link parameters, base first (`self.model().links`).
    fn links(&self) -> [Link; N] {
        self.model().links
    }

    /// Tip position and the orientation of the last link.
    fn tip_pose(&self, q: &SVector<f64, N>) -> Isometry2<f64>;
    /// The 3 x N Jacobian: rows are d/dt of tip x, tip y and the last link's angle.
    fn jacobian<T: Real>(&self, q: &SVector<T, N>) -> SMatrix<T, 3, N>;
    /// Position of each joint (each link's frame origin), joint 1 at the origin; a prismatic
    /// joint's is its slid carriage, so a sliding joint 1 sits at `(q1, 0)`.
    fn joint_positions<T: Real>(&self, q: &SVector<T, N>) -> [Point2<T>; N];
    /// The tip in polar form (r, theta); r does not depend on q1 when joint 1 is revolute.
    fn tip_polar(&self, q: &SVector<f64, N>) -> (f64, f64);
    /// Motor torques that make the tip exert force `force` and torque `torque` on what it
    /// holds: tau = J^T w (gravity is separate, in [`gravity`](crate::Dynamics::gravity)).
    fn joint_torques(
        &self,
        q: &SVector<f64, N>,
        force: &Vector2<f64>,
        torque: f64,
    ) -> SVector<f64, N>;

    /// The reachable region of the tip ([`Workspace::of_links`]): for revolute links without
    /// ranges the annulus with inner radius `max(0, 2 max l - sum l)` and outer radius
    /// `sum l`; exact regions for the polar arm, a slider carrying one or two links and ranged
    /// hinges; a bounding annulus otherwise ([`Workspace::is_exact`] says which).
    fn workspace(&self) -> Workspace {
        Workspace::of_links(&self.links())
    }

    /// The manipulability measure `sqrt(det(J J^T))` of the task rows (tip position for
    /// `N <= 2`, position and orientation beyond); zero at a singular configuration.
    fn manipulability(&self, q: &SVector<f64, N>) -> f64 {
        kinematics::manipulability(&self.jacobian(q))
    }

    /// Whether the configuration is singular: manipulability below `threshold` (in the units
    /// of the measure, for example m^2 for two links).
    fn is_singular(&self, q: &SVector<f64, N>, threshold: f64) -> bool {
        kinematics::is_singular(&self.jacobian(q), threshold)
    }

    /// Damped-least-squares inverse kinematics on the generated Jacobian: the configuration
    /// reached from `seed` (so the one nearest it, in practice), within the joints' ranges
    /// (`#[arm(range = ...)]`) and the joint limits of `options` if it has any (both, where
    /// both are given).
    ///
    /// The target is first checked against the work-space ([`kinematics::reachable_target`]:
    /// the annulus for a position, the wrist's annulus for a pose); one within the reach
    /// tolerance outside it is moved onto the boundary, where the solver then converges.
    ///
    /// # Errors
    /// [`ArmError::NonFinite`] for NaN or infinite input, [`ArmError::Unreachable`] for a target
    /// outside the work-space, [`ArmError::OutOfRange`] for joint limits with `lower > upper`,
    /// [`ArmError::NoConvergence`] when the target is not reached within
    /// `options.max_iterations` (or only outside the joint limits).
    fn inverse_kinematics_near(
        &self,
        target: &IkTarget,
        seed: &SVector<f64, N>,
        options: &DlsOptions<N>,
    ) -> Result<SVector<f64, N>, ArmError> {
        kinematics::inverse_kinematics_near(self, target, seed, options)
    }

    /// Every joint and the tip at `q` in one call, `N + 1` points from the base to the tip,
    /// for drawing the arm ([`kinematics::Skeleton::points`]).
    fn skeleton(&self, q: &SVector<f64, N>) -> kinematics::Skeleton<N> {
        kinematics::Skeleton::of(self, q)
    }
}
