//! Generated code fits any crate: it names nothing the user can shadow (user functions named
//! like its intermediates, a user `core` or `planar_arm` module, user `Link`, `Revolute`,
//! `Result`), it works inside function bodies and nested modules, and the same arm always
//! expands to the same tokens. User consts, statics and unit structs named like the generated
//! locals are in `tests/ui/pass/user_names.rs`: were they to capture a `let`, that file alone
//! would fail to compile, not the whole test suite.
#![deny(warnings)]
// The look-alike items below exist to be in scope, not to be used.
#![allow(dead_code)]

// A user module named `core` must not break the generated `::core::...` paths, nor one named
// `planar_arm` the `::planar_arm::...` paths (both are extern-prelude paths since 2018).
mod core {
    pub mod result {
        pub struct Result;
    }
    pub fn unreachable() {}
}
mod planar_arm {
    pub struct PlanarArm;
    pub mod nalgebra {}
    pub mod __private {}
}

use ::planar_arm::prelude::*;

/// Functions named like the generated locals (`let` may shadow a function), and types, traits
/// and modules named like the items the generated code names.
mod items {
    pub fn q1() {}
    pub fn m11() {}
    pub fn unpack() {}
    pub fn vector() {}
    pub fn matrix() {}
    pub fn pose() {}
    pub fn polar() {}
    pub fn term() {}
    pub struct Link;
    pub trait Revolute {}
    pub struct SVector;
    pub struct SMatrix;
    pub struct Isometry2;
    pub struct Point2;
    pub struct Vector2;
    pub struct ArmError;
    pub trait PlanarArm {}
    pub trait ClosedFormIk {}
    pub enum Result {
        Ok,
        Err,
    }
    #[allow(unused_imports)] // in scope of the derive below, unused by design
    pub use Result::{Err, Ok};
    pub struct Option;
    pub struct Some;
    pub mod nalgebra {}
    pub mod kinematics {}
    pub mod exact {}

    #[derive(::planar_arm::PlanarArm, Default)]
    pub struct Three {
        #[arm(length = 1, mass = 1)]
        pub a: ::planar_arm::Revolute,
        #[arm(length = 0.5, mass = 2)]
        pub b: ::planar_arm::Revolute,
        #[arm(length = 0.25, mass = 1)]
        pub c: ::planar_arm::Revolute,
    }

    #[derive(::planar_arm::PlanarArm, Default)]
    pub struct Two {
        #[arm(length = 1, mass = 1)]
        pub a: ::planar_arm::Revolute,
        #[arm(length = 0.5, mass = 2)]
        pub b: ::planar_arm::Revolute,
    }
}

mod outer {
    pub mod inner {
        use ::planar_arm::prelude::*;

        #[derive(PlanarArm, Default)]
        pub struct Nested {
            #[arm(length = 1, mass = 1)]
            a: Revolute,
            #[arm(length = 0.5, mass = 2)]
            b: Revolute,
        }
    }
}

#[derive(PlanarArm, Default)]
struct Two {
    #[arm(length = 1, mass = 1)]
    a: Revolute,
    #[arm(length = 0.5, mass = 2)]
    b: Revolute,
}

#[derive(PlanarArm, Default)]
struct Three {
    #[arm(length = 1, mass = 1)]
    a: Revolute,
    #[arm(length = 0.5, mass = 2)]
    b: Revolute,
    #[arm(length = 0.25, mass = 1)]
    c: Revolute,
}

/// Every method of a two-link arm, compared with the plain `Two`.
fn same_as_two<A: PlanarArm<2> + ClosedFormIk<2, Target = Point2<f64>> + TipForce>(arm: &A) {
    let reference = Two::default();
    let q = SVector::<f64, 2>::new(0.3, -0.7);
    let qd = SVector::<f64, 2>::new(0.5, 0.2);
    let qdd = SVector::<f64, 2>::new(-0.1, 0.4);
    assert_eq!(arm.mass_matrix(&q), reference.mass_matrix(&q));
    assert_eq!(arm.coriolis(&q, &qd), reference.coriolis(&q, &qd));
    assert_eq!(
        arm.coriolis_matrix(&q, &qd),
        reference.coriolis_matrix(&q, &qd)
    );
    assert_eq!(arm.gravity(&q), reference.gravity(&q));
    let tau = arm.inverse_dynamics(&q, &qd, &qdd);
    assert_eq!(tau, reference.inverse_dynamics(&q, &qd, &qdd));
    assert_eq!(
        arm.forward_dynamics(&q, &qd, &tau),
        reference.forward_dynamics(&q, &qd, &tau)
    );
    assert!((arm.forward_dynamics(&q, &qd, &tau) - qdd).amax() < 1e-12);
    assert_eq!(
        arm.kinetic_energy(&q, &qd),
        reference.kinetic_energy(&q, &qd)
    );
    assert_eq!(arm.potential_energy(&q), reference.potential_energy(&q));
    assert_eq!(arm.tip_pose(&q), reference.tip_pose(&q));
    assert_eq!(arm.jacobian(&q), reference.jacobian(&q));
    assert_eq!(arm.joint_positions(&q), reference.joint_positions(&q));
    assert_eq!(arm.tip_polar(&q), reference.tip_polar(&q));
    let force = Vector2::new(1.0, -2.0);
    assert_eq!(
        arm.joint_torques(&q, &force, 0.5),
        reference.joint_torques(&q, &force, 0.5)
    );
    let target = Point2::new(0.9, 0.6);
    assert_eq!(
        arm.inverse_kinematics(&target),
        reference.inverse_kinematics(&target)
    );
    assert_eq!(arm.tip_force(&q, &tau), reference.tip_force(&q, &tau));
    assert!(tau.amax() < 100.0);
}

fn same_as_three<A: PlanarArm<3> + ClosedFormIk<3, Target = Isometry2<f64>> + TipWrench>(arm: &A) {
    let reference = Three::default();
    let q = SVector::<f64, 3>::new(0.3, -0.7, 1.2);
    let qd = SVector::<f64, 3>::new(0.5, 0.2, -0.3);
    let tau = SVector::<f64, 3>::new(1.0, -0.5, 0.25);
    assert_eq!(
        arm.forward_dynamics(&q, &qd, &tau),
        reference.forward_dynamics(&q, &qd, &tau)
    );
    assert_eq!(arm.mass_matrix(&q), reference.mass_matrix(&q));
    assert_eq!(arm.tip_pose(&q), reference.tip_pose(&q));
    let pose = reference.tip_pose(&q);
    assert_eq!(
        arm.inverse_kinematics(&pose),
        reference.inverse_kinematics(&pose)
    );
    assert_eq!(arm.tip_wrench(&q, &tau), reference.tip_wrench(&q, &tau));
    assert!(arm.forward_dynamics(&q, &qd, &tau).amax() < 1e3);
}

#[test]
fn user_items_named_like_generated_items_change_nothing() {
    same_as_two(&items::Two::default());
    same_as_three(&items::Three::default());
}

#[test]
fn arms_derive_in_nested_modules_and_function_bodies() {
    same_as_two(&outer::inner::Nested::default());

    #[derive(PlanarArm, Default)]
    struct Local {
        #[arm(length = 1, mass = 1)]
        a: Revolute,
        #[arm(length = 0.5, mass = 2)]
        b: Revolute,
    }
    same_as_two(&Local::default());

    // Locals of the enclosing function named like the generated ones.
    let q1 = 1e9_f64;
    let m11 = 1e9_f64;
    #[derive(PlanarArm, Default)]
    struct AfterLocals {
        #[arm(length = 1, mass = 1)]
        a: Revolute,
        #[arm(length = 0.5, mass = 2)]
        b: Revolute,
        #[arm(length = 0.25, mass = 1)]
        c: Revolute,
    }
    same_as_three(&AfterLocals::default());
    assert!(q1 == m11);
}

mod determinism {
    use ::planar_arm::symbolic::generate::{closed_forms, generate, Header};
    use ::planar_arm::symbolic::methods::Derived;
    use ::planar_arm::symbolic::ring::{int, ratio};
    use ::planar_arm::symbolic::{ArmSpec, LinkSpec, PayloadSpec};
    use quote::{format_ident, quote};

    fn arms() -> Vec<ArmSpec> {
        let mut arms: Vec<ArmSpec> = (1..=5).map(ArmSpec::paper).collect();
        arms.push(ArmSpec {
            links: vec![
                LinkSpec::rod(ratio(7, 20), ratio(3, 2)),
                LinkSpec {
                    inertia: int(0),
                    com: (ratio(-1, 7), int(0)),
                    ..LinkSpec::rod(ratio(1, 3), int(2))
                },
                LinkSpec {
                    inertia: ratio(1, 12),
                    com: (int(3), ratio(1, 5)),
                    armature: ratio(1, 50),
                    damping: ratio(1, 10),
                    frictionloss: ratio(3, 10),
                    ..LinkSpec::rod(ratio(9, 10), ratio(1, 1000))
                },
            ],
            gravity: planar_arm_core::down(ratio(981, 100)),
            payload: Some(PayloadSpec {
                mass: ratio(1, 2),
                inertia: ratio(1, 100),
                com: (ratio(1, 10), ratio(-1, 10)),
            }),
        });
        arms.push(ArmSpec {
            links: vec![LinkSpec::rod(ratio(1, 1000), int(1000)); 4],
            gravity: planar_arm_core::down(ratio(980_665, 100_000)),
            payload: None,
        });
        arms
    }

    fn expand(arm: &ArmSpec) -> String {
        let derived = Derived::new(arm);
        let header = Header::new(
            quote!(),
            quote!(Arm),
            quote!(),
            (1..=arm.links.len())
                .map(|i| format_ident!("l{i}"))
                .collect(),
        );
        let mut tokens = generate(&derived, &header).expect("emits");
        tokens.extend(closed_forms(&derived, &header));
        tokens.to_string()
    }

    #[test]
    fn the_same_arm_expands_to_the_same_tokens() {
        for arm in arms() {
            let first = expand(&arm);
            let second = expand(&arm.clone());
            assert!(!first.is_empty());
            assert!(
                first == second,
                "{} links: expansions differ",
                arm.links.len()
            );
        }
    }
}
