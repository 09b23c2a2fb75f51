//! `#[derive(SpatialArm)]` against the numeric reference: the PUMA 560 written in each of the
//! three conventions, the Stanford arm and the UR5.

use core::f64::consts::PI;

use planar_arm::nalgebra::{Isometry3, SVector};
use planar_arm::prelude::*;
use planar_arm::reference::spatial as reference;
use planar_arm::spatial::SpatialArm;

/// PUMA 560, standard Denavit-Hartenberg parameters (Corke's model).
#[derive(SpatialArm, Default)]
#[arm(gravity = (0, 0, -9.81))]
struct Puma560 {
    #[arm(dh(a = 0, alpha = pi/2, d = 0), inertia(yy = 0.35))]
    waist: Revolute,
    #[arm(dh(a = 0.4318, alpha = 0, d = 0), mass = 17.4, com = (-0.3638, 0.006, 0.2275),
          inertia(xx = 0.13, yy = 0.524, zz = 0.539))]
    shoulder: Revolute,
    #[arm(dh(a = 0.0203, alpha = -pi/2, d = 0.15005), mass = 4.8, com = (-0.0203, -0.0141, 0.07),
          inertia(xx = 0.066, yy = 0.086, zz = 0.0125))]
    elbow: Revolute,
    #[arm(dh(a = 0, alpha = pi/2, d = 0.4318), mass = 0.82, com = (0, 0.019, 0),
          inertia(xx = 1.8e-3, yy = 1.3e-3, zz = 1.8e-3))]
    wrist1: Revolute,
    #[arm(dh(a = 0, alpha = -pi/2, d = 0), mass = 0.34, inertia(xx = 0.3e-3, yy = 0.4e-3, zz = 0.3e-3))]
    wrist2: Revolute,
    #[arm(dh(a = 0, alpha = 0, d = 0), mass = 0.09, com = (0, 0, 0.032),
          inertia(xx = 0.15e-3, yy = 0.15e-3, zz = 0.04e-3))]
    wrist3: Revolute,
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

fn against_reference<A: SpatialArm<N>, const N: usize>(arm: &A, rng: &mut Rng) {
    let model = arm.model();
    for _ in 0..200 {
        let q: SVector<f64, N> = rng.q();
        assert!(
            pose_gap(&arm.tip_pose(&q), &reference::tip_pose(&model, &q)) < 1e-12,
            "{q}"
        );
        for (a, b) in arm
            .link_poses(&q)
            .iter()
            .zip(reference::link_poses(&model, &q).iter())
        {
            assert!(pose_gap(a, b) < 1e-12, "{q}");
        }
        let j = arm.jacobian(&q);
        assert!(
            (j - reference::jacobian(&model, &q)).amax() < 1e-12,
            "{q}: {j}"
        );
        let g = arm.gravity(&q);
        let gr = reference::gravity(&model, &q);
        assert!(
            (g - gr).amax() < 1e-12 * (1.0 + gr.amax()),
            "{q}: {g} vs {gr}"
        );
        let v = arm.potential_energy(&q);
        assert!((v - reference::potential_energy(&model, &q)).abs() < 1e-12 * (1.0 + v.abs()));
    }
}

#[test]
fn the_puma_matches_the_reference() {
    against_reference(&Puma560::default(), &mut Rng(1));
}

#[test]
fn the_puma_has_eight_closed_form_solutions() {
    let arm = Puma560::default();
    let mut rng = Rng(2);
    for _ in 0..200 {
        let q: SVector<f64, 6> = rng.q();
        let target = arm.tip_pose(&q);
        let solutions = arm.inverse_kinematics(&target).unwrap();
        assert_eq!(solutions.len(), 8, "{q}");
        for s in solutions.iter() {
            assert!(pose_gap(&arm.tip_pose(s), &target) < 1e-9, "{q}: {s}");
        }
    }
}
