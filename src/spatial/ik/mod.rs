//! Closed-form inverse kinematics of six-joint spatial arms by decoupling the wrist.

mod classify;
pub(crate) mod ranges;
mod solutions;
mod solver;
mod subproblems;

pub use solutions::IkSolutions;
pub use solver::{IkClass, SpatialIk};
