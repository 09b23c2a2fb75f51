use planar_arm::prelude::*;

#[derive(SpatialArm)]
struct Arm {
    #[arm(origin(xyz = (0, 0, 0.3), rpy = (0, f64::to_radians(90.0), 0)))]
    shoulder: Revolute,
}

fn main() {}
