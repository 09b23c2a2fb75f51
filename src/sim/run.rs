//! The simulation loop: a controller sampled every control period, an integrator in between.

use nalgebra::SVector;

use super::error::{finite, positive};
use super::{Integrator, SimError};
use crate::Dynamics;

/// What drives the arm: joint torques from the time and the measured state, called once per
/// control period by [`Simulator::run`] (the torque is then held until the next call).
///
/// [`ComputedTorque`](super::ComputedTorque) and [`PdGravity`](super::PdGravity) implement it;
/// wrap a closure in [`from_fn`].
///
/// # Example
/// A wrapper that limits another controller's torques to what the motors can give:
/// ```
/// use planar_arm::nalgebra::{SVector, Vector2};
/// use planar_arm::sim::{from_fn, Controller};
///
/// struct Saturated<C> {
///     inner: C,
///     limit: f64,
/// }
///
/// impl<C: Controller<N>, const N: usize> Controller<N> for Saturated<C> {
///     fn torque(&mut self, t: f64, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> SVector<f64, N> {
///         self.inner.torque(t, q, qd).map(|u| u.clamp(-self.limit, self.limit))
///     }
/// }
///
/// let stiff = from_fn(|_t, q: &Vector2<f64>, _qd: &Vector2<f64>| -1000.0 * q);
/// let mut limited = Saturated { inner: stiff, limit: 5.0 };
/// let tau = limited.torque(0.0, &Vector2::new(0.1, -0.001), &Vector2::zeros());
/// assert_eq!(tau, Vector2::new(-5.0, 1.0));
/// ```
pub trait Controller<const N: usize> {
    /// The torque to apply from time `t` (s) on, given the joint angles `q` and rates `qd`.
    fn torque(&mut self, t: f64, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> SVector<f64, N>;
}

/// A closure `(t, q, qd) -> tau` as a [`Controller`]; made by [`from_fn`].
#[derive(Debug, Clone, Copy)]
pub struct FnController<F>(pub F);

impl<F, const N: usize> Controller<N> for FnController<F>
where
    F: FnMut(f64, &SVector<f64, N>, &SVector<f64, N>) -> SVector<f64, N>,
{
    fn torque(&mut self, t: f64, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> SVector<f64, N> {
        (self.0)(t, q, qd)
    }
}

/// A closure `(t, q, qd) -> tau` as a [`Controller`] (the closure's argument types are then
/// inferred).
///
/// # Example
/// ```
/// use planar_arm::nalgebra::Vector2;
/// use planar_arm::sim::{from_fn, Controller};
///
/// let mut damper = from_fn(|_t, _q: &Vector2<f64>, qd: &Vector2<f64>| -0.5 * qd);
/// assert_eq!(damper.torque(0.0, &Vector2::zeros(), &Vector2::new(2.0, 0.0)), Vector2::new(-1.0, 0.0));
/// ```
pub fn from_fn<F, const N: usize>(f: F) -> FnController<F>
where
    F: FnMut(f64, &SVector<f64, N>, &SVector<f64, N>) -> SVector<f64, N>,
{
    FnController(f)
}

/// The arm at one control sample: time, angles, rates, the torque applied from `t` until the
/// next sample, and the acceleration that torque gives at `t`.
///
/// `qdd` is the arm's own forward dynamics at `(q, qd, tau)`, so `inverse_dynamics(q, qd, qdd)
/// == tau` to rounding: a state is a regressor row `Y(q, qd, qdd) theta = tau` as it stands,
/// which accelerations differenced from sampled rates are not (they average over the control
/// period and bias what they identify, friction above all).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct State<const N: usize> {
    /// Time, s.
    pub t: f64,
    /// Joint angles, rad.
    pub q: SVector<f64, N>,
    /// Joint rates, rad/s.
    pub qd: SVector<f64, N>,
    /// The controller's torque at `t`, N m, held for the following control period.
    pub tau: SVector<f64, N>,
    /// The joint accelerations at `t` under `tau`, rad/s^2 (m/s^2 for a slide).
    pub qdd: SVector<f64, N>,
}

/// An integrator with its step and the control period (a whole number of steps).
///
/// # Example
/// ```
/// use planar_arm::prelude::*;
/// use planar_arm::sim::{from_fn, Rk4, Simulator};
///
/// #[derive(PlanarArm, Default)]
/// #[arm(gravity = 9.81)]
/// struct Pendulum {
///     #[arm(length = 1, mass = 1)]
///     rod: Revolute,
/// }
///
/// let arm = Pendulum::default();
/// let sim = Simulator::new(Rk4, 1e-3)?.with_control_period(1e-2)?;
/// let free = from_fn(|_t, _q: &SVector<f64, 1>, _qd: &SVector<f64, 1>| SVector::zeros());
/// // Released horizontal: one sample every 10 ms for 1 s, the start included.
/// let run = sim.run(&arm, SVector::<f64, 1>::zeros(), SVector::zeros(), 1.0, free)?;
/// let mut last = None;
/// let mut samples = 0;
/// for state in run {
///     last = Some(state?);
///     samples += 1;
/// }
/// assert_eq!(samples, 101);
/// assert!(last.is_some_and(|s| s.t == 1.0 && s.q[0] < -1.0)); // it has swung down
/// assert!(Simulator::new(Rk4, -1.0).is_err());
/// # Ok::<(), planar_arm::sim::SimError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Simulator<I> {
    integrator: I,
    dt: f64,
    hold: u32,
}

impl<I: Integrator> Simulator<I> {
    /// A simulator stepping `integrator` by `dt` seconds, with the controller called every
    /// step until [`with_control_period`](Self::with_control_period) says otherwise.
    ///
    /// # Errors
    /// [`SimError::BadArgument`] when `dt` is not positive and finite.
    pub fn new(integrator: I, dt: f64) -> Result<Self, SimError> {
        Ok(Self {
            integrator,
            dt: positive(dt, "dt")?,
            hold: 1,
        })
    }

    /// Calls the controller every `period` seconds and holds its torque in between: `period`
    /// must be a whole number of steps (to within 1e-9 relative).
    ///
    /// # Errors
    /// [`SimError::BadArgument`] when `period` is not positive and finite or not a multiple of
    /// the step (or more than `u32::MAX` steps).
    pub fn with_control_period(self, period: f64) -> Result<Self, SimError> {
        let bad = SimError::BadArgument {
            argument: "control period",
            value: period,
        };
        positive(period, "control period")?;
        let steps = num_traits::Float::round(period / self.dt);
        if !(1.0..=f64::from(u32::MAX)).contains(&steps)
            || num_traits::Float::abs(steps * self.dt - period) > 1e-9 * period
        {
            return Err(bad);
        }
        // In 1..=u32::MAX, checked above.
        #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
        let hold = steps as u32;
        Ok(Self { hold, ..self })
    }

    /// The integration step, s.
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// The control period, s.
    pub fn control_period(&self) -> f64 {
        self.dt * f64::from(self.hold)
    }

    /// Simulates `arm` from `(q0, qd0)` at `t = 0` for `duration` seconds (rounded to whole
    /// control periods) under `controller`: an iterator over the states at each control
    /// sample, the start included. It stops after the first error (a non-finite torque from
    /// the controller, a state that blew up, an implicit step that did not converge), which it
    /// yields with the time at which it happened.
    ///
    /// # Errors
    /// [`SimError::BadArgument`] when `duration` is negative or not finite,
    /// [`SimError::NonFinite`] for a non-finite start.
    pub fn run<'a, A, C, const N: usize>(
        &self,
        arm: &'a A,
        q0: SVector<f64, N>,
        qd0: SVector<f64, N>,
        duration: f64,
        controller: C,
    ) -> Result<Run<'a, A, I, C, N>, SimError>
    where
        A: Dynamics<N> + ?Sized,
        I: Clone,
        C: Controller<N>,
    {
        if !(duration >= 0.0 && duration.is_finite()) {
            return Err(SimError::BadArgument {
                argument: "duration",
                value: duration,
            });
        }
        finite(&q0, "q0").map_err(|e| e.at(0.0))?;
        finite(&qd0, "qd0").map_err(|e| e.at(0.0))?;
        let samples = num_traits::Float::round(duration / self.control_period());
        // Bounded by the check below; more than 2^53 samples would not finish anyway.
        #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
        let samples = samples.min(9e15) as u64;
        Ok(Run {
            arm,
            sim: self.clone(),
            controller,
            q: q0,
            qd: qd0,
            sample: 0,
            samples,
            failed: false,
        })
    }
}

/// The states of a simulation, one per control sample: made by [`Simulator::run`].
///
/// Each `next` calls the controller once and the integrator as many times as a control period
/// holds; nothing is allocated.
pub struct Run<'a, A: ?Sized, I, C, const N: usize> {
    arm: &'a A,
    sim: Simulator<I>,
    controller: C,
    q: SVector<f64, N>,
    qd: SVector<f64, N>,
    sample: u64,
    samples: u64,
    failed: bool,
}

impl<A, I, C, const N: usize> Run<'_, A, I, C, N>
where
    A: Dynamics<N> + ?Sized,
    I: Integrator,
    C: Controller<N>,
{
    /// Every state, collected.
    ///
    /// # Errors
    /// The first error of the run.
    #[cfg(feature = "std")]
    pub fn into_vec(self) -> Result<std::vec::Vec<State<N>>, SimError> {
        self.collect()
    }

    /// The controller, for what it recorded.
    pub fn controller(&self) -> &C {
        &self.controller
    }
}

impl<A, I, C, const N: usize> Iterator for Run<'_, A, I, C, N>
where
    A: Dynamics<N> + ?Sized,
    I: Integrator,
    C: Controller<N>,
{
    type Item = Result<State<N>, SimError>;

    fn next(&mut self) -> Option<Self::Item> {
        if self.failed || self.sample > self.samples {
            return None;
        }
        // Whole samples times the period, so that times do not accumulate rounding.
        #[allow(clippy::cast_precision_loss)]
        let t = self.sample as f64 * self.sim.control_period();
        let tau = self.controller.torque(t, &self.q, &self.qd);
        if let Err(e) = finite(&tau, "tau") {
            self.failed = true;
            return Some(Err(e.at(t)));
        }
        let qdd = self.arm.forward_dynamics(&self.q, &self.qd, &tau);
        if let Err(e) = finite(&qdd, "qdd") {
            self.failed = true;
            return Some(Err(e.at(t)));
        }
        let state = State {
            t,
            q: self.q,
            qd: self.qd,
            tau,
            qdd,
        };
        if self.sample < self.samples {
            for k in 0..self.sim.hold {
                match self
                    .sim
                    .integrator
                    .step(self.arm, &self.q, &self.qd, &tau, self.sim.dt)
                {
                    Ok((q, qd)) => (self.q, self.qd) = (q, qd),
                    Err(e) => {
                        self.failed = true;
                        return Some(Err(e.at(t + f64::from(k) * self.sim.dt)));
                    }
                }
            }
        }
        self.sample += 1;
        Some(Ok(state))
    }
}
