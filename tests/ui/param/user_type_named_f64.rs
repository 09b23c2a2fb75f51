#![allow(non_camel_case_types)]
use planar_arm::prelude::*;

// A type of the user's named `f64` shadows the primitive: one error at the field's type, not one
// at every generated read.
struct f64;

#[derive(PlanarArm)]
#[arm(payload = self.load)]
struct Arm {
    #[arm(length = 1, mass = self.m)]
    upper: Revolute,
    m: f64,
    load: f64,
}

fn main() {}
