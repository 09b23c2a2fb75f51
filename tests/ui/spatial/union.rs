use planar_arm::prelude::*;

#[derive(SpatialArm)]
union Arm {
    shoulder: f64,
}

fn main() {}
