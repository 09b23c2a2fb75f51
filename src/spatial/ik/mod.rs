//! Closed-form inverse kinematics of six-joint spatial arms by decoupling the wrist.

mod atan2;
mod classes;
mod classify;
mod position;
pub(crate) mod ranges;
mod solutions;
mod solver;
mod subproblems;
mod wrist;

pub use solutions::IkSolutions;
pub use solver::{IkClass, SpatialIk};
