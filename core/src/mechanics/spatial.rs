//! Spatial serial arms: each joint's geometry in its convention (`spec`), their frames
//! multiplied out exactly (`frames`), and the closed-form decoupling the geometry allows
//! (`decoupling`).

mod decoupling;
pub mod frames;
pub mod lagrangian;
pub mod spec;

pub use decoupling::{decouple, DecoupledGeometry, Decoupling};
pub use frames::{Frame, SpatialKinematics};
pub use spec::{
    unit_axis, FixedAngle, SpatialArmSpec, SpatialBody, SpatialGeometry, SpatialJointSpec,
};
