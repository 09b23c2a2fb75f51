use planar_arm::prelude::*;

#[derive(SpatialArm)]
struct Arm {
    #[arm(dh(a = 0.4, d = self.offset), mass = self.m)]
    shoulder: Revolute,
    m: f64,
}

fn main() {}
