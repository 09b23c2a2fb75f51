//! Spatial (3-D) serial arms: joints in Denavit-Hartenberg or URDF form, their numeric
//! description, and closed-form inverse kinematics by decoupling the wrist.

mod arm;
mod ik;
mod joint;
mod model;
mod numeric;
mod statics;

pub use arm::SpatialArm;
pub use ik::{IkClass, IkSolutions, SpatialIk};
pub use joint::JointGeometry;
pub use model::{SpatialJoint, SpatialLink, SpatialModel};
/// `#[derive(SpatialArm)]`, beside the trait it implements.
pub use planar_arm_derive::SpatialArm;
