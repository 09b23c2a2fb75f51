//! `#[derive(SpatialArm)]` against the numeric reference (a product of 4x4 transformations
//! built at run time from hand-written models, not from the derive's): the PUMA 560 in each of
//! the three conventions, the Stanford arm, the UR5, the Panda, and arms with arbitrary twists,
//! slides and run-time parameters; the Jacobian and gravity against finite differences; the
//! closed-form inverse kinematics of the six-joint arms.

use core::f64::consts::{FRAC_PI_2, FRAC_PI_3, FRAC_PI_4, FRAC_PI_6, PI};

use planar_arm::nalgebra::{Isometry3, Matrix3, SVector, Translation3, UnitQuaternion, Vector3};
use planar_arm::prelude::*;
use planar_arm::reference::spatial as reference;
use planar_arm::spatial::{
    JointGeometry, SpatialArm, SpatialIk, SpatialJoint, SpatialLink, SpatialModel,
};
use planar_arm::{ArmError, Joint};

/// PUMA 560, standard Denavit-Hartenberg parameters and mass properties (Corke's model), as
/// `examples/puma.rs` has it.
#[path = "../examples/support/puma_arm.rs"]
mod puma_arm;
use puma_arm::Puma560;

/// The same PUMA in modified (Craig) parameters: joint i carries link i-1's `a` and `alpha`
/// (`Rx(alpha) Tx(a)` commutes into `Tx(a) Rx(alpha)`), so the tool pose is the same product.
#[derive(SpatialArm, Default)]
struct PumaMdh {
    #[arm(mdh(a = 0, alpha = 0, d = 0))]
    waist: Revolute,
    #[arm(mdh(a = 0, alpha = pi/2, d = 0))]
    shoulder: Revolute,
    #[arm(mdh(a = 0.4318, alpha = 0, d = 0.15005))]
    elbow: Revolute,
    #[arm(mdh(a = 0.0203, alpha = -pi/2, d = 0.4318))]
    wrist1: Revolute,
    #[arm(mdh(a = 0, alpha = pi/2, d = 0))]
    wrist2: Revolute,
    #[arm(mdh(a = 0, alpha = -pi/2, d = 0))]
    wrist3: Revolute,
}

/// The same PUMA as URDF joints: `Rx(alpha) Tx(a) Tz(d) = T(a, -d sin alpha, d cos alpha)
/// Rx(alpha)`, the rotation as a roll.
#[derive(SpatialArm, Default)]
struct PumaUrdf {
    #[arm(origin(xyz = (0, 0, 0)))]
    waist: Revolute,
    #[arm(origin(rpy = (pi/2, 0, 0)), axis = (0, 0, 1))]
    shoulder: Revolute,
    #[arm(origin(xyz = (0.4318, 0, 0.15005)))]
    elbow: Revolute,
    #[arm(origin(xyz = (0.0203, 0.4318, 0), rpy = (-pi/2, 0, 0)))]
    wrist1: Revolute,
    #[arm(origin(rpy = (pi/2, 0, 0)))]
    wrist2: Revolute,
    #[arm(origin(rpy = (-pi/2, 0, 0)))]
    wrist3: Revolute,
}

/// The Stanford arm (Corke's geometry): the third joint slides 0.3048 to 1.27 m. Masses are
/// made up, off every axis, to exercise gravity through the slide.
#[derive(SpatialArm, Default)]
struct Stanford {
    #[arm(dh(a = 0, alpha = -pi/2, d = 0.412), mass = 9.29, com = (0, 0.0175, -0.1105))]
    j1: Revolute,
    #[arm(dh(a = 0, alpha = pi/2, d = 0.154), mass = 5.01, com = (0.01, -0.1054, 0))]
    j2: Revolute,
    #[arm(dh(a = 0.0203, alpha = 0, theta = -pi/2), mass = 4.25, com = (0, 0.02, -0.6447),
          range = (0.3048, 1.27))]
    slide: Prismatic,
    #[arm(dh(a = 0, alpha = -pi/2, d = 0), mass = 1.08, com = (0, 0.092, -0.054))]
    j4: Revolute,
    #[arm(dh(a = 0, alpha = pi/2, d = 0), mass = 0.63, com = (0, 0.0566, 0.003))]
    j5: Revolute,
    #[arm(dh(a = 0, alpha = 0, d = 0.263), mass = 0.51, com = (0, 0, 0.1554))]
    j6: Revolute,
}

/// The UR5 (Universal Robots' DH parameters and published masses and centres of mass).
#[derive(SpatialArm, Default)]
struct Ur5 {
    #[arm(dh(alpha = pi/2, d = 0.089159), mass = 3.7, com = (0, -0.02561, 0.00193))]
    shoulder_pan: Revolute,
    #[arm(dh(a = -0.425), mass = 8.393, com = (0.2125, 0, 0.11336))]
    shoulder_lift: Revolute,
    #[arm(dh(a = -0.39225), mass = 2.275, com = (0.15, 0, 0.0265))]
    elbow: Revolute,
    #[arm(dh(alpha = pi/2, d = 0.10915), mass = 1.219, com = (0, -0.0018, 0.01634))]
    wrist1: Revolute,
    #[arm(dh(alpha = -pi/2, d = 0.09465), mass = 1.219, com = (0, 0.0018, 0.01634))]
    wrist2: Revolute,
    #[arm(dh(d = 0.0823), mass = 0.1879, com = (0, 0, -0.001159))]
    wrist3: Revolute,
}

/// The Franka Emika Panda (Franka's modified DH parameters, the flange 0.107 m along the last
/// axis); seven joints, so no closed form.
#[derive(SpatialArm, Default)]
#[arm(tool(xyz = (0, 0, 0.107)))]
struct Panda {
    #[arm(mdh(d = 0.333), mass = 4.97, com = (0.0039, 0.0021, -0.0476))]
    j1: Revolute,
    #[arm(mdh(alpha = -pi/2), mass = 0.646, com = (-0.0031, -0.0287, 0.0034))]
    j2: Revolute,
    #[arm(mdh(alpha = pi/2, d = 0.316), mass = 3.228, com = (0.0275, 0.0392, -0.0665))]
    j3: Revolute,
    #[arm(mdh(a = 0.0825, alpha = pi/2), mass = 3.587, com = (-0.0532, 0.1044, 0.0274))]
    j4: Revolute,
    #[arm(mdh(a = -0.0825, alpha = -pi/2, d = 0.384), mass = 1.226, com = (-0.0118, 0.0414, -0.0384))]
    j5: Revolute,
    #[arm(mdh(alpha = pi/2), mass = 1.666, com = (0.0601, -0.0141, -0.0105))]
    j6: Revolute,
    #[arm(mdh(a = 0.088, alpha = pi/2), mass = 0.735, com = (0.0105, 0.0043, 0.0617))]
    j7: Revolute,
}

/// Standard parameters with twists that are not multiples of pi/2 (their cosines and sines
/// enter as constants), angle offsets, a slide, and lengths and masses read at run time.
#[derive(SpatialArm)]
#[arm(gravity = (0.5, -1, -9.81), tool(xyz = (0.05, 0, self.flange), rpy = (0.1, -0.2, 0.3)))]
struct OddDh {
    reach: f64,
    flange: f64,
    load: f64,
    #[arm(dh(a = self.reach, alpha = 0.3, d = 0.2, theta = pi/6), mass = 2, com = (-0.1, 0.02, 0.03),
          armature = 0.05, damping = 0.3, frictionloss = 0.2)]
    j1: Revolute,
    #[arm(dh(a = 0.25, alpha = pi/3, d = -0.05, theta = 0.2), mass = self.load, com = (0.01, self.reach, 0),
          armature = 0.4, damping = 1.5)]
    j2: Prismatic,
    #[arm(dh(a = 2 * self.reach - 0.1, alpha = -2*pi/5), mass = 1.5, com = (0.1, 0, -0.02),
          inertia(xx = 0.02, yy = 0.03, zz = 0.025, xy = 0.004, xz = -0.002, yz = 0.001))]
    j3: Revolute,
    #[arm(dh(a = 0.1, alpha = pi/4, d = 0.07), mass = 0.5, com = (0, 0.03, 0.05))]
    j4: Revolute,
}

/// Modified parameters, a slide first and a twist of 0.7 rad.
#[derive(SpatialArm, Default)]
struct OddMdh {
    #[arm(mdh(a = 0.1, alpha = 0.7, d = 0.3), mass = 1, com = (0, 0.1, 0))]
    j1: Prismatic,
    #[arm(mdh(a = 0.4, alpha = -pi/2, theta = -pi/4), mass = 2, com = (0.2, 0, 0.01))]
    j2: Revolute,
    #[arm(mdh(a = 0.3, alpha = pi/6, d = 0.05), mass = 0.7, com = (0.1, 0.01, 0))]
    j3: Revolute,
}

/// URDF joints with rotated origins and axes that are not coordinate axes: (1, 2, 2) has an
/// exact unit vector, (1, 1, 0) does not.
#[derive(SpatialArm, Default)]
#[arm(tool(rpy = (0, pi/2, 0)))]
struct OddUrdf {
    #[arm(origin(xyz = (0, 0, 0.3), rpy = (0.1, -0.2, 0.3)), axis = (1, 1, 0), mass = 1,
          com = (0.05, 0, 0.1),
          inertia(xx = 0.01, yy = 0.012, zz = 0.008, xy = -0.001, xz = 0.002, yz = 0.0005))]
    j1: Revolute,
    #[arm(origin(xyz = (0.2, 0.05, 0)), axis = (0, 1, 0), mass = 2, com = (0.1, 0, 0))]
    j2: Revolute,
    #[arm(origin(xyz = (0.3, 0, 0.02), rpy = (0, 0, pi/2)), axis = (1, 2, 2), mass = 0.8,
          com = (0, 0.1, 0.1))]
    j3: Revolute,
    #[arm(origin(xyz = (0, 0.1, 0)), axis = (0, 0, -1), mass = 0.5, com = (0.02, 0, -0.05),
          armature = 0.2, frictionloss = 0.5)]
    j4: Prismatic,
    #[arm(origin(rpy = (pi, 0, -pi/3)), mass = 0.2, com = (0, 0, 0.04))]
    j5: Revolute,
}

/// One joint about the base's z axis.
#[derive(SpatialArm, Default)]
struct Single {
    #[arm(dh(a = 0.5, alpha = pi/2), mass = 1, com = (-0.25, 0, 0))]
    j1: Revolute,
}

struct Rng(u64);

impl Rng {
    fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
    fn q<const N: usize>(&mut self) -> SVector<f64, N> {
        SVector::from_fn(|_, _| -PI + 2.0 * PI * self.unit())
    }
}

fn pose_gap(a: &Isometry3<f64>, b: &Isometry3<f64>) -> f64 {
    let d = a.inverse() * b;
    d.translation.vector.norm().max(d.rotation.angle())
}

// Hand-written models of the arms above, for the reference: the derive's own `model()` is
// compared with them, not trusted.

const R: Joint = Joint::Revolute;
const P: Joint = Joint::Prismatic;

fn dh(a: f64, alpha: f64, d: f64, theta: f64, kind: Joint) -> SpatialJoint {
    SpatialJoint::new(JointGeometry::Dh { a, alpha, d, theta }, kind)
}

fn mdh(a: f64, alpha: f64, d: f64, theta: f64, kind: Joint) -> SpatialJoint {
    SpatialJoint::new(JointGeometry::Mdh { a, alpha, d, theta }, kind)
}

fn urdf(xyz: [f64; 3], rpy: [f64; 3], axis: [f64; 3], kind: Joint) -> SpatialJoint {
    let v = |a: [f64; 3]| Vector3::new(a[0], a[1], a[2]);
    let geometry = JointGeometry::Urdf {
        xyz: v(xyz),
        rpy: v(rpy),
        axis: v(axis),
    };
    SpatialJoint::new(geometry, kind)
}

fn link(mass: f64, com: [f64; 3], inertia: [f64; 3]) -> SpatialLink {
    SpatialLink {
        mass,
        com: Vector3::new(com[0], com[1], com[2]),
        inertia: Matrix3::from_diagonal(&Vector3::new(inertia[0], inertia[1], inertia[2])),
    }
}

fn massless<const N: usize>() -> [SpatialLink; N] {
    [SpatialLink::MASSLESS; N]
}

fn model<const N: usize>(joints: [SpatialJoint; N], links: [SpatialLink; N]) -> SpatialModel<N> {
    SpatialModel {
        joints,
        links,
        gravity: Vector3::new(0.0, 0.0, -9.81),
        tool: Isometry3::identity(),
        payload: None,
    }
}

fn tool(xyz: [f64; 3], rpy: [f64; 3]) -> Isometry3<f64> {
    Isometry3::from_parts(
        Translation3::new(xyz[0], xyz[1], xyz[2]),
        UnitQuaternion::from_euler_angles(rpy[0], rpy[1], rpy[2]),
    )
}

fn puma_model() -> SpatialModel<6> {
    let h = FRAC_PI_2;
    model(
        [
            dh(0.0, h, 0.0, 0.0, R),
            dh(0.4318, 0.0, 0.0, 0.0, R),
            dh(0.0203, -h, 0.15005, 0.0, R),
            dh(0.0, h, 0.4318, 0.0, R),
            dh(0.0, -h, 0.0, 0.0, R),
            dh(0.0, 0.0, 0.0, 0.0, R),
        ],
        [
            link(0.0, [0.0; 3], [0.0, 0.35, 0.0]),
            link(17.4, [-0.3638, 0.006, 0.2275], [0.13, 0.524, 0.539]),
            link(4.8, [-0.0203, -0.0141, 0.07], [0.066, 0.086, 0.0125]),
            link(0.82, [0.0, 0.019, 0.0], [1.8e-3, 1.3e-3, 1.8e-3]),
            link(0.34, [0.0; 3], [0.3e-3, 0.4e-3, 0.3e-3]),
            link(0.09, [0.0, 0.0, 0.032], [0.15e-3, 0.15e-3, 0.04e-3]),
        ],
    )
}

fn puma_mdh_model() -> SpatialModel<6> {
    let h = FRAC_PI_2;
    model(
        [
            mdh(0.0, 0.0, 0.0, 0.0, R),
            mdh(0.0, h, 0.0, 0.0, R),
            mdh(0.4318, 0.0, 0.15005, 0.0, R),
            mdh(0.0203, -h, 0.4318, 0.0, R),
            mdh(0.0, h, 0.0, 0.0, R),
            mdh(0.0, -h, 0.0, 0.0, R),
        ],
        massless(),
    )
}

fn puma_urdf_model() -> SpatialModel<6> {
    let (h, z) = (FRAC_PI_2, [0.0, 0.0, 1.0]);
    model(
        [
            urdf([0.0; 3], [0.0; 3], z, R),
            urdf([0.0; 3], [h, 0.0, 0.0], z, R),
            urdf([0.4318, 0.0, 0.15005], [0.0; 3], z, R),
            urdf([0.0203, 0.4318, 0.0], [-h, 0.0, 0.0], z, R),
            urdf([0.0; 3], [h, 0.0, 0.0], z, R),
            urdf([0.0; 3], [-h, 0.0, 0.0], z, R),
        ],
        massless(),
    )
}

fn stanford_model() -> SpatialModel<6> {
    let h = FRAC_PI_2;
    let mut slide = dh(0.0203, 0.0, 0.0, -h, P);
    slide.range = Some((0.3048, 1.27));
    model(
        [
            dh(0.0, -h, 0.412, 0.0, R),
            dh(0.0, h, 0.154, 0.0, R),
            slide,
            dh(0.0, -h, 0.0, 0.0, R),
            dh(0.0, h, 0.0, 0.0, R),
            dh(0.0, 0.0, 0.263, 0.0, R),
        ],
        [
            link(9.29, [0.0, 0.0175, -0.1105], [0.0; 3]),
            link(5.01, [0.01, -0.1054, 0.0], [0.0; 3]),
            link(4.25, [0.0, 0.02, -0.6447], [0.0; 3]),
            link(1.08, [0.0, 0.092, -0.054], [0.0; 3]),
            link(0.63, [0.0, 0.0566, 0.003], [0.0; 3]),
            link(0.51, [0.0, 0.0, 0.1554], [0.0; 3]),
        ],
    )
}

fn ur5_model() -> SpatialModel<6> {
    let h = FRAC_PI_2;
    model(
        [
            dh(0.0, h, 0.089159, 0.0, R),
            dh(-0.425, 0.0, 0.0, 0.0, R),
            dh(-0.39225, 0.0, 0.0, 0.0, R),
            dh(0.0, h, 0.10915, 0.0, R),
            dh(0.0, -h, 0.09465, 0.0, R),
            dh(0.0, 0.0, 0.0823, 0.0, R),
        ],
        [
            link(3.7, [0.0, -0.02561, 0.00193], [0.0; 3]),
            link(8.393, [0.2125, 0.0, 0.11336], [0.0; 3]),
            link(2.275, [0.15, 0.0, 0.0265], [0.0; 3]),
            link(1.219, [0.0, -0.0018, 0.01634], [0.0; 3]),
            link(1.219, [0.0, 0.0018, 0.01634], [0.0; 3]),
            link(0.1879, [0.0, 0.0, -0.001159], [0.0; 3]),
        ],
    )
}

fn panda_model() -> SpatialModel<7> {
    let h = FRAC_PI_2;
    let mut m = model(
        [
            mdh(0.0, 0.0, 0.333, 0.0, R),
            mdh(0.0, -h, 0.0, 0.0, R),
            mdh(0.0, h, 0.316, 0.0, R),
            mdh(0.0825, h, 0.0, 0.0, R),
            mdh(-0.0825, -h, 0.384, 0.0, R),
            mdh(0.0, h, 0.0, 0.0, R),
            mdh(0.088, h, 0.0, 0.0, R),
        ],
        [
            link(4.97, [0.0039, 0.0021, -0.0476], [0.0; 3]),
            link(0.646, [-0.0031, -0.0287, 0.0034], [0.0; 3]),
            link(3.228, [0.0275, 0.0392, -0.0665], [0.0; 3]),
            link(3.587, [-0.0532, 0.1044, 0.0274], [0.0; 3]),
            link(1.226, [-0.0118, 0.0414, -0.0384], [0.0; 3]),
            link(1.666, [0.0601, -0.0141, -0.0105], [0.0; 3]),
            link(0.735, [0.0105, 0.0043, 0.0617], [0.0; 3]),
        ],
    );
    m.tool = tool([0.0, 0.0, 0.107], [0.0; 3]);
    m
}

fn odd_dh() -> OddDh {
    OddDh {
        reach: 0.35,
        flange: 0.12,
        load: 0.8,
        j1: Revolute,
        j2: Prismatic,
        j3: Revolute,
        j4: Revolute,
    }
}

fn odd_dh_model() -> SpatialModel<4> {
    let mut m = model(
        [
            dh(0.35, 0.3, 0.2, FRAC_PI_6, R),
            dh(0.25, FRAC_PI_3, -0.05, 0.2, P),
            dh(0.6, -2.0 * PI / 5.0, 0.0, 0.0, R),
            dh(0.1, FRAC_PI_4, 0.07, 0.0, R),
        ],
        [
            link(2.0, [-0.1, 0.02, 0.03], [0.0; 3]),
            link(0.8, [0.01, 0.35, 0.0], [0.0; 3]),
            link(1.5, [0.1, 0.0, -0.02], [0.0; 3]),
            link(0.5, [0.0, 0.03, 0.05], [0.0; 3]),
        ],
    );
    m.gravity = Vector3::new(0.5, -1.0, -9.81);
    m.tool = tool([0.05, 0.0, 0.12], [0.1, -0.2, 0.3]);
    (
        m.joints[0].armature,
        m.joints[0].damping,
        m.joints[0].frictionloss,
    ) = (0.05, 0.3, 0.2);
    (m.joints[1].armature, m.joints[1].damping) = (0.4, 1.5);
    m.links[2].inertia = Matrix3::new(
        0.02, 0.004, -0.002, 0.004, 0.03, 0.001, -0.002, 0.001, 0.025,
    );
    m
}

fn odd_mdh_model() -> SpatialModel<3> {
    model(
        [
            mdh(0.1, 0.7, 0.3, 0.0, P),
            mdh(0.4, -FRAC_PI_2, 0.0, -FRAC_PI_4, R),
            mdh(0.3, FRAC_PI_6, 0.05, 0.0, R),
        ],
        [
            link(1.0, [0.0, 0.1, 0.0], [0.0; 3]),
            link(2.0, [0.2, 0.0, 0.01], [0.0; 3]),
            link(0.7, [0.1, 0.01, 0.0], [0.0; 3]),
        ],
    )
}

fn odd_urdf_model() -> SpatialModel<5> {
    let mut m = model(
        [
            urdf([0.0, 0.0, 0.3], [0.1, -0.2, 0.3], [1.0, 1.0, 0.0], R),
            urdf([0.2, 0.05, 0.0], [0.0; 3], [0.0, 1.0, 0.0], R),
            urdf([0.3, 0.0, 0.02], [0.0, 0.0, FRAC_PI_2], [1.0, 2.0, 2.0], R),
            urdf([0.0, 0.1, 0.0], [0.0; 3], [0.0, 0.0, -1.0], P),
            urdf([0.0; 3], [PI, 0.0, -FRAC_PI_3], [0.0, 0.0, 1.0], R),
        ],
        [
            link(1.0, [0.05, 0.0, 0.1], [0.0; 3]),
            link(2.0, [0.1, 0.0, 0.0], [0.0; 3]),
            link(0.8, [0.0, 0.1, 0.1], [0.0; 3]),
            link(0.5, [0.02, 0.0, -0.05], [0.0; 3]),
            link(0.2, [0.0, 0.0, 0.04], [0.0; 3]),
        ],
    );
    m.tool = tool([0.0; 3], [0.0, FRAC_PI_2, 0.0]);
    m.links[0].inertia = Matrix3::new(
        0.01, -0.001, 0.002, -0.001, 0.012, 0.0005, 0.002, 0.0005, 0.008,
    );
    (m.joints[3].armature, m.joints[3].frictionloss) = (0.2, 0.5);
    m
}

fn single_model() -> SpatialModel<1> {
    model(
        [dh(0.5, FRAC_PI_2, 0.0, 0.0, R)],
        [link(1.0, [-0.25, 0.0, 0.0], [0.0; 3])],
    )
}

/// The derive's `model()` describes the arm it was given: same geometry (URDF axes compared
/// after normalising), links, gravity and tool.
fn same_model<const N: usize>(derived: &SpatialModel<N>, hand: &SpatialModel<N>) {
    let close = |a: f64, b: f64| (a - b).abs() < 1e-15;
    for (i, (a, b)) in derived.joints.iter().zip(hand.joints.iter()).enumerate() {
        assert_eq!(a.kind, b.kind, "joint {i}");
        assert_eq!(a.range, b.range, "joint {i}");
        let pose = |j: &SpatialJoint| j.geometry.transform(j.kind, 0.37);
        assert!(pose_gap(&pose(a), &pose(b)) < 1e-15, "joint {i}");
        let (ga, gb) = (&a.geometry, &b.geometry);
        assert_eq!(
            core::mem::discriminant(ga),
            core::mem::discriminant(gb),
            "joint {i}"
        );
    }
    for (i, (a, b)) in derived.links.iter().zip(hand.links.iter()).enumerate() {
        assert!(close(a.mass, b.mass), "link {i} mass");
        assert!((a.com - b.com).amax() < 1e-15, "link {i} com");
        assert!((a.inertia - b.inertia).amax() < 1e-15, "link {i} inertia");
    }
    assert!(
        (derived.gravity - hand.gravity).amax() < 1e-15,
        "{} vs {}",
        derived.gravity,
        hand.gravity
    );
    assert!(pose_gap(&derived.tool, &hand.tool) < 1e-15);
}

fn random_q<const N: usize>(rng: &mut Rng, model: &SpatialModel<N>) -> SVector<f64, N> {
    SVector::from_fn(|i, _| match model.joints[i].range {
        Some((lo, hi)) => lo + (hi - lo) * rng.unit(),
        None if model.joints[i].kind == P => -0.5 + rng.unit(),
        None => -PI + 2.0 * PI * rng.unit(),
    })
}

/// Tool and link poses, Jacobian, gravity and potential energy against the reference's, at
/// 200 random configurations.
/// Every method against the reference at 200 random states; how many of them had a mass
/// matrix regular enough to check the forward dynamics.
fn against_reference<A: SpatialArm<N>, const N: usize>(
    arm: &A,
    hand: &SpatialModel<N>,
    rng: &mut Rng,
) -> usize {
    let mut solved = 0;
    same_model(&arm.model(), hand);
    for _ in 0..200 {
        let q = random_q(rng, hand);
        let tip = arm.tip_pose(&q);
        assert!(
            pose_gap(&tip, &reference::tip_pose(hand, &q)) < 1e-12,
            "{q}"
        );
        for (a, b) in arm
            .link_poses(&q)
            .iter()
            .zip(reference::link_poses(hand, &q).iter())
        {
            assert!(pose_gap(a, b) < 1e-12, "{q}");
        }
        let j = arm.jacobian(&q);
        assert!(
            (j - reference::jacobian(hand, &q)).amax() < 1e-12,
            "{q}: {j}"
        );
        let g = arm.gravity(&q);
        let gr = reference::gravity(hand, &q);
        assert!(
            (g - gr).amax() < 1e-12 * (1.0 + gr.amax()),
            "{q}: {g} vs {gr}"
        );
        let v = arm.potential_energy(&q);
        let vr = reference::potential_energy(hand, &q);
        assert!((v - vr).abs() < 1e-12 * (1.0 + v.abs()), "{q}");
        let (qd, qdd) = (rng.q::<N>(), rng.q::<N>() * 2.0);
        let tau = arm.inverse_dynamics(&q, &qd, &qdd);
        let tr = reference::inverse_dynamics(hand, &q, &qd, &qdd);
        assert!(
            (tau - tr).amax() < 1e-12 * (1.0 + tr.amax()),
            "{q} {qd} {qdd}: {tau} vs {tr}"
        );
        let m = arm.mass_matrix(&q);
        let mr = reference::mass_matrix(hand, &q);
        let scale = 1.0 + mr.amax();
        assert!((m - mr).amax() < 1e-12 * scale, "{q}: {m} vs {mr}");
        let c = arm.coriolis(&q, &qd);
        let cr = reference::coriolis(hand, &q, &qd);
        assert!(
            (c - cr).amax() < 1e-12 * (1.0 + cr.amax()),
            "{q}: {c} vs {cr}"
        );
        // The emitted derivatives (where the arm has them) against run-time jets.
        let (dq, dqd) = arm.inverse_dynamics_derivatives(&q, &qd, &qdd);
        let (jq, jqd) = planar_arm::Jet::inverse_dynamics_derivatives(arm, &q, &qd, &qdd);
        assert!((dq - jq).amax() < 1e-11 * (1.0 + jq.amax()), "{q}: dtau/dq");
        assert!(
            (dqd - jqd).amax() < 1e-11 * (1.0 + jqd.amax()),
            "{q}: dtau/dqd"
        );
        let cm = arm.coriolis_matrix(&q, &qd);
        assert!(
            (cm * qd - cr).amax() < 1e-12 * (1.0 + cr.amax()),
            "{q}: C qd vs {cr}"
        );
        let f = arm.friction(&qd);
        assert!((f - reference::friction(hand, &qd)).amax() < 1e-14, "{qd}");
        let h = arm.bias(&q, &qd);
        let hr = reference::bias_forces(hand, &q, &qd);
        assert!(
            (h - hr).amax() < 1e-12 * (1.0 + hr.amax()),
            "{q}: {h} vs {hr}"
        );
        let (m2, h2) = arm.mass_matrix_and_bias(&q, &qd);
        assert!((m2 - m).amax() < 1e-13 * scale && (h2 - h).amax() < 1e-13 * (1.0 + h.amax()));
        let t = arm.kinetic_energy(&q, &qd);
        let trf = reference::kinetic_energy(hand, &q, &qd);
        assert!((t - trf).abs() < 1e-12 * (1.0 + trf), "{t} vs {trf}");
        // The kinematic arms' last links are point masses on their own axes: M is singular
        // there, and the solve is checked where it is not.
        let eigenvalues = planar_arm::nalgebra::DMatrix::from_column_slice(N, N, mr.as_slice())
            .symmetric_eigenvalues();
        if eigenvalues.min() > 1e-9 * eigenvalues.max() {
            let back = arm.forward_dynamics(&q, &qd, &tr);
            let want = reference::forward_dynamics(hand, &q, &qd, &tr);
            assert!(
                (back - qdd).amax() < 1e-8 * (1.0 + qdd.amax()),
                "{q}: {back} vs {qdd}"
            );
            assert!((back - want).amax() < 1e-8 * (1.0 + want.amax()));
            assert_eq!(arm.try_forward_dynamics(&q, &qd, &tr), Ok(back));
            solved += 1;
        }
    }
    solved
}

/// The Jacobian against central differences of the tool pose (the angular rows from the
/// rotation between the two displaced poses) and gravity against central differences of the
/// potential energy: neither goes through the reference.
fn against_differences<A: SpatialArm<N>, const N: usize>(
    arm: &A,
    hand: &SpatialModel<N>,
    rng: &mut Rng,
) {
    let h = 1e-6;
    for _ in 0..50 {
        let q = random_q(rng, hand);
        let j = arm.jacobian(&q);
        let g = arm.gravity(&q);
        for i in 0..N {
            let (mut up, mut down) = (q, q);
            up[i] += h;
            down[i] -= h;
            let (a, b) = (arm.tip_pose(&up), arm.tip_pose(&down));
            let v = (a.translation.vector - b.translation.vector) / (2.0 * h);
            let w = (a.rotation * b.rotation.inverse()).scaled_axis() / (2.0 * h);
            for r in 0..3 {
                assert!((j[(r, i)] - v[r]).abs() < 1e-7, "{q}: linear {r},{i}");
                assert!((j[(r + 3, i)] - w[r]).abs() < 1e-7, "{q}: angular {r},{i}");
            }
            let dv = (arm.potential_energy(&up) - arm.potential_energy(&down)) / (2.0 * h);
            assert!(
                (g[i] - dv).abs() < 1e-6 * (1.0 + dv.abs()),
                "{q}: gravity {i}"
            );
        }
    }
}

/// [`against_reference`] and [`against_differences`]; the number of forward-dynamics checks.
fn check<A: SpatialArm<N>, const N: usize>(arm: &A, hand: &SpatialModel<N>, seed: u64) -> usize {
    let mut rng = Rng(seed);
    let solved = against_reference(arm, hand, &mut rng);
    against_differences(arm, hand, &mut rng);
    solved
}

#[test]
fn the_puma_in_each_convention_matches_the_reference() {
    // Corke's PUMA has inertia about every joint's axis: M is regular everywhere. The other
    // two conventions' PUMAs are massless (M = 0): kinematics only.
    assert_eq!(check(&Puma560::default(), &puma_model(), 1), 200);
    assert_eq!(check(&PumaMdh::default(), &puma_mdh_model(), 2), 0);
    assert_eq!(check(&PumaUrdf::default(), &puma_urdf_model(), 3), 0);
}

#[test]
fn the_three_conventions_describe_one_puma() {
    let (dh, mdh, urdf) = (Puma560::default(), PumaMdh::default(), PumaUrdf::default());
    let mut rng = Rng(4);
    for _ in 0..500 {
        let q: SVector<f64, 6> = rng.q();
        let tip = dh.tip_pose(&q);
        assert!(pose_gap(&tip, &mdh.tip_pose(&q)) < 1e-12, "{q}");
        assert!(pose_gap(&tip, &urdf.tip_pose(&q)) < 1e-12, "{q}");
        // Modified frame i is standard frame i-1 moved along and turned about x: same origin
        // up to `a`, same z axis.
        assert!((dh.jacobian(&q) - mdh.jacobian(&q)).amax() < 1e-12);
        assert!((dh.jacobian(&q) - urdf.jacobian(&q)).amax() < 1e-12);
    }
}

/// Tool positions Corke's Robotics Toolbox prints for its named PUMA poses (`p560.fkine`).
#[test]
fn the_puma_reaches_the_toolbox_poses() {
    let arm = Puma560::default();
    let (h, quarter) = (FRAC_PI_2, FRAC_PI_4);
    for (q, p) in [
        ([0.0; 6], [0.4521, -0.1500, 0.4318]),
        ([0.0, h, -h, 0.0, 0.0, 0.0], [0.0203, -0.1500, 0.8636]),
        (
            [0.0, quarter, PI, 0.0, quarter, 0.0],
            [0.5963, -0.1500, -0.0144],
        ),
    ] {
        let t = arm.tip_pose(&SVector::from(q)).translation.vector;
        for k in 0..3 {
            assert!((t[k] - p[k]).abs() < 1e-4, "{q:?}: {t}");
        }
    }
}

#[test]
fn the_stanford_arm_ur5_and_panda_match_the_reference() {
    check(&Stanford::default(), &stanford_model(), 5);
    check(&Ur5::default(), &ur5_model(), 6);
    check(&Panda::default(), &panda_model(), 7);
}

/// Zero poses worked by hand from the parameters: the UR5's tool at (a2 + a3, -(d4 + d6),
/// d1 - d5), the Panda's flange at (a4 + a5 + a7, 0, d1 + d3 + d5 - 0.107) pointing down.
#[test]
fn zero_poses_are_the_hand_computed_ones() {
    let ur5 = Ur5::default().tip_pose(&SVector::zeros());
    let expected = Vector3::new(-0.425 - 0.39225, -(0.10915 + 0.0823), 0.089159 - 0.09465);
    assert!((ur5.translation.vector - expected).amax() < 1e-15, "{ur5}");
    let panda = Panda::default().tip_pose(&SVector::zeros());
    let expected = Vector3::new(0.088, 0.0, 0.333 + 0.316 + 0.384 - 0.107);
    assert!(
        (panda.translation.vector - expected).amax() < 1e-15,
        "{panda}"
    );
    let down = panda.rotation * Vector3::z();
    assert!((down + Vector3::z()).amax() < 1e-15, "{down}");
}

#[test]
fn odd_twists_slides_and_run_time_parameters_match_the_reference() {
    assert!(check(&odd_dh(), &odd_dh_model(), 8) > 100);
    check(&OddMdh::default(), &odd_mdh_model(), 9);
    check(&OddUrdf::default(), &odd_urdf_model(), 10);
    check(&Single::default(), &single_model(), 11);
}

/// A run-time length changes the pose: the parameter is read, not frozen at compile time.
#[test]
fn run_time_parameters_are_read_at_each_call() {
    let mut arm = odd_dh();
    let mut hand = odd_dh_model();
    arm.reach = 0.5;
    arm.flange = 0.2;
    arm.load = 3.0;
    hand.joints[0].geometry = JointGeometry::Dh {
        a: 0.5,
        alpha: 0.3,
        d: 0.2,
        theta: FRAC_PI_6,
    };
    hand.joints[2].geometry = JointGeometry::Dh {
        a: 0.9,
        alpha: -2.0 * PI / 5.0,
        d: 0.0,
        theta: 0.0,
    };
    hand.links[1].mass = 3.0;
    hand.links[1].com.y = 0.5;
    hand.tool = tool([0.05, 0.0, 0.2], [0.1, -0.2, 0.3]);
    check(&arm, &hand, 12);
}

#[test]
fn every_method_takes_other_scalars() {
    let arm = Ur5::default();
    let q = SVector::<f64, 6>::from([0.3, -0.7, 1.1, 0.2, -0.4, 0.9]);
    let j32 = arm.jacobian(&q.map(|x| x as f32));
    let g32 = arm.gravity(&q.map(|x| x as f32));
    assert!((j32.map(f64::from) - arm.jacobian(&q)).amax() < 1e-5);
    assert!((g32.map(f64::from) - arm.gravity(&q)).amax() < 1e-4);
    // Dual numbers: the potential energy's derivatives are the gravity torques.
    use planar_arm::Jet;
    let dual = SVector::<Jet<6>, 6>::from_fn(|i, _| Jet::variable(q[i], i));
    let v = arm.potential_energy(&dual);
    let g = arm.gravity(&q);
    for i in 0..6 {
        assert!((v.eps[i] - g[i]).abs() < 1e-12 * (1.0 + g[i].abs()), "{i}");
    }
    // Dual accelerations: d tau / d qdd is the mass matrix (the reference's, from the links'
    // Jacobians), and the real parts are the f64 torques.
    let qd = SVector::<f64, 6>::from([0.5, -1.0, 0.3, 2.0, -0.2, 1.5]);
    let qdd = SVector::<f64, 6>::from([1.0, 0.2, -0.8, 0.0, 3.0, -1.0]);
    let tau = arm.inverse_dynamics(
        &q.map(Jet::constant),
        &qd.map(Jet::constant),
        &SVector::<Jet<6>, 6>::from_fn(|i, _| Jet::variable(qdd[i], i)),
    );
    let m = reference::mass_matrix(&arm.model(), &q);
    let plain = arm.inverse_dynamics(&q, &qd, &qdd);
    for i in 0..6 {
        assert!((tau[i].re - plain[i]).abs() < 1e-12 * (1.0 + plain[i].abs()));
        for k in 0..6 {
            assert!((tau[i].eps[k] - m[(i, k)]).abs() < 1e-12, "M{i}{k}");
        }
    }
    // Four states at once: each lane is the f64 result.
    use planar_arm::simd::{SimdValue, WideF64x4};
    let states: [SVector<f64, 6>; 4] = core::array::from_fn(|k| q.add_scalar(0.3 * k as f64));
    let batch = SVector::<WideF64x4, 6>::from_fn(|i, _| {
        WideF64x4::from(core::array::from_fn::<f64, 4, _>(|k| states[k][i]))
    });
    let jb = arm.jacobian(&batch);
    let zero = SVector::<WideF64x4, 6>::from_element(WideF64x4::from([0.0; 4]));
    let mb = arm.mass_matrix(&batch);
    let tb = arm.inverse_dynamics(&batch, &batch, &zero);
    for (k, state) in states.iter().enumerate() {
        let jk = jb.map(|x| x.extract(k));
        assert!((jk - arm.jacobian(state)).amax() < 1e-12, "lane {k}");
        let mk = mb.map(|x| x.extract(k));
        assert!((mk - arm.mass_matrix(state)).amax() < 1e-12, "lane {k}: M");
        let tk = tb.map(|x| x.extract(k));
        let want = arm.inverse_dynamics(state, state, &SVector::zeros());
        assert!(
            (tk - want).amax() < 1e-12 * (1.0 + want.amax()),
            "lane {k}: tau"
        );
    }
    // And in f32: the torques to single precision.
    let t32 = arm.inverse_dynamics(
        &q.map(|x| x as f32),
        &q.map(|x| x as f32),
        &SVector::zeros(),
    );
    let t64 = arm.inverse_dynamics(&q, &q, &SVector::zeros());
    assert!((t32.map(f64::from) - t64).amax() < 1e-4 * (1.0 + t64.amax()));
}

/// Every closed-form solution reproduces its target, the configuration the target came from is
/// among them, and the count is what the geometry allows, for targets made by the forward
/// kinematics of random configurations.
fn closed_form<A: SpatialArm<6>>(arm: &A, hand: &SpatialModel<6>, seed: u64, counts: &[usize]) {
    let ranges = hand.joints.map(|j| j.range);
    let runtime = SpatialIk::of_model(hand).expect("a closed-form class");
    let mut rng = Rng(seed);
    for _ in 0..300 {
        let q = random_q(&mut rng, hand);
        let target = arm.tip_pose(&q);
        let solutions = arm.inverse_kinematics(&target).unwrap();
        assert!(
            counts.contains(&solutions.len()),
            "{q}: {}",
            solutions.len()
        );
        assert_eq!(
            solutions.len(),
            runtime.solve(&target, &ranges).unwrap().len()
        );
        for s in solutions.iter() {
            assert!(pose_gap(&arm.tip_pose(s), &target) < 1e-9, "{q}: {s}");
        }
        let wrapped = |a: f64, b: f64| {
            let d = (a - b).rem_euclid(2.0 * PI);
            d.min(2.0 * PI - d)
        };
        let found = solutions.iter().any(|s| {
            (0..6).all(|i| match hand.joints[i].kind {
                Joint::Prismatic => (s[i] - q[i]).abs() < 1e-7,
                Joint::Revolute => wrapped(s[i], q[i]) < 1e-7,
            })
        });
        assert!(found, "{q} not among {:?}", &solutions[..]);
    }
}

#[test]
fn the_puma_has_eight_closed_form_solutions() {
    closed_form(&Puma560::default(), &puma_model(), 20, &[8]);
}

#[test]
fn the_stanford_arm_keeps_the_solutions_with_the_slide_in_range() {
    closed_form(&Stanford::default(), &stanford_model(), 21, &[2, 4]);
}

#[test]
fn the_ur5_has_up_to_eight_closed_form_solutions() {
    closed_form(&Ur5::default(), &ur5_model(), 22, &[2, 4, 6, 8]);
}

#[test]
fn bad_targets_give_errors() {
    let arm = Puma560::default();
    let far = Isometry3::translation(2.0, 0.0, 0.0);
    match arm.inverse_kinematics(&far) {
        Err(ArmError::OutOfReach { distance, .. }) => assert!(distance > 1.0, "{distance}"),
        other => panic!("{other:?}"),
    }
    let nan = Isometry3::translation(f64::NAN, 0.0, 0.0);
    assert!(matches!(
        arm.inverse_kinematics(&nan),
        Err(ArmError::NonFinite { .. })
    ));
    // The wrist singularity (q5 = 0): the solutions still reach the target and say they are
    // representatives.
    let q = SVector::<f64, 6>::from([0.2, 0.5, -0.3, 0.4, 0.0, 0.1]);
    let target = arm.tip_pose(&q);
    let solutions = arm.inverse_kinematics(&target).unwrap();
    assert!(solutions.singular(), "{:?}", &solutions[..]);
    assert!(!solutions.is_empty());
    // Each family's representative (the solutions whose wrist is singular; the other shoulder
    // and elbow postures reach the target with a regular wrist): the free q4 is 0, or pi for
    // its wrist flip.
    let families: Vec<_> = solutions.iter().filter(|s| s[4].abs() < 1e-9).collect();
    assert_eq!(families.len(), 2, "{:?}", &solutions[..]);
    assert!(families
        .iter()
        .all(|s| s[3] == 0.0 || (s[3].abs() - PI).abs() < 1e-12));
    for s in solutions.iter() {
        assert!(pose_gap(&arm.tip_pose(s), &target) < 1e-9, "{s}");
    }
    // The UR5's wrist singularity (q5 = 0: axes 4 and 6 parallel, with 2 and 3, four in a
    // family) and its stretched elbow (q3 = 0: the two elbow solutions meet).
    let ur5 = Ur5::default();
    for (q, singular) in [
        ([0.2, -0.9, 0.7, 0.4, 0.0, 0.1], true),
        ([0.2, -0.9, 0.0, 0.4, 0.8, 0.1], false),
    ] {
        let target = ur5.tip_pose(&SVector::from(q));
        let solutions = ur5.inverse_kinematics(&target).unwrap();
        assert_eq!(solutions.singular(), singular, "{q:?}");
        assert!(!solutions.is_empty(), "{q:?}");
        for s in solutions.iter() {
            assert!(pose_gap(&ur5.tip_pose(s), &target) < 1e-9, "{q:?}: {s}");
        }
    }
}

#[test]
fn arms_without_a_closed_form_say_so_and_search_instead() {
    let arm = Panda::default();
    let q = SVector::<f64, 7>::from([0.1, -0.4, 0.2, -2.0, 0.3, 1.6, 0.7]);
    let target = arm.tip_pose(&q);
    assert!(matches!(
        arm.inverse_kinematics(&target),
        Err(ArmError::NoClosedForm { .. })
    ));
    let seed = q.add_scalar(0.1);
    let options = DlsOptions {
        tolerance: 1e-10,
        ..DlsOptions::default()
    };
    let found = arm
        .inverse_kinematics_near(&target, &seed, &options)
        .unwrap();
    assert!(pose_gap(&arm.tip_pose(&found), &target) < 1e-9);
    assert!(matches!(
        odd_dh().inverse_kinematics(&Isometry3::identity()),
        Err(ArmError::NoClosedForm { .. })
    ));
}

/// `joint_torques` is the virtual work of the wrench (checked against differences of the tool
/// pose), and `tip_wrench` inverts it away from singular poses.
#[test]
fn statics_balance_the_wrench() {
    let arm = Ur5::default();
    let mut rng = Rng(30);
    let h = 1e-6;
    for _ in 0..100 {
        let q: SVector<f64, 6> = rng.q();
        let f = Vector3::new(rng.unit() - 0.5, rng.unit() - 0.5, rng.unit() - 0.5) * 20.0;
        let n = Vector3::new(rng.unit() - 0.5, rng.unit() - 0.5, rng.unit() - 0.5) * 5.0;
        let tau = arm.joint_torques(&q, &f, &n);
        for i in 0..6 {
            let (mut up, mut down) = (q, q);
            up[i] += h;
            down[i] -= h;
            let (a, b) = (arm.tip_pose(&up), arm.tip_pose(&down));
            let dp = a.translation.vector - b.translation.vector;
            let dtheta = (a.rotation * b.rotation.inverse()).scaled_axis();
            let work = (f.dot(&dp) + n.dot(&dtheta)) / (2.0 * h);
            assert!(
                (tau[i] - work).abs() < 1e-6 * (1.0 + work.abs()),
                "{q}: {i}"
            );
        }
        match arm.tip_wrench(&q, &tau) {
            Ok((f2, n2)) => {
                assert!(
                    (f2 - f).amax() < 1e-6 * 20.0 && (n2 - n).amax() < 1e-6 * 5.0,
                    "{q}"
                );
            }
            Err(ArmError::Singular { .. }) => {}
            Err(e) => panic!("{e}"),
        }
    }
    let stretched = SVector::<f64, 6>::from([0.3, 0.0, 0.0, 0.2, 0.5, 0.1]);
    assert!(matches!(
        arm.tip_wrench(&stretched, &SVector::zeros()),
        Err(ArmError::Singular { .. })
    ));
}

/// `EXACT` holds the multiplied-out formulas where they stay small, and they evaluate to what
/// the code computes; an arm with generic rotations is left as the product.
#[test]
fn exact_formulas_evaluate_to_the_pose_or_are_left_as_the_product() {
    use planar_arm::exact::eval;
    let arm = Puma560::default();
    let expansion = Puma560::EXACT.expansion.expect("right angles multiply out");
    let mut rng = Rng(40);
    for _ in 0..50 {
        let q: SVector<f64, 6> = rng.q();
        let pose = arm.tip_pose(&q).to_homogeneous();
        for r in 0..3 {
            for c in 0..4 {
                let v = eval(expansion.tip[r][c], q.as_slice(), &[]);
                assert!((v - pose[(r, c)]).abs() < 1e-12, "{r},{c}: {v}");
            }
        }
        let g = arm.gravity(&q);
        for i in 0..6 {
            let v = eval(expansion.gravity[i], q.as_slice(), &[]);
            assert!((v - g[i]).abs() < 1e-10 * (1.0 + g[i].abs()), "g{i}: {v}");
        }
    }
    assert!(OddUrdf::EXACT.expansion.is_none());
    assert!(OddUrdf::EXACT.to_string().contains("product"));
    let text = Puma560::EXACT.to_string();
    assert!(text.starts_with("R11 = "), "{text}");
}

/// Roll, pitch and yaw as the README documents them: nalgebra's `from_euler_angles` is URDF's
/// `Rz(yaw) Ry(pitch) Rx(roll)` and `euler_angles` inverts it; near gimbal lock the round trip
/// loses accuracy as the README says (at the lock itself nalgebra 0.34 can return angles of
/// another rotation, which the README warns of and this test does not pin).
#[test]
fn roll_pitch_yaw_are_urdf_s_and_lose_accuracy_near_gimbal_lock() {
    let (r, p, y): (f64, f64, f64) = (0.3, -0.7, 1.1);
    let q = UnitQuaternion::from_euler_angles(r, p, y);
    let urdf = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), y)
        * UnitQuaternion::from_axis_angle(&Vector3::y_axis(), p)
        * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), r);
    assert!(q.angle_to(&urdf) < 1e-15);
    let (r2, p2, y2) = q.euler_angles();
    assert!((r2 - r).abs() < 1e-12 && (p2 - p).abs() < 1e-12 && (y2 - y).abs() < 1e-12);
    // 1e-6 rad from the lock: the rotation survives the round trip to 1e-9.
    let mut rng = Rng(50);
    for _ in 0..1000 {
        let (r, y) = (-PI + 2.0 * PI * rng.unit(), -PI + 2.0 * PI * rng.unit());
        let near = UnitQuaternion::from_euler_angles(r, FRAC_PI_2 - 1e-6, y);
        let (a, b, c) = near.euler_angles();
        assert!(UnitQuaternion::from_euler_angles(a, b, c).angle_to(&near) < 1e-9);
    }
}

/// A massless arm (written for its kinematics) has M = 0: its forward dynamics cannot be
/// finite, and `try_forward_dynamics` says so; NaN input is named.
#[test]
fn singular_or_bad_dynamics_give_errors() {
    let q = SVector::<f64, 6>::from([0.1, -0.4, 0.3, 1.0, 0.5, -0.2]);
    let (qd, tau) = (SVector::repeat(0.5), SVector::repeat(1.0));
    assert_eq!(PumaMdh::default().mass_matrix(&q), SMatrixOf6::zeros());
    assert_eq!(
        PumaMdh::default().try_forward_dynamics(&q, &qd, &tau),
        Err(ArmError::NonFinite { argument: "result" })
    );
    let mut bad = q;
    bad[2] = f64::NAN;
    let puma = Puma560::default();
    assert_eq!(
        puma.try_forward_dynamics(&bad, &qd, &tau),
        Err(ArmError::NonFinite { argument: "q" })
    );
    assert_eq!(
        puma.try_inverse_dynamics(&q, &qd, &SVector::repeat(f64::INFINITY)),
        Err(ArmError::NonFinite { argument: "qdd" })
    );
    assert!(puma.try_forward_dynamics(&q, &qd, &tau).is_ok());
}

type SMatrixOf6 = planar_arm::nalgebra::SMatrix<f64, 6, 6>;
