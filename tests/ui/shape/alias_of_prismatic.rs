use planar_arm::prelude::*;

// The derive reads the joint kind from the type's name: an alias of `Prismatic` reads as a
// hinge, which the type check then refuses with a note saying so.
type Slide = planar_arm::Prismatic;

#[derive(PlanarArm)]
struct Gantry {
    #[arm(length = 1, mass = 1)]
    carriage: Slide,
}

fn main() {}
