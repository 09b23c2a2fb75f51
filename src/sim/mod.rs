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
//! | [`Rk4`] | 4 | 4 forward dynamics | drifts, O(dt^4) per unit time |
//! | [`VariationalMidpoint`] | 2 | an implicit solve: about 6 fixed-point iterations | bounded O(dt^2) error, no drift (symplectic) |
//! | [`Variational4`] | 4 | three of those | bounded O(dt^4) error, no drift (symplectic) |
//!
//! Measured on the paper's two rods swinging freely from `q = (-1, 0.4)` for 100 s at
//! `dt = 10 ms` (`cargo run --example simulate`, `docs/sim-energy.svg`; wall times on a busy
//! 2-core machine, the least of 30 interleaved rounds, two runs each of the unoptimised dev
//! build and of `--release`):
//!
//! | integrator | time per step, dev | release | largest energy error, 0-10 s | 90-100 s |
//! | --- | --- | --- | --- | --- |
//! | semi-implicit Euler | 0.3x RK4 | 0.4-0.5x RK4 | 0.27 J | 7.4 J |
//! | RK4 | 6-7 us | 0.10-0.12 us | 4.8e-7 J | 5.1e-6 J |
//! | variational midpoint | 5-8x RK4 | 3.9-4.1x RK4 | 3.1e-4 J | 3.2e-4 J |
//! | variational, 4th order | 24-25x RK4 | 12.7-13.3x RK4 | 1.7e-6 J | 1.7e-6 J |
//! | RK4 at the 4th order's cost, dev: dt = 0.40-0.42 ms | | | 3-6e-13 J | 1.0-1.1e-12 J |
//! | the same, release: dt = 0.75-0.79 ms | | | 5-6e-12 J | 1.6-1.9e-11 J |
//!
//! What the variational integrators buy is the absence of drift: their error at 100 s is the one at
//! 10 s, where RK4's has grown tenfold, and at equal step the fourth-order one is below RK4 after
//! about 30 s. What they cost is an implicit solve per step: at equal work, RK4 with the shorter
//! step is 1e5 to 1e6 times more accurate over 100 s, and at its measured drift would need months
//! to years of simulated time to reach the fourth-order variational error. So [`Rk4`] is the choice
//! for accuracy per unit of work, and for every control run; the variational integrators are for
//! when the qualitative long-time behaviour matters more than the error (no secular gain or loss of
//! energy at a coarse step, a symplectic map for phase portraits and long statistics).
//! [`SemiImplicitEuler`] costs a third to a half of an RK4 step and is useful only for rough
//! previews.
//!
//! # Step size
//!
//! A fixed step must resolve the fastest motion of the arm, which is set by its lightest link
//! and by the gains. The rate to compare `dt` with:
//!
//! - under feedback, [`fastest_rate`]: for PD gains `kp`, `kd` in N m/rad and N m s/rad (as in
//!   [`PdGravity`]) a link of joint inertia `m` moves at about `sqrt(kp / m) + kd / m`, so the
//!   same gains on a heavy and a light joint make the light one stiff. For [`ComputedTorque`]
//!   the gains are per unit inertia and the rate is `sqrt(kp) + kd` whatever the arm.
//! - a free arm has no gains, but a light last link is thrown about by the links below it.
//!
//! Explicit RK4 is stable for `dt * rate < 2.8` and accurate for `dt * rate` well below 1.
//! Measured (`cargo run --example simulate` prints the table) on a six-link arm of 4, 3, 2, 1,
//! 0.3 and 0.02 kg, the last link 5 cm long:
//!
//! - free swing for 2 s under RK4, largest energy error relative to the energy released:
//!   diverges at `dt = 1e-2` s (NaN after 1.67 s), 7.7e-4 at 3e-3 s, 4.3e-6 at 1e-3 s, 3.0e-8
//!   at 3e-4 s, 3.5e-10 at 1e-4 s (fourth order: a factor 10 in `dt` is 1e4 in error);
//! - PD with gravity compensation and the same gains on every joint (`kp = 200 N m/rad`,
//!   `kd = 10 N m s/rad`): `fastest_rate` is 7.0e5 1/s (`kd / m` of the 20 g link), RK4
//!   diverges at 1e-3, 1e-4 and 3e-5 s and would need `dt < 4e-6` s. The fix is gains scaled to
//!   each joint's inertia, not a smaller step:
//! - computed torque at 20 rad/s on every joint (rate 60 1/s): `dt = 1e-2` s is stable and holds
//!   the arm to 5.6e-5 rad after 0.5 s (2.9e-5 rad at 1e-3 s).
//!
//! Halving `dt` until the quantity you care about stops changing is the check that always
//! applies.

//!
//! [`ComputedTorque`]: crate::sim::ComputedTorque
//! [`PdGravity`]: crate::sim::PdGravity
//! [`Rk4`]: crate::sim::Rk4
//! [`Run`]: crate::sim::Run
//! [`Run::into_vec`]: crate::sim::Run::into_vec
//! [`SemiImplicitEuler`]: crate::sim::SemiImplicitEuler
//! [`SimError`]: crate::sim::SimError
//! [`State`]: crate::sim::State
//! [`Variational4`]: crate::sim::Variational4
//! [`VariationalMidpoint`]: crate::sim::VariationalMidpoint
//! [`fastest_rate`]: crate::sim::fastest_rate

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
