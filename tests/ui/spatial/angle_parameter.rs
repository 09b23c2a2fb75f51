use planar_arm::prelude::*;

// Lengths may be run-time parameters; angles may not.
#[derive(SpatialArm)]
struct Arm {
    #[arm(dh(a = self.reach, alpha = self.twist))]
    shoulder: Revolute,
    reach: f64,
    twist: f64,
}

fn main() {}
