//! Arms with prismatic joints and their all-revolute twins, timed by `benches/prismatic.rs`
//! (`bench/pinocchio` builds the same arms).
//!
//! Each `MixedN` has the lengths, masses and inertias of `random_arms.rs`'s `RandomN` with a
//! centre of mass moved off the link's axis (`com.y` nonzero) and some joints prismatic;
//! `AllRevoluteN` is the same links, every joint revolute. Joints, base first: RP (the polar
//! arm), PRR, RPRP, RPRPRP, RPRPRPRP.

use planar_arm::prelude::*;

#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 9.80665)]
pub struct Mixed2 {
    #[arm(length = 6/1, mass = 3/1, inertia = 6/25, com = (12/5, 3/10))]
    a: Revolute,
    #[arm(length = 4/1, mass = 38/5, inertia = 1/25, com = (4/1, -1/5))]
    b: Prismatic,
}

#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 9.80665)]
pub struct AllRevolute2 {
    #[arm(length = 6/1, mass = 3/1, inertia = 6/25, com = (12/5, 3/10))]
    a: Revolute,
    #[arm(length = 4/1, mass = 38/5, inertia = 1/25, com = (4/1, -1/5))]
    b: Revolute,
}

#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 9.80665)]
pub struct Mixed3 {
    #[arm(length = 12/5, mass = 26/5, inertia = 5/4, com = (6/25, 1/10))]
    a: Prismatic,
    #[arm(length = 23/10, mass = 2/1, inertia = 1/20, com = (69/100, -3/20))]
    b: Revolute,
    #[arm(length = 2/1, mass = 3/2, inertia = 11/25, com = (3/5, 1/5))]
    c: Revolute,
}

#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 9.80665)]
pub struct AllRevolute3 {
    #[arm(length = 12/5, mass = 26/5, inertia = 5/4, com = (6/25, 1/10))]
    a: Revolute,
    #[arm(length = 23/10, mass = 2/1, inertia = 1/20, com = (69/100, -3/20))]
    b: Revolute,
    #[arm(length = 2/1, mass = 3/2, inertia = 11/25, com = (3/5, 1/5))]
    c: Revolute,
}

#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 9.80665)]
pub struct Mixed4 {
    #[arm(length = 9/5, mass = 13/4, inertia = 1/40, com = (9/5, 1/10))]
    a: Revolute,
    #[arm(length = 9/5, mass = 9/2, inertia = 11/40, com = (-27/50, 1/5))]
    b: Prismatic,
    #[arm(length = 23/8, mass = 3/4, inertia = 3/10, com = (69/20, -1/4))]
    c: Revolute,
    #[arm(length = 14/5, mass = 16/5, inertia = 23/25, com = (-14/25, 3/10))]
    d: Prismatic,
}

#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 9.80665)]
pub struct AllRevolute4 {
    #[arm(length = 9/5, mass = 13/4, inertia = 1/40, com = (9/5, 1/10))]
    a: Revolute,
    #[arm(length = 9/5, mass = 9/2, inertia = 11/40, com = (-27/50, 1/5))]
    b: Revolute,
    #[arm(length = 23/8, mass = 3/4, inertia = 3/10, com = (69/20, -1/4))]
    c: Revolute,
    #[arm(length = 14/5, mass = 16/5, inertia = 23/25, com = (-14/25, 3/10))]
    d: Revolute,
}

#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 9.80665)]
pub struct Mixed6 {
    #[arm(length = 3/1, mass = 12/5, inertia = 1/50, com = (12/5, 1/5))]
    a: Revolute,
    #[arm(length = 4/1, mass = 15/2, inertia = 23/25, com = (6/5, -1/10))]
    b: Prismatic,
    #[arm(length = 7/5, mass = 31/8, inertia = 17/40, com = (7/10, 3/20))]
    c: Revolute,
    #[arm(length = 9/2, mass = 39/8, inertia = 7/10, com = (-9/10, 1/4))]
    d: Prismatic,
    #[arm(length = 17/4, mass = 15/8, inertia = 17/40, com = (17/40, -1/5))]
    e: Revolute,
    #[arm(length = 7/4, mass = 9/1, inertia = 1/4, com = (21/20, 1/10))]
    f: Prismatic,
}

#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 9.80665)]
pub struct AllRevolute6 {
    #[arm(length = 3/1, mass = 12/5, inertia = 1/50, com = (12/5, 1/5))]
    a: Revolute,
    #[arm(length = 4/1, mass = 15/2, inertia = 23/25, com = (6/5, -1/10))]
    b: Revolute,
    #[arm(length = 7/5, mass = 31/8, inertia = 17/40, com = (7/10, 3/20))]
    c: Revolute,
    #[arm(length = 9/2, mass = 39/8, inertia = 7/10, com = (-9/10, 1/4))]
    d: Revolute,
    #[arm(length = 17/4, mass = 15/8, inertia = 17/40, com = (17/40, -1/5))]
    e: Revolute,
    #[arm(length = 7/4, mass = 9/1, inertia = 1/4, com = (21/20, 1/10))]
    f: Revolute,
}

#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 9.80665)]
pub struct Mixed8 {
    #[arm(length = 9/4, mass = 11/8, inertia = 16/25, com = (-9/20, 1/10))]
    a: Revolute,
    #[arm(length = 3/5, mass = 4/5, inertia = 3/5, com = (3/10, -1/5))]
    b: Prismatic,
    #[arm(length = 9/5, mass = 11/4, inertia = 3/2, com = (54/25, 1/4))]
    c: Revolute,
    #[arm(length = 14/5, mass = 2/1, inertia = 21/50, com = (0/1, 3/20))]
    d: Prismatic,
    #[arm(length = 9/10, mass = 5/1, inertia = 1/25, com = (27/50, -1/10))]
    e: Revolute,
    #[arm(length = 4/5, mass = 6/5, inertia = 2/5, com = (24/25, 1/5))]
    f: Prismatic,
    #[arm(length = 3/2, mass = 16/5, inertia = 29/25, com = (0/1, -3/20))]
    g: Revolute,
    #[arm(length = 16/5, mass = 33/8, inertia = 3/10, com = (96/25, 1/10))]
    h: Prismatic,
}

#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 9.80665)]
pub struct AllRevolute8 {
    #[arm(length = 9/4, mass = 11/8, inertia = 16/25, com = (-9/20, 1/10))]
    a: Revolute,
    #[arm(length = 3/5, mass = 4/5, inertia = 3/5, com = (3/10, -1/5))]
    b: Revolute,
    #[arm(length = 9/5, mass = 11/4, inertia = 3/2, com = (54/25, 1/4))]
    c: Revolute,
    #[arm(length = 14/5, mass = 2/1, inertia = 21/50, com = (0/1, 3/20))]
    d: Revolute,
    #[arm(length = 9/10, mass = 5/1, inertia = 1/25, com = (27/50, -1/10))]
    e: Revolute,
    #[arm(length = 4/5, mass = 6/5, inertia = 2/5, com = (24/25, 1/5))]
    f: Revolute,
    #[arm(length = 3/2, mass = 16/5, inertia = 29/25, com = (0/1, -3/20))]
    g: Revolute,
    #[arm(length = 16/5, mass = 33/8, inertia = 3/10, com = (96/25, 1/10))]
    h: Revolute,
}
