use planar_arm::prelude::*;

#[derive(PlanarArm)]
union Arm {
    upper: Revolute,
}

fn main() {}
