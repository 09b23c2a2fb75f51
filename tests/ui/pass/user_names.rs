//! User consts, statics and unit structs named like the locals of the generated code, in
//! scope where the arms are derived: a plain `let m11 = ...` would turn into a constant pattern
//! (E0005) or a forbidden shadowing (E0530). The derived arms must compile and compute exactly
//! what the same arms derived elsewhere compute.
#![deny(warnings)]
// Named like the generated locals on purpose; only their being in scope matters.
#![allow(non_upper_case_globals, non_camel_case_types, dead_code)]

use planar_arm::prelude::*;

/// Consts named like every generated local: with plain `let` bindings each would turn into a
/// constant pattern (E0005) or a forbidden shadowing (E0530).
mod consts {
    use planar_arm::prelude::*;

    pub const q: f64 = 1e9;
    pub const q1: f64 = 1e9;
    pub const q2: f64 = 1e9;
    pub const q3: f64 = 1e9;
    pub const qd: f64 = 1e9;
    pub const qd1: f64 = 1e9;
    pub const qd2: f64 = 1e9;
    pub const qd3: f64 = 1e9;
    pub const qdd: f64 = 1e9;
    pub const qdd1: f64 = 1e9;
    pub const qdd2: f64 = 1e9;
    pub const qdd3: f64 = 1e9;
    pub const tau: f64 = 1e9;
    pub const tau1: f64 = 1e9;
    pub const tau2: f64 = 1e9;
    pub const tau3: f64 = 1e9;
    pub const s1: f64 = 1e9;
    pub const s2: f64 = 1e9;
    pub const s3: f64 = 1e9;
    pub const c1: f64 = 1e9;
    pub const c2: f64 = 1e9;
    pub const c3: f64 = 1e9;
    pub const c12: f64 = 1e9;
    pub const s12: f64 = 1e9;
    pub const c23: f64 = 1e9;
    pub const c123: f64 = 1e9;
    pub const s123: f64 = 1e9;
    pub const t1: f64 = 1e9;
    pub const t2: f64 = 1e9;
    pub const t3: f64 = 1e9;
    pub const m11: f64 = 1e9;
    pub const m12: f64 = 1e9;
    pub const m22: f64 = 1e9;
    pub const m33: f64 = 1e9;
    pub const cm11: f64 = 1e9;
    pub const g1: f64 = 1e9;
    pub const cor1: f64 = 1e9;
    pub const rhs1: f64 = 1e9;
    pub const rhs2: f64 = 1e9;
    pub const det: f64 = 1e9;
    pub const d1: f64 = 1e9;
    pub const d2: f64 = 1e9;
    pub const inv_d1: f64 = 1e9;
    pub const l21: f64 = 1e9;
    pub const l31: f64 = 1e9;
    pub const l32: f64 = 1e9;
    pub const x: f64 = 1e9;
    pub const y: f64 = 1e9;
    pub const x1: f64 = 1e9;
    pub const y1: f64 = 1e9;
    pub const r2: f64 = 1e9;
    pub const u: f64 = 1e9;
    pub const v: f64 = 1e9;
    pub const j11: f64 = 1e9;
    pub const cos_phi: f64 = 1e9;
    pub const sin_phi: f64 = 1e9;
    pub const kinetic: f64 = 1e9;
    pub const potential: f64 = 1e9;
    pub const torque: f64 = 1e9;
    pub const force: f64 = 1e9;
    pub const target: f64 = 1e9;

    #[derive(PlanarArm, Default)]
    pub struct Two {
        #[arm(length = 1, mass = 1)]
        pub a: Revolute,
        #[arm(length = 0.5, mass = 2)]
        pub b: Revolute,
    }

    #[derive(PlanarArm, Default)]
    pub struct Three {
        #[arm(length = 1, mass = 1)]
        pub a: Revolute,
        #[arm(length = 0.5, mass = 2)]
        pub b: Revolute,
        #[arm(length = 0.25, mass = 1)]
        pub c: Revolute,
    }
}

/// The same names as statics, which no binding may shadow.
mod statics {
    use planar_arm::prelude::*;

    pub static q: f64 = 1e9;
    pub static q1: f64 = 1e9;
    pub static q2: f64 = 1e9;
    pub static qd: f64 = 1e9;
    pub static qd1: f64 = 1e9;
    pub static qd2: f64 = 1e9;
    pub static qdd: f64 = 1e9;
    pub static tau: f64 = 1e9;
    pub static tau1: f64 = 1e9;
    pub static s2: f64 = 1e9;
    pub static c2: f64 = 1e9;
    pub static c12: f64 = 1e9;
    pub static t1: f64 = 1e9;
    pub static m11: f64 = 1e9;
    pub static rhs1: f64 = 1e9;
    pub static det: f64 = 1e9;
    pub static x: f64 = 1e9;
    pub static y: f64 = 1e9;
    pub static u: f64 = 1e9;
    pub static v: f64 = 1e9;
    pub static torque: f64 = 1e9;
    pub static force: f64 = 1e9;
    pub static target: f64 = 1e9;

    #[derive(PlanarArm, Default)]
    pub struct Two {
        #[arm(length = 1, mass = 1)]
        pub a: Revolute,
        #[arm(length = 0.5, mass = 2)]
        pub b: Revolute,
    }
}

/// Unit structs, which a pattern would match instead of binding.
mod unit_structs {
    use planar_arm::prelude::*;

    pub struct q1;
    pub struct qd2;
    pub struct c2;
    pub struct s12;
    pub struct m11;
    pub struct m12;
    pub struct t1;
    pub struct det;
    pub struct rhs1;
    pub struct d1;
    pub struct l21;
    pub struct inv_d1;
    pub struct x;
    pub struct u;
    pub struct torque;
    pub struct target;

    #[derive(PlanarArm, Default)]
    pub struct Two {
        #[arm(length = 1, mass = 1)]
        pub a: Revolute,
        #[arm(length = 0.5, mass = 2)]
        pub b: Revolute,
    }

    #[derive(PlanarArm, Default)]
    pub struct Three {
        #[arm(length = 1, mass = 1)]
        pub a: Revolute,
        #[arm(length = 0.5, mass = 2)]
        pub b: Revolute,
        #[arm(length = 0.25, mass = 1)]
        pub c: Revolute,
    }
}

/// The same arms where no look-alike is in scope.
mod plain {
    use planar_arm::prelude::*;

    #[derive(PlanarArm, Default)]
    pub struct Two {
        #[arm(length = 1, mass = 1)]
        pub a: Revolute,
        #[arm(length = 0.5, mass = 2)]
        pub b: Revolute,
    }

    #[derive(PlanarArm, Default)]
    pub struct Three {
        #[arm(length = 1, mass = 1)]
        pub a: Revolute,
        #[arm(length = 0.5, mass = 2)]
        pub b: Revolute,
        #[arm(length = 0.25, mass = 1)]
        pub c: Revolute,
    }
}

fn same_as_two<A: PlanarArm<2> + ClosedFormIk<2, Target = Point2<f64>> + TipForce>(arm: &A) {
    let plain = plain::Two::default();
    let q = SVector::<f64, 2>::new(0.3, -0.7);
    let qd = SVector::<f64, 2>::new(0.5, 0.2);
    let qdd = SVector::<f64, 2>::new(-0.1, 0.4);
    let tau = arm.inverse_dynamics(&q, &qd, &qdd);
    assert_eq!(tau, plain.inverse_dynamics(&q, &qd, &qdd));
    assert_eq!(
        arm.forward_dynamics(&q, &qd, &tau),
        plain.forward_dynamics(&q, &qd, &tau)
    );
    assert_eq!(arm.mass_matrix(&q), plain.mass_matrix(&q));
    assert_eq!(arm.coriolis(&q, &qd), plain.coriolis(&q, &qd));
    assert_eq!(arm.coriolis_matrix(&q, &qd), plain.coriolis_matrix(&q, &qd));
    assert_eq!(arm.gravity(&q), plain.gravity(&q));
    assert_eq!(arm.kinetic_energy(&q, &qd), plain.kinetic_energy(&q, &qd));
    assert_eq!(arm.potential_energy(&q), plain.potential_energy(&q));
    assert_eq!(arm.tip_pose(&q), plain.tip_pose(&q));
    assert_eq!(arm.jacobian(&q), plain.jacobian(&q));
    assert_eq!(arm.joint_positions(&q), plain.joint_positions(&q));
    assert_eq!(arm.tip_polar(&q), plain.tip_polar(&q));
    let force = Vector2::new(1.0, -2.0);
    assert_eq!(
        arm.joint_torques(&q, &force, 0.5),
        plain.joint_torques(&q, &force, 0.5)
    );
    let target = Point2::new(0.9, 0.6);
    assert_eq!(
        arm.inverse_kinematics(&target),
        plain.inverse_kinematics(&target)
    );
    assert_eq!(arm.tip_force(&q, &tau), plain.tip_force(&q, &tau));
    // None of the look-alikes (1e9) leaked in.
    assert!(tau.amax() < 100.0);
}

fn same_as_three<A: PlanarArm<3> + ClosedFormIk<3, Target = Isometry2<f64>> + TipWrench>(arm: &A) {
    let plain = plain::Three::default();
    let q = SVector::<f64, 3>::new(0.3, -0.7, 1.2);
    let qd = SVector::<f64, 3>::new(0.5, 0.2, -0.3);
    let tau = SVector::<f64, 3>::new(1.0, -0.5, 0.25);
    let qdd = arm.forward_dynamics(&q, &qd, &tau);
    assert_eq!(qdd, plain.forward_dynamics(&q, &qd, &tau));
    assert!((arm.inverse_dynamics(&q, &qd, &qdd) - tau).amax() < 1e-12);
    assert_eq!(arm.mass_matrix(&q), plain.mass_matrix(&q));
    let pose = plain.tip_pose(&q);
    assert_eq!(arm.tip_pose(&q), pose);
    assert_eq!(
        arm.inverse_kinematics(&pose),
        plain.inverse_kinematics(&pose)
    );
    assert_eq!(arm.tip_wrench(&q, &tau), plain.tip_wrench(&q, &tau));
}

fn main() {
    same_as_two(&consts::Two::default());
    same_as_three(&consts::Three::default());
    same_as_two(&statics::Two::default());
    same_as_two(&unit_structs::Two::default());
    same_as_three(&unit_structs::Three::default());
}
