//! The arm traits the derives implement. The trait of a planar arm has its own file, so that
//! the kinematics of other geometries can sit beside it over the dynamics they share.

mod dynamics;
mod planar;

pub use dynamics::Dynamics;
pub use planar::PlanarArm;
