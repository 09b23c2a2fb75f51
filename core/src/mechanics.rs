//! The second stage: the exact mechanics of an arm, derived symbolically in the algebra of
//! [`crate::expr`]. One part per geometry; `planar` is the planar serial arm, Lagrangian
//! mechanics following the paper's route.

pub(crate) mod planar;
pub mod spatial;

pub use planar::{
    down, standard_bodies, ArmSpec, Body, Dynamics, JointKind, Kinematics, LinkSpec, Offset,
    PayloadSpec, RateProducts,
};
