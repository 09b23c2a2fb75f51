//! Simulation and control of any derived arm: fixed-step integrators, a simulation loop with a
//! torque callback, joint and tip trajectories, computed-torque and PD controllers.
//!
//! Everything here is `f64`, works for every `A: PlanarArm<N>`, and allocates nothing: states
//! are `SVector`s on the stack, the simulation loop is an iterator ([`Run`]) that yields one
//! [`State`] per control sample, and the only `Vec` is in [`Run::into_vec`], under the `std`
//! feature. Bad run-time input (NaN, a step `dt <= 0`, a trajectory of zero duration) gives a
//! [`SimError`], never a panic.
//!
//! ```
//! use planar_arm::prelude::*;
//! use planar_arm::sim::{ComputedTorque, Quintic, Rk4, Simulator, Trajectory};
//!
//! #[derive(PlanarArm, Default)]
//! #[arm(gravity = 9.81)]
//! struct Rods {
//!     #[arm(length = 1, mass = 1)]
//!     upper: Revolute,
//!     #[arm(length = 1, mass = 1)]
//!     fore: Revolute,
//! }
//!
//! let arm = Rods::default();
//! // Rest to rest in 2 s, tracked by computed torque: the model's inverse dynamics (the
//! // paper's dead reckoning) plus PD feedback, sampled and held every 5 ms.
//! let path = Quintic::rest_to_rest(Vector2::new(-1.5, 0.0), Vector2::new(0.5, 1.2), 2.0)?;
//! let controller = ComputedTorque::critically_damped(&arm, path, 20.0);
//! let sim = Simulator::new(Rk4, 1e-3)?.with_control_period(5e-3)?;
//! let mut worst = 0.0_f64;
//! for state in sim.run(&arm, path.start().q, Vector2::zeros(), 2.5, controller)? {
//!     let state = state?;
//!     worst = worst.max((state.q - path.sample(state.t).q).amax());
//! }
//! assert!(worst < 1e-3, "tracking error {worst}");
//! # Ok::<(), planar_arm::sim::SimError>(())
//! ```
//!
//! # Choosing the integrator
//!
//! | integrator | order | work per step | energy of a free arm over long times |
//! | --- | --- | --- | --- |
//! | [`SemiImplicitEuler`] | 1 | 1 forward dynamics | error O(dt), drifts (not symplectic: M depends on q) |
//! | [`Rk4`] | 4 | 4 forward dynamics | drifts, O(dt^4) per unit time, usually losing energy |
//! | [`VariationalMidpoint`] | 2 | an implicit solve, 4-9 fixed-point iterations | bounded O(dt^2) error, no drift (symplectic) |
//! | [`Variational4`] | 4 | three of those | bounded O(dt^4) error, no drift (symplectic) |
//!
//! [`Rk4`] is the default choice for control runs of seconds to minutes. The variational
//! integrators are for long free or lightly driven runs where a slow energy drift would
//! mislead (an hour of a swinging arm). `docs/sim-energy.svg` and the table in
//! [`Variational4`]'s documentation give the measured numbers.
//!
//! # Step size
//!
//! A fixed step must resolve the fastest motion of the arm, and that is set by the lightest
//! link and the gains. Two rates to compare `dt` with:
//!
//! - under feedback, the closed-loop rate [`fastest_rate`]: for gains `kp`, `kd` in N m/rad and
//!   N m s/rad (PD with gravity compensation) a light link of joint inertia `m` moves at about
//!   `sqrt(kp / m) + kd / m`. For [`ComputedTorque`] the gains are per unit inertia and the rate
//!   is `sqrt(kp) + kd` whatever the arm.
//! - a free arm has no gains, but a light last link is thrown about by the links below it at a
//!   rate that grows as its inertia shrinks.
//!
//! Explicit RK4 is stable for `dt * rate < 2.8` and accurate (to about 1e-6 relative over a
//! few periods) for `dt * rate < 0.1`. Measured (`cargo run --example simulate`): a six-link
//! arm whose last link is 5 cm and 20 g, under PD with gravity compensation and the same gains
//! on every joint (`kp = 200 N m/rad`, `kd = 10 N m s/rad`), has `fastest_rate` about 2e5 1/s
//! at its start pose, and RK4 diverges at `dt = 1e-4` s and above: per-joint gains scaled to the
//! joint's inertia are the fix, not a smaller step. The example prints the table for that arm.
//! Halving `dt` until the quantity you care about stops changing is the check that always
//! applies.

mod control;
mod error;
mod integrate;
mod run;
mod trajectory;

pub use control::{fastest_rate, ComputedTorque, PdGravity};
pub use error::SimError;
pub use integrate::{Integrator, Rk4, SemiImplicitEuler, Variational4, VariationalMidpoint};
pub use run::{from_fn, Controller, FnController, Run, Simulator, State};
pub use trajectory::{Quintic, Sample, TipLine, Trajectory, ViaPoints};
