use planar_arm::prelude::*;

// Every problem of one struct is reported in one compilation.
#[derive(SpatialArm)]
#[arm(gravity = 9.81, lenght = 2)]
struct Arm {
    #[arm(dh(a = 0.4, alpha = 90deg), mass = -1)]
    waist: Revolute,
    #[arm(mdh(a = 0.4), inertia(xx = 1, qq = 2))]
    shoulder: Revolute,
    #[arm(origin(xyz = (0, 0, 1)), axis = (0, 0, 0), range = (1, -1))]
    elbow: Revolute,
    wrist: Revolute,
}

fn main() {}
