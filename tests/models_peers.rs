//! Arms derived from model files against the engines that read the same files: MuJoCo for the
//! DeepMind control suite's MJCF models, Pinocchio for the UR5 and Panda URDFs. The fixture
//! `tests/data/models_peers.txt` is written by hand with `bench/models/fixtures.py` (CI
//! installs neither engine): each engine's mass matrix, bias forces, gravity torques and
//! inverse dynamics with damping at three random states, `q` in MuJoCo's `qpos` (URDF's joint
//! values), which the derive reads without conversion.
//!
//! The same check holds the exporter to account: `tests/data/export_peers.txt`
//! (`bench/models/load_exports.py`) is MuJoCo's and Pinocchio's reading of the files
//! `to_mjcf` and `to_urdf` wrote (`tests/data/export/`), compared here with the arms that
//! wrote them.

#[path = "common/export_arms.rs"]
mod export_arms;

use planar_arm::nalgebra::{SMatrix, SVector};
use planar_arm::prelude::*;

#[derive(SpatialArm)]
#[arm(mjcf = "models/acrobot.xml")]
struct Acrobot;

#[derive(SpatialArm)]
#[arm(mjcf = "models/cartpole.xml")]
struct CartPole;

#[derive(SpatialArm)]
#[arm(mjcf = "models/pendulum.xml")]
struct Pendulum;

#[derive(SpatialArm)]
#[arm(mjcf = "models/reacher.xml")]
struct Reacher;

#[derive(SpatialArm)]
#[arm(mjcf = "models/hopper.xml")]
struct Hopper;

/// The reacher again, as a planar arm: its hinges turn about z, its links lie along x at
/// `qpos = 0`, and gravity is normal to its plane.
#[derive(PlanarArm)]
#[arm(mjcf = "models/reacher.xml")]
struct ReacherPlanar;

/// The acrobot, cart-pole and pendulum as planar arms: their hinges turn about y; the
/// acrobot's links stand up its plane's x at `qpos = 0`, so its gravity points along -x of the
/// plane; the cart-pole's plane has y = -z, so gravity points up its y.
#[derive(PlanarArm)]
#[arm(mjcf = "models/acrobot.xml")]
struct AcrobotPlanar;

#[derive(PlanarArm)]
#[arm(mjcf = "models/cartpole.xml")]
struct CartPolePlanar;

#[derive(PlanarArm)]
#[arm(mjcf = "models/pendulum.xml")]
struct PendulumPlanar;

/// The hopper and the six-link swimmer as planar arms: a floating base of two slides at right
/// angles (an `offset` of a quarter turn) and a hinge, all at one point, then the legs or the
/// body's links.
#[derive(PlanarArm)]
#[arm(mjcf = "models/hopper.xml")]
struct HopperPlanar;

#[derive(PlanarArm)]
#[arm(mjcf = "models/swimmer6.xml")]
struct Swimmer6Planar;

#[derive(SpatialArm)]
#[arm(mjcf = "models/swimmer6.xml")]
struct Swimmer6;

#[derive(SpatialArm)]
#[arm(urdf = "models/ur5.urdf")]
struct Ur5;

/// The Panda to its hand: the fingers hang beyond the tip and are locked, as Pinocchio's
/// `buildReducedModel` locks them in the fixture.
#[derive(SpatialArm)]
#[arm(urdf = "models/panda.urdf", tip = "panda_hand")]
struct Panda;

/// One arm's lines: key and numbers.
type Lines = Vec<(String, Vec<f64>)>;

const MODELS: &str = include_str!("data/models_peers.txt");
const EXPORTS: &str = include_str!("data/export_peers.txt");

fn arm(text: &str, name: &str) -> (Vec<String>, Lines) {
    let mut found: Option<(Vec<String>, Lines)> = None;
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let (key, rest) = line.split_once(' ').unwrap();
        match key {
            "arm" if rest == name => found = Some((Vec::new(), Vec::new())),
            "arm" if found.is_some() => break,
            _ => {}
        }
        let Some((joints, lines)) = found.as_mut() else {
            continue;
        };
        match key {
            "arm" => {}
            "joints" => *joints = rest.split_whitespace().map(str::to_string).collect(),
            _ => lines.push((
                key.to_string(),
                rest.split_whitespace()
                    .map(|x| x.parse().unwrap())
                    .collect(),
            )),
        }
    }
    found.unwrap_or_else(|| panic!("no arm `{name}` in the fixture"))
}

/// Relative to the larger entry, or to 0.01 (N, N m, kg m²) where all are smaller: a gravity
/// torque that is zero by symmetry comes out of MuJoCo's float rotations as 1e-14.
fn relative(a: &[f64], b: &[f64]) -> f64 {
    let scale = b.iter().fold(1e-2_f64, |m, x| m.max(x.abs()));
    a.iter()
        .zip(b)
        .fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()))
        / scale
}

/// Every state of the fixture to 1e-12 relative (of the quantity's largest entry): M, bias,
/// gravity, inverse dynamics, and forward dynamics of the engine's torques; returns the worst
/// difference. The engines' bias holds no friction and their inverse dynamics only the
/// viscous part (MuJoCo's frictionloss is a constraint, off in the fixtures): the arm's Coulomb
/// friction is taken out before comparing.
fn check<const N: usize, A: Dynamics<N>>(
    fixture: &str,
    arm: &A,
    names: [&str; N],
    name: &str,
) -> f64 {
    let (joints, lines) = self::arm(fixture, name);
    assert_eq!(joints, names, "{name}: the chain's joints, in order");
    let get = |k: usize, key: &str| -> &Vec<f64> {
        let (kk, v) = &lines[k];
        assert_eq!(kk, key);
        v
    };
    let mut worst = 0.0_f64;
    // gravity line, then 8 lines per state.
    for s in 0..3 {
        let k = 1 + 8 * s;
        let v = |key: &str, i: usize| SVector::<f64, N>::from_column_slice(get(k + i, key));
        let (q, qd, qdd) = (v("q", 0), v("qd", 1), v("qdd", 2));
        let m = SMatrix::<f64, N, N>::from_row_slice(get(k + 3, "M"));
        let viscous = v("damping", 6).component_mul(&qd);
        let coulomb = arm.friction(&qd) - viscous;
        let pairs = [
            (
                "M",
                arm.mass_matrix(&q).as_slice().to_vec(),
                m.as_slice().to_vec(),
            ),
            (
                "bias",
                (arm.bias(&q, &qd) - arm.friction(&qd)).as_slice().to_vec(),
                v("bias", 4).as_slice().to_vec(),
            ),
            (
                "gravity",
                arm.gravity(&q).as_slice().to_vec(),
                v("gravity_torque", 5).as_slice().to_vec(),
            ),
            (
                "tau",
                (arm.inverse_dynamics(&q, &qd, &qdd) - coulomb)
                    .as_slice()
                    .to_vec(),
                v("tau", 7).as_slice().to_vec(),
            ),
            // Forward dynamics: the engine's torques (with the Coulomb part MuJoCo leaves to
            // its constraints put back) give back the accelerations it was asked for.
            (
                "qdd",
                arm.forward_dynamics(&q, &qd, &(v("tau", 7) + coulomb))
                    .as_slice()
                    .to_vec(),
                qdd.as_slice().to_vec(),
            ),
        ];
        for (what, ours, theirs) in pairs {
            let d = relative(&ours, &theirs);
            assert!(
                d < 1e-12,
                "{name} state {s} {what}: {d:e}\n ours {ours:?}\n theirs {theirs:?}"
            );
            worst = worst.max(d);
        }
    }
    worst
}

#[test]
fn control_suite_models_match_mujoco() {
    let worst = [
        check(MODELS, &Acrobot, ["shoulder", "elbow"], "acrobot"),
        check(MODELS, &CartPole, ["slider", "hinge_1"], "cartpole"),
        check(MODELS, &Pendulum, ["hinge"], "pendulum"),
        check(MODELS, &Reacher, ["shoulder", "wrist"], "reacher"),
        check(MODELS, &ReacherPlanar, ["shoulder", "wrist"], "reacher"),
        check(MODELS, &AcrobotPlanar, ["shoulder", "elbow"], "acrobot"),
        check(MODELS, &CartPolePlanar, ["slider", "hinge_1"], "cartpole"),
        check(MODELS, &PendulumPlanar, ["hinge"], "pendulum"),
        check(
            MODELS,
            &HopperPlanar,
            ["rootx", "rootz", "rooty", "waist", "hip", "knee", "ankle"],
            "hopper",
        ),
        check(
            MODELS,
            &Swimmer6Planar,
            [
                "rootx", "rooty", "rootz", "joint_0", "joint_1", "joint_2", "joint_3", "joint_4",
            ],
            "swimmer6",
        ),
        check(
            MODELS,
            &Hopper,
            ["rootx", "rootz", "rooty", "waist", "hip", "knee", "ankle"],
            "hopper",
        ),
        check(
            MODELS,
            &Swimmer6,
            [
                "rootx", "rooty", "rootz", "joint_0", "joint_1", "joint_2", "joint_3", "joint_4",
            ],
            "swimmer6",
        ),
    ];
    eprintln!("worst relative difference to MuJoCo: {worst:?}");
    assert_eq!(Acrobot::JOINT_NAMES, ["shoulder", "elbow"]);
}

#[test]
fn industrial_urdfs_match_pinocchio() {
    let ur5 = check(MODELS, &Ur5, Ur5::JOINT_NAMES, "ur5");
    let panda = check(MODELS, &Panda, Panda::JOINT_NAMES, "panda");
    eprintln!("worst relative difference to Pinocchio: ur5 {ur5:e}, panda {panda:e}");
}

#[test]
fn exported_files_load_in_mujoco_and_pinocchio_as_the_arms_that_wrote_them() {
    use export_arms::{DhArm, MdhArm, OriginArm, PlanarExact, PlanarMix, PlanarTurned};
    let worst = [
        check(EXPORTS, &DhArm::default(), DhArm::JOINT_NAMES, "dh_arm.xml"),
        check(
            EXPORTS,
            &MdhArm::default(),
            MdhArm::JOINT_NAMES,
            "mdh_arm.xml",
        ),
        check(
            EXPORTS,
            &OriginArm::default(),
            OriginArm::JOINT_NAMES,
            "origin_arm.xml",
        ),
        check(EXPORTS, &Ur5, Ur5::JOINT_NAMES, "ur5.xml"),
        check(
            EXPORTS,
            &MdhArm::default(),
            MdhArm::JOINT_NAMES,
            "mdh_arm.urdf",
        ),
        check(EXPORTS, &Ur5, Ur5::JOINT_NAMES, "ur5.urdf"),
        // A planar arm's MJCF: its plane is MuJoCo's x-y plane, gravity along -y.
        check(
            EXPORTS,
            &PlanarMix::default(),
            PlanarMix::JOINT_NAMES,
            "planar_mix.xml",
        ),
        check(
            EXPORTS,
            &PlanarExact::default(),
            PlanarExact::JOINT_NAMES,
            "planar_exact.xml",
        ),
        // Offsets as turned bodies, a hinge about -z, springs and gravity off -y.
        check(
            EXPORTS,
            &PlanarTurned::default(),
            PlanarTurned::JOINT_NAMES,
            "planar_turned.xml",
        ),
    ];
    eprintln!("worst relative difference of the exports: {worst:?}");
    // The DH arm's URDF has no armature: Pinocchio's M misses exactly the 0.05 of `fore`.
    let (_, lines) = arm(EXPORTS, "dh_arm.urdf");
    let q = SVector::<f64, 3>::from_column_slice(&lines[1].1);
    let theirs = SMatrix::<f64, 3, 3>::from_row_slice(&lines[4].1);
    let missing = DhArm::default().mass_matrix(&q) - theirs;
    assert!((missing[(2, 2)] - 0.05).abs() < 1e-12, "{missing}");
    assert!(
        missing.abs().sum() - 0.05 < 1e-12,
        "only the armature of `fore` is missing: {missing}"
    );
}

/// A test arm with springs (`tests/data/springs.xml`): a hinge's `springref` in degrees, a
/// slide's in metres, a `ref` beside a `springref`, a hinge about an anchor.
#[derive(SpatialArm)]
#[arm(mjcf = "tests/data/springs.xml")]
struct Springs;

/// The same kind of arm in a plane (`tests/data/planar_springs.xml`): a hinge about -y among
/// +y ones (reversed), a slide across the link before it (an offset), an anchored hinge.
#[derive(PlanarArm)]
#[arm(mjcf = "tests/data/planar_springs.xml")]
struct PlanarSprings;

/// MuJoCo puts the springs in `qfrc_passive`; here they are part of the potential, so
/// `gravity` and `bias` hold them: `bias = qfrc_bias - qfrc_passive` (damping included), and
/// the inverse dynamics is `mj_inverse`'s. The potential energy's derivative is the static
/// torque, springs and all (central differences).
fn springs_against_mujoco<A: Dynamics<3>>(arm: &A, names: [&str; 3], text: &str) -> f64 {
    let mut lines: Vec<(&str, Vec<f64>)> = Vec::new();
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let (key, rest) = line.split_once(' ').unwrap();
        if key == "joints" {
            assert_eq!(rest.split(' ').collect::<Vec<_>>(), names);
            continue;
        }
        lines.push((key, rest.split(' ').map(|x| x.parse().unwrap()).collect()));
    }
    assert_eq!(lines.len(), 21, "three states of seven lines");
    let mut worst = 0.0_f64;
    for state in lines.chunks(7) {
        let v = |k: usize| SVector::<f64, 3>::from_column_slice(&state[k].1);
        let (q, qd, qdd) = (v(0), v(1), v(2));
        let m = SMatrix::<f64, 3, 3>::from_row_slice(&state[3].1);
        let (bias, passive, tau) = (v(4), v(5), v(6));
        for (what, ours, theirs) in [
            (
                "M",
                arm.mass_matrix(&q).as_slice().to_vec(),
                m.as_slice().to_vec(),
            ),
            (
                "bias",
                arm.bias(&q, &qd).as_slice().to_vec(),
                (bias - passive).as_slice().to_vec(),
            ),
            (
                "tau",
                arm.inverse_dynamics(&q, &qd, &qdd).as_slice().to_vec(),
                tau.as_slice().to_vec(),
            ),
        ] {
            let d = relative(&ours, &theirs);
            assert!(
                d < 1e-12,
                "{what}: {d:e}\n ours {ours:?}\n theirs {theirs:?}"
            );
            worst = worst.max(d);
        }
        let h = 1e-6;
        for i in 0..3 {
            let step = SVector::<f64, 3>::from_fn(|k, _| if k == i { h } else { 0.0 });
            let dv =
                (arm.potential_energy(&(q + step)) - arm.potential_energy(&(q - step))) / (2.0 * h);
            let g = arm.gravity(&q)[i];
            assert!(
                (dv - g).abs() < 1e-6 * g.abs().max(1.0),
                "dV/dq{i} {dv} against g {g}"
            );
        }
    }
    worst
}

#[test]
fn joint_springs_match_mujoco() {
    let spatial = springs_against_mujoco(
        &Springs,
        Springs::JOINT_NAMES,
        include_str!("data/springs_peers.txt"),
    );
    let planar = springs_against_mujoco(
        &PlanarSprings,
        PlanarSprings::JOINT_NAMES,
        include_str!("data/planar_springs_peers.txt"),
    );
    assert_eq!(PlanarSprings::JOINT_NAMES, ["hinge1", "slide", "hinge2"]);
    eprintln!("springs against MuJoCo: spatial {spatial:e}, planar {planar:e}");
}
