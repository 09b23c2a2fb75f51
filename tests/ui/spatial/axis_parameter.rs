use planar_arm::prelude::*;

#[derive(SpatialArm)]
struct Arm {
    #[arm(origin(xyz = (0, 0, 0.3)), axis = (0, 0, self.z))]
    shoulder: Revolute,
    z: f64,
}

fn main() {}
