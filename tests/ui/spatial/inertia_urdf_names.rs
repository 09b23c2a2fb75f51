use planar_arm::prelude::*;

// URDF writes `ixx`, `ixy`, ...; the attribute writes `xx`, `xy`, ...
#[derive(SpatialArm)]
struct Arm {
    #[arm(dh(a = 0.4), mass = 1, inertia(ixx = 0.1, yx = 0.01))]
    shoulder: Revolute,
}

fn main() {}
