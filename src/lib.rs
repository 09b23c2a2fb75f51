//! Crate guide: written at the end (see README.md for now).
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod error;
pub mod exact;
pub mod kinematics;
mod link;
pub mod reference;

#[doc(hidden)]
pub mod __private;

pub use error::ArmError;
pub use link::{Link, Revolute};
pub use nalgebra;
pub use planar_arm_core as symbolic;
pub use planar_arm_derive::PlanarArm;

use kinematics::{DlsOptions, IkTarget, Workspace};
use nalgebra::{Isometry2, Point2, SMatrix, SVector, Vector2};

/// Everything a user of a derived arm needs: `use planar_arm::prelude::*;`.
pub mod prelude {
    pub use crate::kinematics::{
        ClosedFormIk, DexterousWorkspace, DlsOptions, IkTarget, TipForce, TipWrench, Workspace,
    };
    pub use crate::{ArmError, Link, PlanarArm, Revolute};
    pub use nalgebra::{Isometry2, Point2, SMatrix, SVector, Vector2};
}

/// A planar serial arm of `N` revolute links whose dynamics, kinematics and statics were
/// derived at compile time by `#[derive(PlanarArm)]`.
///
/// Conventions: `q[0]` is link 1's angle from +x, `q[i]` (i > 0) is link i+1's angle relative to
/// link i; all zeros is the arm stretched along +x. Gravity acts along -y. The equations of
/// motion are `tau = M(q) qdd + c(q, qd) + g(q)`.
pub trait PlanarArm<const N: usize> {
    /// The numeric link parameters, base first.
    const LINKS: [Link; N];
    /// Magnitude of gravity along -y, m/s^2.
    const GRAVITY: f64;
    /// The exact symbolic result the generated code evaluates.
    const EXACT: exact::Derivation<N>;

    /// The mass (sensitivity) matrix M(q): symmetric positive definite.
    fn mass_matrix(&self, q: &SVector<f64, N>) -> SMatrix<f64, N, N>;
    /// The velocity-product (Coriolis and centrifugal) torques c(q, qd).
    fn coriolis(&self, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> SVector<f64, N>;
    /// The Coriolis matrix C(q, qd) built from Christoffel symbols: `C qd = c` and `Mdot - 2C` is skew.
    fn coriolis_matrix(&self, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> SMatrix<f64, N, N>;
    /// The torques that hold the arm against gravity, g(q) = dV/dq.
    fn gravity(&self, q: &SVector<f64, N>) -> SVector<f64, N>;
    /// The joint torques tau = M qdd + c + g.
    fn inverse_dynamics(
        &self,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        qdd: &SVector<f64, N>,
    ) -> SVector<f64, N>;
    /// The joint accelerations qdd that solve M qdd = tau - c - g.
    fn forward_dynamics(
        &self,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        tau: &SVector<f64, N>,
    ) -> SVector<f64, N>;
    /// Kinetic energy, J.
    fn kinetic_energy(&self, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> f64;
    /// Potential energy, J, measured from y = 0 at the base.
    fn potential_energy(&self, q: &SVector<f64, N>) -> f64;
    /// Tip position and the orientation of the last link.
    fn tip_pose(&self, q: &SVector<f64, N>) -> Isometry2<f64>;
    /// The 3 x N Jacobian: rows are d/dt of tip x, tip y and the last link's angle.
    fn jacobian(&self, q: &SVector<f64, N>) -> SMatrix<f64, 3, N>;
    /// Position of each joint, joint 1 at the origin.
    fn joint_positions(&self, q: &SVector<f64, N>) -> [Point2<f64>; N];
    /// The tip in polar form (r, theta); r depends on q2..qN only.
    fn tip_polar(&self, q: &SVector<f64, N>) -> (f64, f64);
    /// Motor torques that make the tip exert force `force` and torque `torque` on what it
    /// holds: tau = J^T w (gravity is separate, in [`gravity`](Self::gravity)).
    fn joint_torques(
        &self,
        q: &SVector<f64, N>,
        force: &Vector2<f64>,
        torque: f64,
    ) -> SVector<f64, N>;

    /// The reachable region: an annulus with inner radius `max(0, 2 max l - sum l)` and outer
    /// radius `sum l`.
    fn workspace(&self) -> Workspace {
        let lengths: [f64; N] = core::array::from_fn(|i| Self::LINKS[i].length);
        Workspace::of_lengths(&lengths)
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
    /// reached from `seed` (so the one nearest it, in practice).
    ///
    /// # Errors
    /// [`ArmError::NonFinite`] for NaN or infinite input, [`ArmError::NoConvergence`] when the
    /// target is not reached within `options.max_iterations`.
    fn inverse_kinematics_near(
        &self,
        target: &IkTarget,
        seed: &SVector<f64, N>,
        options: &DlsOptions,
    ) -> Result<SVector<f64, N>, ArmError> {
        kinematics::solve_dls(
            |q| self.tip_pose(q),
            |q| self.jacobian(q),
            target,
            seed,
            options,
        )
    }

    /// [`forward_dynamics`](Self::forward_dynamics) for input that may be bad: NaN or infinite
    /// states give an `Err` instead of NaN accelerations.
    ///
    /// # Errors
    /// [`ArmError::NonFinite`] naming the first argument that holds NaN or an infinity, or
    /// `"result"` when finite input overflowed.
    fn try_forward_dynamics(
        &self,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        tau: &SVector<f64, N>,
    ) -> Result<SVector<f64, N>, ArmError> {
        finite(q, "q")?;
        finite(qd, "qd")?;
        finite(tau, "tau")?;
        let qdd = self.forward_dynamics(q, qd, tau);
        finite(&qdd, "result")?;
        Ok(qdd)
    }

    /// [`inverse_dynamics`](Self::inverse_dynamics) for input that may be bad.
    ///
    /// # Errors
    /// [`ArmError::NonFinite`] as for [`try_forward_dynamics`](Self::try_forward_dynamics).
    fn try_inverse_dynamics(
        &self,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        qdd: &SVector<f64, N>,
    ) -> Result<SVector<f64, N>, ArmError> {
        finite(q, "q")?;
        finite(qd, "qd")?;
        finite(qdd, "qdd")?;
        let tau = self.inverse_dynamics(q, qd, qdd);
        finite(&tau, "result")?;
        Ok(tau)
    }
}

fn finite<const N: usize>(v: &SVector<f64, N>, argument: &'static str) -> Result<(), ArmError> {
    if v.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(ArmError::NonFinite { argument })
    }
}
