//! The numeric spatial reference and the derived PUMA 560 against MuJoCo: the fixture
//! `tests/data/mujoco_spatial_dynamics.txt`, written by hand with
//! `bench/mujoco/spatial_dynamics.py` (CI does not install MuJoCo), holds MuJoCo's mass matrix
//! (`mj_fullM`), bias forces (`qfrc_bias`, also at rest), passive damping (`qfrc_passive`),
//! inverse dynamics (`mj_inverse`) and forward dynamics (`mj_forward`'s `qacc` under a
//! `qfrc_applied`) of the PUMA 560 with armature and damping on three joints and of a random
//! seven-joint modified-DH arm with full inertia tensors, armature, damping and a tilted gravity.
//!
//! MuJoCo's armature is the crate's (on the diagonal of M), its damping the crate's `damping`
//! (`qfrc_passive = -damping qd`, which the crate's bias counts as a force to overcome);
//! frictionloss is zero in the fixture, as MuJoCo makes it a constraint.

use planar_arm::nalgebra::{Isometry3, Matrix3, SMatrix, SVector, Vector3};
use planar_arm::prelude::*;
use planar_arm::reference::spatial as reference;
use planar_arm::spatial::{JointGeometry, SpatialArm, SpatialJoint, SpatialLink, SpatialModel};
use planar_arm::Joint;

/// PUMA 560, Corke's standard DH parameters and mass properties, without armature or damping:
/// compared with MuJoCo's after adding the fixture's joint terms.
#[path = "../examples/support/puma_arm.rs"]
mod puma_arm;
use puma_arm::Puma560;

/// A fixture's lines after an `arm` line: key and numbers.
type Lines<'a> = Vec<(&'a str, Vec<f64>)>;

/// The arms of the fixture: header (`NAME CONVENTION N`) and lines.
fn arms() -> Vec<(String, Lines<'static>)> {
    let text = include_str!("data/mujoco_spatial_dynamics.txt");
    let mut arms: Vec<(String, Lines)> = Vec::new();
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let (key, rest) = line.split_once(' ').unwrap();
        if key == "arm" {
            arms.push((rest.to_string(), Vec::new()));
        } else {
            let numbers = rest
                .split_whitespace()
                .map(|x| x.parse().unwrap())
                .collect();
            arms.last_mut().unwrap().1.push((key, numbers));
        }
    }
    arms
}

/// The keys of one state's lines, in order.
const STATE: [&str; 10] = [
    "q",
    "qd",
    "qdd",
    "M",
    "bias",
    "gravity_torque",
    "passive",
    "tau",
    "applied",
    "qacc",
];

/// MuJoCo's numbers at one state.
struct State<const N: usize> {
    q: SVector<f64, N>,
    qd: SVector<f64, N>,
    qdd: SVector<f64, N>,
    m: SMatrix<f64, N, N>,
    bias: SVector<f64, N>,
    gravity: SVector<f64, N>,
    passive: SVector<f64, N>,
    tau: SVector<f64, N>,
    applied: SVector<f64, N>,
    qacc: SVector<f64, N>,
}

/// The model the fixture describes, and its states.
fn parse<const N: usize>(lines: &Lines, modified: bool) -> (SpatialModel<N>, Vec<State<N>>) {
    assert_eq!(lines[0].0, "gravity");
    let gravity = Vector3::from_column_slice(&lines[0].1);
    let joints = core::array::from_fn(|i| {
        let (key, v) = &lines[1 + i];
        assert_eq!((*key, v.len()), ("joint", 6));
        let (a, alpha, d, theta) = (v[0], v[1], v[2], v[3]);
        let geometry = if modified {
            JointGeometry::Mdh { a, alpha, d, theta }
        } else {
            JointGeometry::Dh { a, alpha, d, theta }
        };
        SpatialJoint {
            armature: v[4],
            damping: v[5],
            ..SpatialJoint::new(geometry, Joint::Revolute)
        }
    });
    let links = core::array::from_fn(|i| {
        let (key, v) = &lines[1 + N + i];
        assert_eq!((*key, v.len()), ("link", 10));
        SpatialLink {
            mass: v[0],
            com: Vector3::new(v[1], v[2], v[3]),
            inertia: Matrix3::new(v[4], v[7], v[8], v[7], v[5], v[9], v[8], v[9], v[6]),
        }
    });
    let model = SpatialModel::<N> {
        joints,
        links,
        gravity,
        tool: Isometry3::identity(),
        payload: None,
    };
    assert_eq!(model.check(), Ok(()));
    let body = &lines[1 + 2 * N..];
    assert_eq!(body.len() % STATE.len(), 0);
    let states = body
        .chunks(STATE.len())
        .map(|s| {
            for (line, key) in s.iter().zip(STATE) {
                assert_eq!(line.0, key);
            }
            let v = |k: usize| SVector::<f64, N>::from_column_slice(&s[k].1);
            State {
                q: v(0),
                qd: v(1),
                qdd: v(2),
                m: SMatrix::<f64, N, N>::from_row_slice(&s[3].1),
                bias: v(4),
                gravity: v(5),
                passive: v(6),
                tau: v(7),
                applied: v(8),
                qacc: v(9),
            }
        })
        .collect();
    (model, states)
}

/// `|ours - theirs| / |theirs|`, largest entries.
fn gap<const R: usize, const C: usize>(
    ours: &SMatrix<f64, R, C>,
    theirs: &SMatrix<f64, R, C>,
) -> f64 {
    (ours - theirs).amax() / theirs.amax()
}

/// The worst relative gaps over an arm's states: M, bias (`c + g + f`), gravity, friction,
/// inverse dynamics, forward dynamics.
#[derive(Debug, Default, Clone, Copy)]
struct Gaps([f64; 6]);

impl Gaps {
    fn take(&mut self, k: usize, gap: f64) {
        self.0[k] = self.0[k].max(gap);
    }

    fn report(&self, what: &str) {
        let g = &self.0;
        eprintln!(
            "{what}: M {:.1e}, bias {:.1e}, gravity {:.1e}, damping {:.1e}, inverse dynamics {:.1e}, forward dynamics {:.1e} (relative)",
            g[0], g[1], g[2], g[3], g[4], g[5]
        );
    }
}

/// `reference::spatial` at every state of one arm.
fn reference_gaps<const N: usize>(model: &SpatialModel<N>, states: &[State<N>]) -> Gaps {
    let mut gaps = Gaps::default();
    for s in states {
        gaps.take(0, gap(&reference::mass_matrix(model, &s.q), &s.m));
        // MuJoCo's bias has no damping; its passive force is minus the crate's friction.
        let bias = s.bias - s.passive;
        gaps.take(1, gap(&reference::bias_forces(model, &s.q, &s.qd), &bias));
        let c_g = reference::coriolis(model, &s.q, &s.qd) + reference::gravity(model, &s.q);
        gaps.take(1, gap(&c_g, &s.bias));
        gaps.take(2, gap(&reference::gravity(model, &s.q), &s.gravity));
        let still = reference::inverse_dynamics(model, &s.q, &SVector::zeros(), &SVector::zeros());
        gaps.take(2, gap(&still, &s.gravity));
        if s.passive.amax() > 0.0 {
            gaps.take(3, gap(&reference::friction(model, &s.qd), &-s.passive));
        }
        let tau = reference::inverse_dynamics(model, &s.q, &s.qd, &s.qdd);
        gaps.take(4, gap(&tau, &s.tau));
        let qacc = reference::forward_dynamics(model, &s.q, &s.qd, &s.applied);
        gaps.take(5, gap(&qacc, &s.qacc));
    }
    gaps
}

/// MuJoCo and the reference agree to rounding on both arms.
#[test]
fn the_reference_agrees_with_mujoco() {
    let arms = arms();
    assert_eq!(arms.len(), 2);
    for (header, lines) in &arms {
        let modified = header.contains(" mdh ");
        let (gaps, states) = if header.ends_with(" 6") {
            let (model, states) = parse::<6>(lines, modified);
            (reference_gaps(&model, &states), states.len())
        } else {
            assert!(header.ends_with(" 7"), "{header}");
            let (model, states) = parse::<7>(lines, modified);
            (reference_gaps(&model, &states), states.len())
        };
        gaps.report(&format!("reference, {header} ({states} states)"));
        assert_eq!(states, 6);
        // Measured (MuJoCo 4.0.1): 4e-15 at worst, though the random arm's tensors went
        // through MuJoCo's eigen-decomposition (1e-14 of each tensor); forward dynamics carries
        // cond(M), about 1e5 for the PUMA: 3e-13.
        let [m, bias, gravity, damping, tau, qacc] = gaps.0;
        assert!(m <= 2e-14, "{header}: M {m:e}");
        assert!(bias <= 2e-14, "{header}: bias {bias:e}");
        assert!(gravity <= 2e-14, "{header}: gravity {gravity:e}");
        assert!(damping <= 1e-15, "{header}: damping {damping:e}");
        assert!(tau <= 2e-14, "{header}: inverse dynamics {tau:e}");
        assert!(qacc <= 3e-12, "{header}: forward dynamics {qacc:e}");
    }
}

/// The derived PUMA (`examples/support/puma_arm.rs`, no armature or damping) is the fixture's
/// PUMA but for its joint terms; with them added, its generated methods give MuJoCo's numbers.
#[test]
fn the_derived_puma_agrees_with_mujoco() {
    let arms = arms();
    let (header, lines) = arms
        .iter()
        .find(|(h, _)| h.starts_with("Puma560 "))
        .unwrap();
    assert_eq!(header, "Puma560 dh 6");
    let (model, states) = parse::<6>(lines, false);
    let arm = Puma560::default();
    // Everything but armature and damping is the fixture's.
    let mut derived = arm.model();
    for (d, f) in derived.joints.iter_mut().zip(&model.joints) {
        assert_eq!((d.armature, d.damping, d.frictionloss), (0.0, 0.0, 0.0));
        d.armature = f.armature;
        d.damping = f.damping;
    }
    assert_eq!(derived, model);
    let armature =
        SMatrix::<f64, 6, 6>::from_diagonal(&SVector::from_fn(|i, _| model.joints[i].armature));
    let damping =
        SMatrix::<f64, 6, 6>::from_diagonal(&SVector::from_fn(|i, _| model.joints[i].damping));
    let mut gaps = Gaps::default();
    for s in &states {
        let m = arm.mass_matrix(&s.q) + armature;
        gaps.take(0, gap(&m, &s.m));
        let c_g = arm.coriolis(&s.q, &s.qd) + arm.gravity(&s.q);
        gaps.take(1, gap(&c_g, &s.bias));
        gaps.take(1, gap(&arm.bias(&s.q, &s.qd), &s.bias));
        let (m2, h) = arm.mass_matrix_and_bias(&s.q, &s.qd);
        gaps.take(0, gap(&(m2 + armature), &s.m));
        gaps.take(1, gap(&h, &s.bias));
        gaps.take(2, gap(&arm.gravity(&s.q), &s.gravity));
        gaps.take(3, gap(&(arm.friction(&s.qd) + damping * s.qd), &-s.passive));
        let tau = arm.inverse_dynamics(&s.q, &s.qd, &s.qdd) + armature * s.qdd + damping * s.qd;
        gaps.take(4, gap(&tau, &s.tau));
        // MuJoCo's qacc solves (M + A) qacc = applied - c - g - D qd, so the rigid arm under
        // applied - A qacc - D qd accelerates by it.
        let rigid = s.applied - armature * s.qacc - damping * s.qd;
        gaps.take(5, gap(&arm.forward_dynamics(&s.q, &s.qd, &rigid), &s.qacc));
    }
    gaps.report("derived Puma560");
    // Measured (MuJoCo 4.0.1): 1.4e-15, forward dynamics 2.8e-13.
    let [m, bias, gravity, damping, tau, qacc] = gaps.0;
    assert!(m <= 2e-14, "M {m:e}");
    assert!(bias <= 2e-14, "bias {bias:e}");
    assert!(gravity <= 2e-14, "gravity {gravity:e}");
    assert!(damping <= 1e-15, "damping {damping:e}");
    assert!(tau <= 2e-14, "inverse dynamics {tau:e}");
    assert!(qacc <= 3e-12, "forward dynamics {qacc:e}");
    assert_eq!(arm.friction(&states[0].qd), SVector::<f64, 6>::zeros());
}
