//! Arms derived at compile time by `#[derive(PlanarArm)]` with random rational parameters
//! (1 to 8 links, drawn once with a fixed seed and written here), checked against the numeric
//! reference for random states: the generated Rust itself, not just the engine's programs.
//!
//! Also checked, for each arm: M symmetric positive definite, `C qd = c`, `Mdot - 2C`
//! skew-symmetric with Mdot by central finite differences, `g = dV/dq` by finite differences,
//! `T = qd^T M qd / 2`, and `forward_dynamics` inverting `inverse_dynamics`.

mod common;

use planar_arm::prelude::*;

#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 3/2)]
struct Random1 {
    #[arm(length = 17/4, mass = 1.80, com = 15/4)]
    l1: Revolute,
}

#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 24.79)]
struct Random2 {
    #[arm(length = 12/5, mass = 9.60, inertia = 26/97, com = 19/7)]
    l1: Revolute,
    #[arm(length = 20/4, mass = 36/5, com = 1/2)]
    l2: Revolute,
}

#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 1.625)]
struct Random3 {
    #[arm(length = 25/6, mass = 3.70)]
    l1: Revolute,
    #[arm(length = 9/3, mass = 35/3, inertia = 37/44, com = -14/6)]
    l2: Revolute,
    #[arm(length = 23/6, mass = 7.27, inertia = 9/36, com = 20/2)]
    l3: Revolute,
}

#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 1.625)]
struct Random4 {
    #[arm(length = 6/8, mass = 19/4)]
    l1: Revolute,
    #[arm(length = 5/3, mass = 9/8, inertia = 28/36, com = 2/2)]
    l2: Revolute,
    #[arm(length = 13/4, mass = 4.89, inertia = 49/22, com = 13/1)]
    l3: Revolute,
    #[arm(length = 8/8, mass = 7.83, com = -10/4)]
    l4: Revolute,
}

#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 1.625)]
struct Random5 {
    #[arm(length = 1/4, mass = 35/7, inertia = 34/73, com = 0/1)]
    l1: Revolute,
    #[arm(length = 23/5, mass = 4/1, inertia = 19/1, com = 15/8)]
    l2: Revolute,
    #[arm(length = 30/4, mass = 9.58, com = 12/7)]
    l3: Revolute,
    #[arm(length = 18/1, mass = 5.93, com = -15/9)]
    l4: Revolute,
    #[arm(length = 18/4, mass = 25/1, inertia = 48/28)]
    l5: Revolute,
}

#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 0)]
struct Random6 {
    #[arm(length = 10/11, mass = 8.36, inertia = 21/80, com = 16/5)]
    l1: Revolute,
    #[arm(length = 23/8, mass = 2.01, inertia = 15/89, com = 2/9)]
    l2: Revolute,
    #[arm(length = 19/2, mass = 38/3, inertia = 15/58)]
    l3: Revolute,
    #[arm(length = 17/11, mass = 17/1)]
    l4: Revolute,
    #[arm(length = 1/2, mass = 8/2, inertia = 21/76, com = 17/3)]
    l5: Revolute,
    #[arm(length = 10/3, mass = 7.09, com = -16/4)]
    l6: Revolute,
}

#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 0)]
struct Random7 {
    #[arm(length = 14/3, mass = 5.50, inertia = 2/64, com = -3/8)]
    l1: Revolute,
    #[arm(length = 27/8, mass = 21/5, inertia = 41/31, com = 0/5)]
    l2: Revolute,
    #[arm(length = 12/9, mass = 20/5, inertia = 10/95)]
    l3: Revolute,
    #[arm(length = 28/7, mass = 9.37, com = -6/9)]
    l4: Revolute,
    #[arm(length = 25/6, mass = 26/3, com = 9/8)]
    l5: Revolute,
    #[arm(length = 25/7, mass = 35/7, inertia = 37/57)]
    l6: Revolute,
    #[arm(length = 15/12, mass = 2.20, inertia = 23/21)]
    l7: Revolute,
}

#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 1.625)]
struct Random8 {
    #[arm(length = 17/8, mass = 7.39, inertia = 45/33, com = -0/2)]
    l1: Revolute,
    #[arm(length = 15/10, mass = 8.13, com = -14/6)]
    l2: Revolute,
    #[arm(length = 17/3, mass = 34/8)]
    l3: Revolute,
    #[arm(length = 25/9, mass = 29/1, inertia = 26/69, com = 2/5)]
    l4: Revolute,
    #[arm(length = 2/1, mass = 4.50, inertia = 5/90, com = -5/1)]
    l5: Revolute,
    #[arm(length = 3/1, mass = 20/8, com = 4/2)]
    l6: Revolute,
    #[arm(length = 3/4, mass = 3.32, inertia = 14/7)]
    l7: Revolute,
    #[arm(length = 15/11, mass = 13/1, inertia = 34/23, com = -8/8)]
    l8: Revolute,
}

#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 9.81)]
struct Random2b {
    #[arm(length = 24/9, mass = 2.37, com = -8/1)]
    l1: Revolute,
    #[arm(length = 3/1, mass = 3/6, com = 8/3)]
    l2: Revolute,
}

#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 1.625)]
struct Random3b {
    #[arm(length = 28/8, mass = 9/1, inertia = 39/63)]
    l1: Revolute,
    #[arm(length = 11/6, mass = 19/5, inertia = 27/90)]
    l2: Revolute,
    #[arm(length = 27/2, mass = 9/1, inertia = 19/65, com = -11/8)]
    l3: Revolute,
}

planar_arm_tests_check_arms! {
    random1: Random1, 1;
    random2: Random2, 2;
    random3: Random3, 3;
    random4: Random4, 4;
    random5: Random5, 5;
    random6: Random6, 6;
    random7: Random7, 7;
    random8: Random8, 8;
    random2b: Random2b, 2;
    random3b: Random3b, 3;
}
