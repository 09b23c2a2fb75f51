//! Closed-form inverse kinematics of six-joint spatial arms (`planar_arm::spatial::SpatialIk`)
//! against the numeric reference's forward kinematics: every solution reproduces the target,
//! the configuration the target came from is among them, and the count matches what the
//! geometry allows.

use core::f64::consts::{FRAC_PI_2, PI};

use planar_arm::nalgebra::{Isometry3, SVector, Vector3};
use planar_arm::reference::spatial::tip_pose;
use planar_arm::spatial::{
    IkClass, JointGeometry, SpatialIk, SpatialJoint, SpatialLink, SpatialModel,
};
use planar_arm::{ArmError, Joint};

struct Rng(u64);

impl Rng {
    fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
    fn within(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
}

fn dh(a: f64, alpha: f64, d: f64, theta: f64, kind: Joint) -> SpatialJoint {
    SpatialJoint::new(JointGeometry::Dh { a, alpha, d, theta }, kind)
}

fn model(joints: [SpatialJoint; 6]) -> SpatialModel<6> {
    SpatialModel {
        joints,
        links: [SpatialLink::MASSLESS; 6],
        gravity: Vector3::new(0.0, 0.0, -9.81),
        tool: Isometry3::identity(),
        payload: None,
    }
}

/// The PUMA 560 (Corke's standard DH parameters).
fn puma() -> SpatialModel<6> {
    let r = Joint::Revolute;
    model([
        dh(0.0, FRAC_PI_2, 0.0, 0.0, r),
        dh(0.4318, 0.0, 0.0, 0.0, r),
        dh(0.0203, -FRAC_PI_2, 0.15005, 0.0, r),
        dh(0.0, FRAC_PI_2, 0.4318, 0.0, r),
        dh(0.0, -FRAC_PI_2, 0.0, 0.0, r),
        dh(0.0, 0.0, 0.0, 0.0, r),
    ])
}

/// The Stanford arm (Corke's model): the third joint slides, 0.3048 to 1.27 m.
fn stanford() -> SpatialModel<6> {
    let (r, p) = (Joint::Revolute, Joint::Prismatic);
    model([
        dh(0.0, -FRAC_PI_2, 0.412, 0.0, r),
        dh(0.0, FRAC_PI_2, 0.154, 0.0, r),
        dh(0.0203, 0.0, 0.0, -FRAC_PI_2, p),
        dh(0.0, -FRAC_PI_2, 0.0, 0.0, r),
        dh(0.0, FRAC_PI_2, 0.0, 0.0, r),
        dh(0.0, 0.0, 0.263, 0.0, r),
    ])
}

/// The UR5 (Universal Robots' standard DH parameters).
fn ur5() -> SpatialModel<6> {
    let r = Joint::Revolute;
    model([
        dh(0.0, FRAC_PI_2, 0.089159, 0.0, r),
        dh(-0.425, 0.0, 0.0, 0.0, r),
        dh(-0.39225, 0.0, 0.0, 0.0, r),
        dh(0.0, FRAC_PI_2, 0.10915, 0.0, r),
        dh(0.0, -FRAC_PI_2, 0.09465, 0.0, r),
        dh(0.0, 0.0, 0.0823, 0.0, r),
    ])
}

fn pose_error(a: &Isometry3<f64>, b: &Isometry3<f64>) -> f64 {
    let d = a.inverse() * b;
    d.translation.vector.norm().max(d.rotation.angle())
}

fn same_configuration(a: &SVector<f64, 6>, b: &SVector<f64, 6>, kinds: &[Joint; 6]) -> bool {
    (0..6).all(|i| match kinds[i] {
        Joint::Revolute => {
            let d = (a[i] - b[i]).rem_euclid(2.0 * PI);
            d.min(2.0 * PI - d) < 1e-7
        }
        Joint::Prismatic => (a[i] - b[i]).abs() < 1e-7,
    })
}

/// Random configurations: each solution reproduces the target to 1e-9, the configuration is
/// among them, and (at generic poses) there are `expected` of them. Returns how many targets
/// had each count.
fn round_trips(m: &SpatialModel<6>, class: IkClass, samples: usize, rng: &mut Rng) -> [usize; 9] {
    let ik = SpatialIk::of_model(m).expect("classified");
    assert_eq!(ik.class, class);
    let kinds = m.joints.map(|j| j.kind);
    let ranges = m.joints.map(|j| j.range);
    let mut counts = [0; 9];
    for _ in 0..samples {
        let q = SVector::<f64, 6>::from_fn(|i, _| match (kinds[i], ranges[i]) {
            (_, Some((lo, hi))) => rng.within(lo, hi),
            (Joint::Revolute, None) => rng.within(-PI, PI),
            (Joint::Prismatic, None) => rng.within(-1.0, 1.0),
        });
        let target = tip_pose(m, &q);
        let solutions = ik
            .solve(&target, &ranges)
            .unwrap_or_else(|e| panic!("{q}: {e}"));
        for s in solutions.iter() {
            let error = pose_error(&tip_pose(m, s), &target);
            assert!(error < 1e-9, "{q} -> {s}: {error}");
        }
        assert!(
            solutions.iter().any(|s| same_configuration(s, &q, &kinds)),
            "{q} not among {:?}",
            solutions.iter().collect::<Vec<_>>()
        );
        counts[solutions.len()] += 1;
    }
    counts
}

#[test]
fn the_puma_has_eight_solutions_at_generic_poses() {
    let counts = round_trips(&puma(), IkClass::SphericalWrist, 500, &mut Rng(1));
    assert!(counts[8] >= 495, "{counts:?}");
}

#[test]
fn the_stanford_arm_has_eight_or_four_within_its_slide() {
    let free = round_trips(&stanford(), IkClass::SlidingWrist, 300, &mut Rng(2));
    assert!(free[8] >= 295, "{free:?}");
    let mut limited = stanford();
    limited.joints[2] = limited.joints[2].with_range(0.3048, 1.27);
    let counts = round_trips(&limited, IkClass::SlidingWrist, 300, &mut Rng(3));
    assert!(counts[4] >= 295, "{counts:?}");
}

#[test]
fn the_ur5_has_up_to_eight() {
    let counts = round_trips(&ur5(), IkClass::ParallelTriple, 500, &mut Rng(4));
    // Near the edges of the work-space some elbow branches vanish: 8, 6, 4 or 2.
    assert!(
        counts[8] >= 300 && counts[1..].iter().step_by(2).all(|&c| c == 0),
        "{counts:?}"
    );
}

/// The solutions an independent solver finds for `target`: damped least squares on the
/// reference's forward kinematics and geometric Jacobian from many random starts, converged
/// ones kept, duplicates merged.
fn by_search(
    m: &SpatialModel<6>,
    target: &Isometry3<f64>,
    starts: usize,
    rng: &mut Rng,
) -> Vec<SVector<f64, 6>> {
    use planar_arm::nalgebra::SMatrix;
    let kinds = m.joints.map(|j| j.kind);
    // The error in base coordinates, as the Jacobian's rows are.
    let residual = |q: &SVector<f64, 6>| {
        let now = tip_pose(m, q);
        let mut r = SVector::<f64, 6>::zeros();
        r.fixed_rows_mut::<3>(0)
            .copy_from(&(target.translation.vector - now.translation.vector));
        r.fixed_rows_mut::<3>(3)
            .copy_from(&(target.rotation * now.rotation.inverse()).scaled_axis());
        r
    };
    let mut found: Vec<SVector<f64, 6>> = Vec::new();
    for _ in 0..starts {
        let mut q = SVector::<f64, 6>::from_fn(|_, _| rng.within(-PI, PI));
        for _ in 0..60 {
            let r = residual(&q);
            if r.norm() < 1e-13 {
                break;
            }
            let j = planar_arm::reference::spatial::jacobian(m, &q);
            let lambda = 1e-6 + r.norm().min(1e-2);
            let Some(inv) =
                (j.transpose() * j + SMatrix::<f64, 6, 6>::identity() * lambda).try_inverse()
            else {
                break;
            };
            q += inv * j.transpose() * r;
        }
        if residual(&q).norm() < 1e-10 && !found.iter().any(|f| same_configuration(f, &q, &kinds)) {
            found.push(q);
        }
    }
    found
}

#[test]
fn every_solution_the_geometry_allows_is_returned() {
    let mut rng = Rng(9);
    let m = ur5();
    let ik = SpatialIk::of_model(&m).unwrap();
    let kinds = m.joints.map(|j| j.kind);
    let (mut equal, mut total) = (0, 0);
    for _ in 0..8 {
        let q = SVector::<f64, 6>::from_fn(|_, _| rng.within(-PI, PI));
        let target = tip_pose(&m, &q);
        let closed = ik.solve(&target, &[None; 6]).unwrap();
        let searched = by_search(&m, &target, 100, &mut rng);
        for s in &searched {
            assert!(
                closed.iter().any(|c| same_configuration(c, s, &kinds)),
                "{q}: missed {s}"
            );
        }
        total += 1;
        equal += usize::from(searched.len() == closed.len());
    }
    eprintln!("{equal} of {total} counts agree");
    assert!(equal + 1 >= total, "{equal} of {total} counts agree");
}

#[test]
fn unreachable_and_nan_targets_are_errors() {
    let ik = SpatialIk::of_model(&puma()).unwrap();
    let far = Isometry3::translation(3.0, 0.0, 0.0);
    match ik.solve(&far, &[None; 6]) {
        Err(ArmError::OutOfReach { distance, unit, .. }) => assert!(distance > 1.0 && unit == "m"),
        other => panic!("{other:?}"),
    }
    let nan = Isometry3::translation(f64::NAN, 0.0, 0.0);
    assert_eq!(
        ik.solve(&nan, &[None; 6]),
        Err(ArmError::NonFinite { argument: "target" })
    );
}
