//! Fixed-step integrators of `M(q) qdd + c + g + f = tau` with the torque held over the step.

use nalgebra::SVector;

use super::error::{finite, positive};
use super::SimError;
use crate::{Dynamics, Jet};

/// A fixed-step integrator: advances `(q, qd)` by `dt` with the joint torque `tau` held
/// constant over the step (a zero-order hold, what a digital controller applies).
///
/// Implementations allocate nothing and check their input: `dt` must be positive and finite
/// ([`SimError::BadArgument`]), and a non-finite result ([`SimError::NonFinite`], with
/// `t = NaN`: the simulation loop fills in the time) is an error rather than NaN carried on.
pub trait Integrator {
    /// One step from `(q, qd)`: the state `dt` later.
    ///
    /// # Errors
    /// [`SimError::BadArgument`] for a `dt` that is not positive and finite,
    /// [`SimError::NonFinite`] for NaN or infinite input or result, and for the implicit
    /// integrators [`SimError::NoConvergence`].
    fn step<A: Dynamics<N> + ?Sized, const N: usize>(
        &self,
        arm: &A,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        tau: &SVector<f64, N>,
        dt: f64,
    ) -> Result<(SVector<f64, N>, SVector<f64, N>), SimError>;
}

/// Checks the input every integrator shares.
fn check<const N: usize>(
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    tau: &SVector<f64, N>,
    dt: f64,
) -> Result<(), SimError> {
    positive(dt, "dt")?;
    finite(q, "q")?;
    finite(qd, "qd")?;
    finite(tau, "tau")
}

/// Checks the output.
fn done<const N: usize>(
    q: SVector<f64, N>,
    qd: SVector<f64, N>,
) -> Result<(SVector<f64, N>, SVector<f64, N>), SimError> {
    finite(&q, "q")?;
    finite(&qd, "qd")?;
    Ok((q, qd))
}

/// The classical fourth-order Runge-Kutta method on `(q, qd)`: four forward-dynamics
/// evaluations per step, local error O(dt^5), global O(dt^4). Not symplectic: the energy of a
/// free arm drifts, by O(dt^4) per unit time.
///
/// # Example
/// ```
/// use planar_arm::prelude::*;
/// use planar_arm::sim::{Integrator, Rk4};
///
/// #[derive(PlanarArm, Default)]
/// #[arm(gravity = 9.81)]
/// struct Pendulum {
///     #[arm(length = 1, mass = 1)]
///     rod: Revolute,
/// }
///
/// let arm = Pendulum::default();
/// let (mut q, mut qd) = (SVector::<f64, 1>::new(0.5), SVector::<f64, 1>::zeros());
/// let e0 = arm.kinetic_energy(&q, &qd) + arm.potential_energy(&q);
/// for _ in 0..1000 {
///     (q, qd) = Rk4.step(&arm, &q, &qd, &SVector::zeros(), 1e-3)?;
/// }
/// let e1 = arm.kinetic_energy(&q, &qd) + arm.potential_energy(&q);
/// assert!((e1 - e0).abs() < 1e-10);
/// assert!(Rk4.step(&arm, &q, &qd, &SVector::zeros(), 0.0).is_err());
/// # Ok::<(), planar_arm::sim::SimError>(())
/// ```
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Rk4;

impl Integrator for Rk4 {
    fn step<A: Dynamics<N> + ?Sized, const N: usize>(
        &self,
        arm: &A,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        tau: &SVector<f64, N>,
        dt: f64,
    ) -> Result<(SVector<f64, N>, SVector<f64, N>), SimError> {
        check(q, qd, tau, dt)?;
        let h = 0.5 * dt;
        let a1 = arm.forward_dynamics(q, qd, tau);
        let (q2, v2) = (q + qd * h, qd + a1 * h);
        let a2 = arm.forward_dynamics(&q2, &v2, tau);
        let (q3, v3) = (q + v2 * h, qd + a2 * h);
        let a3 = arm.forward_dynamics(&q3, &v3, tau);
        let (q4, v4) = (q + v3 * dt, qd + a3 * dt);
        let a4 = arm.forward_dynamics(&q4, &v4, tau);
        let sixth = dt / 6.0;
        done(
            q + (qd + v2 * 2.0 + v3 * 2.0 + v4) * sixth,
            qd + (a1 + a2 * 2.0 + a3 * 2.0 + a4) * sixth,
        )
    }
}

/// Semi-implicit (symplectic) Euler in the joint rates: `qd += dt qdd(q, qd)`, then
/// `q += dt qd` with the new rate. One forward-dynamics evaluation per step, first order
/// (measured: 0.94-0.97 on the paper's rods, `tests/sim.rs`).
///
/// For a mass matrix that does not depend on q (one link, or a Cartesian robot) this is the
/// symplectic Euler method and the energy error stays bounded. An arm's M(q) makes the
/// Hamiltonian non-separable, and in the rates `qd` (rather than the momenta `M(q) qd`) the
/// step is no longer symplectic: the energy error is O(dt) and drifts (on the paper's two rods
/// at 10 ms, from 0.27 J in the first 10 s to 7.4 J by 100 s, of a 4.5 J swing). It is here
/// because it is what many game and robot simulators run; use it where one evaluation per step
/// matters more than accuracy.
///
/// # Example
/// ```
/// use planar_arm::prelude::*;
/// use planar_arm::sim::{Integrator, SemiImplicitEuler};
///
/// #[derive(PlanarArm, Default)]
/// #[arm(gravity = 9.81)]
/// struct Pendulum {
///     #[arm(length = 1, mass = 1)]
///     rod: Revolute,
/// }
///
/// // One link: M is constant, the method is symplectic and the energy error stays small.
/// let arm = Pendulum::default();
/// let (mut q, mut qd) = (SVector::<f64, 1>::new(0.5), SVector::<f64, 1>::zeros());
/// let e0 = arm.kinetic_energy(&q, &qd) + arm.potential_energy(&q);
/// let mut worst = 0.0_f64;
/// for _ in 0..100_000 {
///     (q, qd) = SemiImplicitEuler.step(&arm, &q, &qd, &SVector::zeros(), 1e-3)?;
///     worst = worst.max((arm.kinetic_energy(&q, &qd) + arm.potential_energy(&q) - e0).abs());
/// }
/// assert!(worst < 1e-2 * e0.abs());
/// # Ok::<(), planar_arm::sim::SimError>(())
/// ```
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct SemiImplicitEuler;

impl Integrator for SemiImplicitEuler {
    fn step<A: Dynamics<N> + ?Sized, const N: usize>(
        &self,
        arm: &A,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        tau: &SVector<f64, N>,
        dt: f64,
    ) -> Result<(SVector<f64, N>, SVector<f64, N>), SimError> {
        check(q, qd, tau, dt)?;
        let v = qd + arm.forward_dynamics(q, qd, tau) * dt;
        done(q + v * dt, v)
    }
}

/// The variational integrator of the midpoint discrete Lagrangian
/// `L_d(q0, q1) = dt L((q0 + q1) / 2, (q1 - q0) / dt)`, with the torque and the friction
/// entering by the discrete Lagrange-d'Alembert principle (half a step's impulse at each end).
///
/// The discrete Euler-Lagrange equations give, for the midpoint rate `v = (q1 - q0) / dt` at
/// `qm = q0 + v dt / 2`,
///
/// ```text
/// M(qm) v = p0 + dt/2 (C(qm, v)^T v - g(qm) + tau - f(v)),     p1 = 2 M(qm) v - p0
/// ```
///
/// with `p = M(q) qd` the joint momenta and `C^T v = dT/dq` (from the generated Coriolis
/// matrix: `Mdot = C + C^T`). The equation for `v` is solved by fixed-point iteration from
/// `v = qd0`, to `tolerance` (rad/s, relative to `1 + |v|`) or to the rounding floor (the
/// change stops shrinking below `1e-10 (1 + |v|)`). The map `(q0, p0) -> (q1, p1)` is
/// symplectic and symmetric, second order: the energy error of a free arm oscillates at O(dt^2)
/// and does not drift, however long the run (until round-off, which random-walks).
///
/// Cost: each iteration evaluates C, g and the friction at the midpoint and solves with M
/// there (through the generated forward dynamics at rest, one more g), and the step evaluates M
/// twice more and solves once more (the momenta at both ends). On the paper's two rods at
/// `dt = 10 ms` it takes 6.26 iterations on average (at most 8), and a step costs 5-8 RK4 steps
/// in the dev build, about 4 in release (the table in the [module docs](super)). The iteration
/// converges while `dt` times the fastest rate of the arm stays well below 1; beyond, the step
/// returns [`SimError::NoConvergence`] instead of a wrong answer.
///
/// # Example
/// ```
/// use planar_arm::prelude::*;
/// use planar_arm::sim::{Integrator, VariationalMidpoint};
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
/// let (mut q, mut qd) = (Vector2::new(0.3, 1.0), Vector2::zeros());
/// let energy = |q: &Vector2<f64>, qd: &Vector2<f64>| arm.kinetic_energy(q, qd) + arm.potential_energy(q);
/// let e0 = energy(&q, &qd);
/// for _ in 0..2000 {
///     (q, qd) = VariationalMidpoint::default().step(&arm, &q, &qd, &Vector2::zeros(), 5e-3)?;
/// }
/// assert!((energy(&q, &qd) - e0).abs() < 1e-2);
/// # Ok::<(), planar_arm::sim::SimError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VariationalMidpoint {
    /// The most fixed-point iterations per step.
    pub max_iterations: u32,
    /// Converged when the midpoint rate changes by at most `tolerance (1 + |v|)`, rad/s, or
    /// stops shrinking below `1e-10 (1 + |v|)` (rounding).
    pub tolerance: f64,
}

impl Default for VariationalMidpoint {
    /// 50 iterations, tolerance `1e-14`: converged to rounding, as symplecticity needs.
    fn default() -> Self {
        Self {
            max_iterations: 50,
            tolerance: 1e-14,
        }
    }
}

impl VariationalMidpoint {
    /// One step, returning the iterations it took too (for cost measurements).
    ///
    /// # Errors
    /// As [`Integrator::step`].
    pub fn step_counted<A: Dynamics<N> + ?Sized, const N: usize>(
        &self,
        arm: &A,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        tau: &SVector<f64, N>,
        dt: f64,
    ) -> Result<(SVector<f64, N>, SVector<f64, N>, u32), SimError> {
        // A negative dt is allowed here: Variational4 composes steps with one backwards.
        if dt == 0.0 || !dt.is_finite() {
            return Err(SimError::BadArgument {
                argument: "dt",
                value: dt,
            });
        }
        finite(q, "q")?;
        finite(qd, "qd")?;
        finite(tau, "tau")?;
        let p0 = arm.mass_matrix(q) * qd;
        let h = 0.5 * dt;
        let zero = SVector::<f64, N>::zeros();
        // M(x)^-1 b through the generated forward dynamics at rest, which solve with M's
        // factorisation in straight-line code: `forward_dynamics(x, 0, b + g(x)) = M(x)^-1 b`
        // (at rest c = 0 and f = 0).
        let mut v = *qd;
        let mut change = f64::INFINITY;
        for iteration in 1..=self.max_iterations {
            let qm = q + v * h;
            let g = arm.gravity(&qm);
            // p0 + h (C^T v - g + tau - f) + g, solved against M(qm).
            let rhs = p0
                + (transposed_coriolis(arm, &qm, &v) + tau - arm.friction(&v)) * h
                + g * (1.0 - h);
            let next = arm.forward_dynamics(&qm, &zero, &rhs);
            let previous = change;
            change = (next - v).amax();
            v = next;
            let scale = 1.0 + v.amax();
            // Converged, or at the rounding floor: the change no longer shrinks, and is small.
            let floor = change >= previous && change <= 1e-10 * scale;
            if change <= self.tolerance * scale || floor {
                let q1 = q + v * dt;
                let p1 = arm.mass_matrix(&qm) * v * 2.0 - p0;
                let qd1 = arm.forward_dynamics(&q1, &zero, &(p1 + arm.gravity(&q1)));
                let (q1, qd1) = done(q1, qd1)?;
                return Ok((q1, qd1, iteration));
            }
            if !change.is_finite() {
                break;
            }
        }
        Err(SimError::NoConvergence {
            iterations: self.max_iterations,
            change,
        })
    }
}

/// `C(q, v)^T v` for the Christoffel matrix `C`: `Mdot = C + C^T` makes it `Mdot v - C v`, and
/// `Mdot` (along `v`) is the mass matrix evaluated in a one-dimensional jet seeded with `v`,
/// `C v` the velocity-product forces. Any arm's dynamics give it, planar or spatial.
fn transposed_coriolis<A: Dynamics<N> + ?Sized, const N: usize>(
    arm: &A,
    q: &SVector<f64, N>,
    v: &SVector<f64, N>,
) -> SVector<f64, N> {
    let seeded = SVector::<Jet<1>, N>::from_fn(|i, _| Jet {
        re: q[i],
        eps: [v[i]],
    });
    let m_dot = arm.mass_matrix(&seeded).map(|x| x.eps[0]);
    m_dot * v - arm.coriolis(q, v)
}

impl Integrator for VariationalMidpoint {
    fn step<A: Dynamics<N> + ?Sized, const N: usize>(
        &self,
        arm: &A,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        tau: &SVector<f64, N>,
        dt: f64,
    ) -> Result<(SVector<f64, N>, SVector<f64, N>), SimError> {
        positive(dt, "dt")?;
        self.step_counted(arm, q, qd, tau, dt)
            .map(|(q, qd, _)| (q, qd))
    }
}

/// Fourth-order symplectic integrator: three [`VariationalMidpoint`] steps of
/// `w dt, (1 - 2w) dt, w dt` with `w = 1 / (2 - 2^(1/3))` (Yoshida's triple jump; the middle
/// step goes backwards). Symmetric and symplectic like its parts, so the energy error of a free
/// arm stays bounded, now at O(dt^4), and never drifts.
///
/// What it costs and buys, measured (the table in the [module docs](super), from
/// `cargo run --example simulate`): on the paper's two rods swinging for 100 s at 10 ms its
/// energy error stays at 1.7e-6 J from the first ten seconds to the last, where RK4's grows
/// from 4.8e-7 J to 5.1e-6 J; but a step costs 24-25 RK4 steps in the dev build, about 13 in
/// release (its three parts take larger steps, so more iterations each), and RK4 with its step
/// shortened to the same work is far more accurate (1e-12 to 2e-11 J at 100 s) over any
/// horizon one would simulate. Use it for the absence of drift, not for accuracy per unit of
/// work.
///
/// # Example
/// ```
/// use planar_arm::prelude::*;
/// use planar_arm::sim::{Integrator, Variational4};
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
/// // A swing about hanging down, 10 s at 10 ms.
/// let (mut q, mut qd) = (Vector2::new(-1.0, 0.4), Vector2::zeros());
/// let energy = |q: &Vector2<f64>, qd: &Vector2<f64>| arm.kinetic_energy(q, qd) + arm.potential_energy(q);
/// let e0 = energy(&q, &qd);
/// for _ in 0..1000 {
///     (q, qd) = Variational4::default().step(&arm, &q, &qd, &Vector2::zeros(), 1e-2)?;
/// }
/// assert!((energy(&q, &qd) - e0).abs() < 1e-5);
/// # Ok::<(), planar_arm::sim::SimError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Variational4 {
    /// The midpoint step composed, with its iteration settings.
    pub midpoint: VariationalMidpoint,
}

impl Variational4 {
    /// Yoshida's outer weight `1 / (2 - 2^(1/3))`.
    const W: f64 = 1.351_207_191_959_657_6;
}

impl Integrator for Variational4 {
    fn step<A: Dynamics<N> + ?Sized, const N: usize>(
        &self,
        arm: &A,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        tau: &SVector<f64, N>,
        dt: f64,
    ) -> Result<(SVector<f64, N>, SVector<f64, N>), SimError> {
        positive(dt, "dt")?;
        let outer = Self::W * dt;
        let inner = (1.0 - 2.0 * Self::W) * dt;
        let (q, qd, _) = self.midpoint.step_counted(arm, q, qd, tau, outer)?;
        let (q, qd, _) = self.midpoint.step_counted(arm, &q, &qd, tau, inner)?;
        let (q, qd, _) = self.midpoint.step_counted(arm, &q, &qd, tau, outer)?;
        Ok((q, qd))
    }
}
