//! Controllers that follow a [`Trajectory`]: computed torque and PD with gravity compensation.

use nalgebra::SVector;

use super::error::finite;
use super::{Controller, SimError, Trajectory};
use crate::Dynamics;

/// Computed torque: the model's inverse dynamics along the desired motion corrected by PD
/// feedback, `tau = M(q) (qdd* + kp (q* - q) + kd (qd* - qd)) + h(q, qd)` with the model's M
/// and bias h.
///
/// This is the paper's "open-loop dead-reckoning approach ... modified ... by a small amount
/// of compensating feed-back": with `kp = kd = 0` it is the dead reckoning alone. With an exact
/// model the tracking error obeys `e'' + kd e' + kp e = 0` joint by joint (gains per unit
/// inertia: `kp` in 1/s^2, `kd` in 1/s, the same response on a heavy joint and a light one);
/// with a model that differs from the arm (`model` may be another instance, say without the
/// payload the arm holds) the feedback keeps the error bounded.
///
/// The feedback acts through the model's M, so where the model underestimates a joint's inertia
/// it is softer by that ratio. Measured in `cargo run --example simulate`: 0.5 kg unknown in
/// the gripper of a 0.5 kg, 15 cm hand (model inertia about the joint 0.0037 kg m^2, true
/// 0.0150) leaves computed torque at 20 rad/s with errors up to 0.78 rad, where
/// [`PdGravity`] with absolute gains (20 N m/rad on that joint) keeps 0.076 rad and dead
/// reckoning alone drifts 4 rad away. With the exact model the same run tracks to 2.7e-3 rad.
///
/// # Example
/// ```
/// use planar_arm::prelude::*;
/// use planar_arm::sim::{ComputedTorque, Controller, Quintic, Trajectory};
///
/// #[derive(PlanarArm, Default)]
/// #[arm(gravity = 9.81)]
/// struct Rods {
///     #[arm(length = 1, mass = 1)]
///     upper: Revolute,
///     #[arm(length = 1, mass = 1)]
///     fore: Revolute,
/// }
///
/// let arm = Rods::default();
/// let path = Quintic::rest_to_rest(Vector2::new(0.0, 0.5), Vector2::new(1.0, 0.0), 1.0)?;
/// let mut ct = ComputedTorque::critically_damped(&arm, path, 10.0);
/// // On the path, the torque is the inverse dynamics of the path.
/// let want = path.sample(0.3);
/// let tau = ct.torque(0.3, &want.q, &want.qd);
/// assert!((tau - arm.inverse_dynamics(&want.q, &want.qd, &want.qdd)).norm() < 1e-12);
/// # Ok::<(), planar_arm::sim::SimError>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct ComputedTorque<'m, M: ?Sized, R, const N: usize> {
    /// The model of the arm the controller believes in.
    pub model: &'m M,
    /// The desired motion.
    pub reference: R,
    /// Position gains, 1/s^2.
    pub kp: SVector<f64, N>,
    /// Rate gains, 1/s.
    pub kd: SVector<f64, N>,
}

impl<'m, M: Dynamics<N> + ?Sized, R: Trajectory<N>, const N: usize> ComputedTorque<'m, M, R, N> {
    /// Critically damped error dynamics of natural frequency `omega` (rad/s) on every joint:
    /// `kp = omega^2`, `kd = 2 omega`. `omega = 0` is dead reckoning alone.
    pub fn critically_damped(model: &'m M, reference: R, omega: f64) -> Self {
        Self {
            model,
            reference,
            kp: SVector::from_element(omega * omega),
            kd: SVector::from_element(2.0 * omega),
        }
    }
}

impl<M: Dynamics<N> + ?Sized, R: Trajectory<N>, const N: usize> Controller<N>
    for ComputedTorque<'_, M, R, N>
{
    fn torque(&mut self, t: f64, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> SVector<f64, N> {
        let want = self.reference.sample(t);
        let qdd = want.qdd
            + self.kp.component_mul(&(want.q - q))
            + self.kd.component_mul(&(want.qd - qd));
        self.model.inverse_dynamics(q, qd, &qdd)
    }
}

/// PD feedback with gravity compensation, `tau = g(q) + kp (q* - q) + kd (qd* - qd)`, the
/// model's g: the simplest controller that holds an arm still anywhere, and (Takegaki and
/// Arimoto) globally stable at a set-point whatever the gains, for an exact g. Along a moving
/// reference it lags: it knows nothing of the inertia. The gains are in N m/rad and N m s/rad;
/// see [`fastest_rate`] for the step size they call for.
///
/// # Example
/// ```
/// use planar_arm::prelude::*;
/// use planar_arm::sim::{Controller, PdGravity, Quintic};
///
/// #[derive(PlanarArm, Default)]
/// #[arm(gravity = 9.81)]
/// struct Rods {
///     #[arm(length = 1, mass = 1)]
///     upper: Revolute,
///     #[arm(length = 1, mass = 1)]
///     fore: Revolute,
/// }
///
/// let arm = Rods::default();
/// let hold = Quintic::rest_to_rest(Vector2::new(0.4, 0.2), Vector2::new(0.4, 0.2), 1.0)?;
/// let mut pd = PdGravity::new(&arm, hold, Vector2::new(50.0, 20.0), Vector2::new(10.0, 4.0));
/// let q = Vector2::new(0.4, 0.2);
/// assert_eq!(pd.torque(0.0, &q, &Vector2::zeros()), arm.gravity(&q)); // on target: holds it
/// # Ok::<(), planar_arm::sim::SimError>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct PdGravity<'m, M: ?Sized, R, const N: usize> {
    /// The model of the arm whose gravity is compensated.
    pub model: &'m M,
    /// The desired motion.
    pub reference: R,
    /// Position gains, N m/rad.
    pub kp: SVector<f64, N>,
    /// Rate gains, N m s/rad.
    pub kd: SVector<f64, N>,
}

impl<'m, M: Dynamics<N> + ?Sized, R: Trajectory<N>, const N: usize> PdGravity<'m, M, R, N> {
    /// The controller with gains `kp` (N m/rad) and `kd` (N m s/rad).
    pub fn new(model: &'m M, reference: R, kp: SVector<f64, N>, kd: SVector<f64, N>) -> Self {
        Self {
            model,
            reference,
            kp,
            kd,
        }
    }
}

impl<M: Dynamics<N> + ?Sized, R: Trajectory<N>, const N: usize> Controller<N>
    for PdGravity<'_, M, R, N>
{
    fn torque(&mut self, t: f64, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> SVector<f64, N> {
        let want = self.reference.sample(t);
        self.model.gravity(q)
            + self.kp.component_mul(&(want.q - q))
            + self.kd.component_mul(&(want.qd - qd))
    }
}

/// An upper bound on the fastest rate (1/s) of the arm at `q` under joint-space PD gains `kp`
/// (N m/rad) and `kd` (N m s/rad): `mu_d + sqrt(mu_p)`, with `mu_p` and `mu_d` the largest
/// eigenvalues of `kp` and `kd` relative to M(q) (of `L^-1 K L^-T`, `M = L L^T`). Every root
/// `s` of `det(M s^2 + kd s + kp) = 0` has `|s|` at most this. An explicit step `dt` wants
/// `dt * rate` below about 0.1 for accuracy and 2.8 (RK4) or 2 (semi-implicit Euler) for
/// stability. For [`ComputedTorque`], whose gains are per unit inertia, pass `kp` and `kd`
/// multiplied by M's diagonal, or use `sqrt(kp) + kd` directly.
///
/// # Errors
/// [`SimError::NonFinite`] for non-finite input; [`SimError::BadArgument`] when M(q) is not
/// positive definite (a non-physical run-time parameter) or a gain is negative.
///
/// # Example
/// ```
/// use planar_arm::prelude::*;
/// use planar_arm::sim::fastest_rate;
///
/// #[derive(PlanarArm, Default)]
/// #[arm(gravity = 9.81)]
/// struct Pendulum {
///     #[arm(length = 1, mass = 3)]
///     rod: Revolute,
/// }
///
/// // Inertia about the joint m l^2 / 3 = 1 kg m^2: the rate is kd + sqrt(kp).
/// let q = SVector::<f64, 1>::zeros();
/// let rate = fastest_rate(&Pendulum::default(), &q, &SVector::from_element(100.0), &SVector::from_element(5.0))?;
/// assert!((rate - 15.0).abs() < 1e-12);
/// # Ok::<(), planar_arm::sim::SimError>(())
/// ```
pub fn fastest_rate<A: Dynamics<N> + ?Sized, const N: usize>(
    arm: &A,
    q: &SVector<f64, N>,
    kp: &SVector<f64, N>,
    kd: &SVector<f64, N>,
) -> Result<f64, SimError> {
    finite(q, "q")?;
    finite(kp, "kp")?;
    finite(kd, "kd")?;
    if let Some(k) = kp.iter().chain(kd.iter()).find(|k| **k < 0.0) {
        return Err(SimError::BadArgument {
            argument: "gain",
            value: *k,
        });
    }
    let mass = arm.mass_matrix(q);
    let Some(chol) = mass.cholesky() else {
        return Err(SimError::BadArgument {
            argument: "mass matrix (not positive definite)",
            value: mass.trace(),
        });
    };
    let largest = |k: &SVector<f64, N>| -> f64 {
        // L^-1 diag(k) L^-T, symmetric positive semidefinite.
        let linv = chol
            .l()
            .try_inverse()
            .unwrap_or_else(nalgebra::SMatrix::zeros);
        let s = linv * nalgebra::SMatrix::from_diagonal(k) * linv.transpose();
        let s = (s + s.transpose()) * 0.5;
        // Power iteration: the matrix is symmetric positive semidefinite, so the Rayleigh
        // quotient rises to the largest eigenvalue; 200 rounds are plenty for N of a few tens.
        let mut x = SVector::<f64, N>::from_fn(|i, _| 1.0 + 0.1 * i as f64);
        let mut value = 0.0_f64;
        for _ in 0..200 {
            let y = s * x;
            let norm = y.norm();
            if norm.is_nan() || norm <= 0.0 {
                return 0.0;
            }
            value = x.dot(&y) / x.norm_squared();
            x = y / norm;
        }
        value.max(0.0)
    };
    Ok(largest(kd) + num_traits::Float::sqrt(largest(kp)))
}
