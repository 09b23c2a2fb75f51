//! The arm traits the derives implement. The trait of a planar arm has its own file, so that
//! the kinematics of other geometries can sit beside it over the dynamics they share.

mod planar;

pub(crate) use planar::finite;
pub use planar::PlanarArm;
