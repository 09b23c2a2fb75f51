//! The trait `#[derive(PlanarArm)]` implements: the dynamics, kinematics and statics of a
//! planar serial arm.

use nalgebra::{Isometry2, Point2, SMatrix, SVector, Vector2};

use crate::kinematics::{self, DlsOptions, IkTarget, Workspace};
use crate::{exact, mass_inverse, ArmError, Frozen, Jet, Link, Model, Real};

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
pub trait PlanarArm<const N: usize> {
    /// The exact symbolic result the generated code evaluates. Coefficients that involve
    /// run-time parameters carry them by name ([`exact::Term::params`]).
    const EXACT: exact::Derivation<N>;

    /// The arm's numeric description now: links, gravity and payload, with every run-time
    /// parameter read from its field. This is what the [`reference`](mod@crate::reference)
    /// implementations and a simulator take to model the same arm.
    fn model(&self) -> Model<N>;

    /// The numeric link parameters, base first (`self.model().links`).
    fn links(&self) -> [Link; N] {
        self.model().links
    }

    /// The mass (sensitivity) matrix M(q): symmetric positive definite.
    fn mass_matrix<T: Real>(&self, q: &SVector<T, N>) -> SMatrix<T, N, N>;
    /// The velocity-product (Coriolis and centrifugal) torques c(q, qd).
    fn coriolis<T: Real>(&self, q: &SVector<T, N>, qd: &SVector<T, N>) -> SVector<T, N>;
    /// The Coriolis matrix C(q, qd) built from Christoffel symbols: `C qd = c` and `Mdot - 2C` is skew.
    fn coriolis_matrix<T: Real>(&self, q: &SVector<T, N>, qd: &SVector<T, N>) -> SMatrix<T, N, N>;
    /// The torques that hold the arm against gravity, g(q) = dV/dq.
    fn gravity<T: Real>(&self, q: &SVector<T, N>) -> SVector<T, N>;
    /// The joint friction torques f(qd): viscous `damping qd_i` plus Coulomb
    /// `frictionloss sign(qd_i)` (MuJoCo's `damping` and `frictionloss`), with `sign(0) = 0`.
    /// The Coulomb term is discontinuous at `qd_i = 0`; an integrator stepping through zero
    /// rate chatters around it (a stiction model is not part of this crate).
    fn friction<T: Real>(&self, qd: &SVector<T, N>) -> SVector<T, N>;
    /// The bias h(q, qd) = c + g + f: every torque but the inertial one, so that
    /// `inverse_dynamics(q, qd, qdd) = mass_matrix(q) * qdd + bias(q, qd)` (Pinocchio's
    /// `nonLinearEffects`; MuJoCo's `qfrc_bias` with the passive joint friction added).
    fn bias<T: Real>(&self, q: &SVector<T, N>, qd: &SVector<T, N>) -> SVector<T, N>;
    /// `(mass_matrix(q), bias(q, qd))` in one pass that shares the trigonometry and common
    /// subexpressions: what a computed-torque or operational-space controller needs every cycle.
    fn mass_matrix_and_bias<T: Real>(
        &self,
        q: &SVector<T, N>,
        qd: &SVector<T, N>,
    ) -> (SMatrix<T, N, N>, SVector<T, N>);
    /// The joint torques tau = M qdd + c + g + f.
    fn inverse_dynamics<T: Real>(
        &self,
        q: &SVector<T, N>,
        qd: &SVector<T, N>,
        qdd: &SVector<T, N>,
    ) -> SVector<T, N>;
    /// The joint accelerations qdd that solve M qdd = tau - c - g - f.
    ///
    /// With one joint, or two whose mass matrix has no run-time parameter, in closed form
    /// (Cramer's rule, on the exact determinant) on M, c and g as
    /// [`mass_matrix`](Self::mass_matrix), [`coriolis`](Self::coriolis) and
    /// [`gravity`](Self::gravity) return them; otherwise (from three joints, and two with
    /// parameters in M, whose determinant, a product of two of them, could overflow) M and
    /// h = c + g + f as
    /// [`mass_matrix_and_bias`](Self::mass_matrix_and_bias) returns them, solved by an
    /// `L D L^T` factorisation whose pivots are floored at 2^-52 times a bound on `M_ii`, so an
    /// ill-conditioned M gives finite accelerations. The method's docs on your arm give its
    /// operation count.
    fn forward_dynamics<T: Real>(
        &self,
        q: &SVector<T, N>,
        qd: &SVector<T, N>,
        tau: &SVector<T, N>,
    ) -> SVector<T, N>;
    /// The partial derivatives of [`inverse_dynamics`](Self::inverse_dynamics),
    /// `(dtau/dq, dtau/dqd)`, N x N each (`dtau/dqdd` is [`mass_matrix`](Self::mass_matrix)),
    /// as Pinocchio's `computeRNEADerivatives`.
    ///
    /// Exact to rounding. For arms whose derivative program stays small (about 4,000
    /// operations, every arm up to 10 links at least) the derive emits it: the inverse dynamics'
    /// straight-line program differentiated at compile time, its operation count in the
    /// method's docs. For larger arms this default evaluates the generated inverse dynamics in
    /// [`Jet<N>`](Jet) ([`Jet::inverse_dynamics_derivatives`]). Run-time parameters, armature,
    /// damping and payload are included. Coulomb friction `frictionloss sign(qd_i)` jumps at
    /// `qd_i = 0` and has no derivative there; it contributes 0 to `dtau/dqd` everywhere (its
    /// derivative away from the jump).
    fn inverse_dynamics_derivatives(
        &self,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        qdd: &SVector<f64, N>,
    ) -> (SMatrix<f64, N, N>, SMatrix<f64, N, N>) {
        Jet::inverse_dynamics_derivatives(self, q, qd, qdd)
    }

    /// The partial derivatives of [`forward_dynamics`](Self::forward_dynamics),
    /// `(dqdd/dq, dqdd/dqd, dqdd/dtau)`, N x N each, as Pinocchio's `computeABADerivatives`:
    /// with `qdd = forward_dynamics(q, qd, tau)`, `dqdd/dq = -M^-1 dtau/dq`,
    /// `dqdd/dqd = -M^-1 dtau/dqd` (from [`inverse_dynamics_derivatives`](Self::inverse_dynamics_derivatives)
    /// at `qdd`) and `dqdd/dtau = M^-1`. Coulomb friction as there.
    ///
    /// For arms of up to five links the derive emits this as one straight-line program that
    /// shares the trigonometry, M and its factorisation (guarded by the pivot floors of
    /// `forward_dynamics`, so finite wherever `forward_dynamics` is); its operation count is in
    /// the method's docs. For larger arms this default computes it from the methods above and
    /// a fixed-size Cholesky factorisation of M (no allocation; 1.4x the time of the emitted
    /// program at six links, measured in docs/performance.md, and none of its compile time),
    /// NaN everywhere if that fails (only with NaN or infinite input). NaN input gives NaN
    /// output either way, never a panic.
    fn forward_dynamics_derivatives(
        &self,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        tau: &SVector<f64, N>,
    ) -> (SMatrix<f64, N, N>, SMatrix<f64, N, N>, SMatrix<f64, N, N>) {
        let qdd = self.forward_dynamics(q, qd, tau);
        let (dq, dqd) = self.inverse_dynamics_derivatives(q, qd, &qdd);
        mass_inverse::inverse_products(&self.mass_matrix(q), &dq, &dqd).unwrap_or_else(|| {
            let nan = SMatrix::from_element(f64::NAN);
            (nan, nan, nan)
        })
    }

    /// Kinetic energy, J: the links, the payload and the rotors (`armature qd_i^2 / 2`).
    fn kinetic_energy<T: Real>(&self, q: &SVector<T, N>, qd: &SVector<T, N>) -> T;
    /// Potential energy, J, measured from y = 0 at the base.
    fn potential_energy<T: Real>(&self, q: &SVector<T, N>) -> T;
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
    /// holds: tau = J^T w (gravity is separate, in [`gravity`](Self::gravity)).
    fn joint_torques(
        &self,
        q: &SVector<f64, N>,
        force: &Vector2<f64>,
        torque: f64,
    ) -> SVector<f64, N>;

    /// A view that evaluates the parameter-only part of the dynamics once and reuses it on every
    /// call, for an arm with run-time parameters whose values hold still for many calls (a
    /// control loop between payload changes). The arm stays borrowed while the view lives, so
    /// its values cannot go stale. See [`Frozen`].
    fn freeze(&self) -> Frozen<'_, Self, N> {
        Frozen::new(self)
    }

    /// The parameter-only values [`Frozen`] holds (empty for all-literal arms).
    #[doc(hidden)]
    type __Frozen: Copy + Default + core::fmt::Debug;
    #[doc(hidden)]
    fn __freeze(&self) -> Self::__Frozen {
        Self::__Frozen::default()
    }
    #[doc(hidden)]
    fn __mass_matrix_frozen<T: Real>(
        &self,
        _: &Self::__Frozen,
        q: &SVector<T, N>,
    ) -> SMatrix<T, N, N> {
        self.mass_matrix(q)
    }
    #[doc(hidden)]
    fn __bias_frozen<T: Real>(
        &self,
        _: &Self::__Frozen,
        q: &SVector<T, N>,
        qd: &SVector<T, N>,
    ) -> SVector<T, N> {
        self.bias(q, qd)
    }
    #[doc(hidden)]
    fn __mass_matrix_and_bias_frozen<T: Real>(
        &self,
        _: &Self::__Frozen,
        q: &SVector<T, N>,
        qd: &SVector<T, N>,
    ) -> (SMatrix<T, N, N>, SVector<T, N>) {
        self.mass_matrix_and_bias(q, qd)
    }
    #[doc(hidden)]
    fn __inverse_dynamics_frozen<T: Real>(
        &self,
        _: &Self::__Frozen,
        q: &SVector<T, N>,
        qd: &SVector<T, N>,
        qdd: &SVector<T, N>,
    ) -> SVector<T, N> {
        self.inverse_dynamics(q, qd, qdd)
    }
    #[doc(hidden)]
    fn __forward_dynamics_frozen<T: Real>(
        &self,
        _: &Self::__Frozen,
        q: &SVector<T, N>,
        qd: &SVector<T, N>,
        tau: &SVector<T, N>,
    ) -> SVector<T, N> {
        self.forward_dynamics(q, qd, tau)
    }

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

/// `Err(NonFinite { argument })` if `v` holds NaN or an infinity.
pub(crate) fn finite<const N: usize>(
    v: &SVector<f64, N>,
    argument: &'static str,
) -> Result<(), ArmError> {
    if v.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(ArmError::NonFinite { argument })
    }
}
