//! A link field's type through an alias and a path, and user types named like the primitives
//! that generated code uses: all must compile and run.
#![allow(non_camel_case_types, dead_code)]

use planar_arm::prelude::*;

type Joint = planar_arm::Revolute;

struct f64;
struct usize;
struct bool;
struct str;

#[derive(PlanarArm)]
#[arm(gravity = 9.81, payload = self.load)]
struct Arm {
    #[arm(length = 1, mass = self.m1)]
    upper: Joint,
    #[arm(length = 1/2, mass = 1)]
    fore: ::planar_arm::Revolute,
    m1: core::primitive::f64,
    load: core::primitive::f64,
}

fn main() {
    let arm = Arm { upper: planar_arm::Revolute, fore: planar_arm::Revolute, m1: 2.0, load: 0.5 };
    let q = Vector2::<core::primitive::f64>::new(0.3, -0.4);
    let tau = arm.inverse_dynamics(&q, &q, &q);
    assert!(tau.iter().all(|t| t.is_finite()));
}
