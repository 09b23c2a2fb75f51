//! Lagrangian mechanics of a planar serial arm, following the paper's route: velocities of
//! each centre of mass and link angular velocities, kinetic energy (translation of the centre
//! of mass plus rotation about it), potential energy of the centres of mass. Then M is the
//! Hessian of T in the rates, g = dV/dq, C comes from Christoffel symbols of M and c = C qd:
//! the same exact functions Lagrange's equation gives (`Dynamics::lagrange_torques` expands
//! that equation itself, and the tests assert the two equal), without its costliest step.

mod bodies;
pub(crate) mod christoffel;
pub mod definite;
mod dynamics;
mod energy;
mod kinematics;
mod metric;
mod rates;
mod spec;
#[cfg(test)]
pub(crate) mod tests;

pub use bodies::{standard_bodies, Body};
pub use dynamics::Dynamics;
pub use kinematics::Kinematics;
pub use rates::RateProducts;
pub use spec::{down, ArmSpec, JointKind, LinkSpec, Offset, PayloadSpec};
