//! Arms derived from model files against the engines that read the same files: MuJoCo for the
//! DeepMind control suite's MJCF models, Pinocchio for the UR5 and Panda URDFs. The fixture
//! `tests/data/models_peers.txt` is written by hand with `bench/models/fixtures.py` (CI
//! installs neither engine): each engine's mass matrix, bias forces, gravity torques and
//! inverse dynamics with damping at three random states, `q` in MuJoCo's `qpos` (URDF's joint
//! values), which the derive reads without conversion.

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

fn arm(name: &str) -> (Vec<String>, Lines) {
    let text = include_str!("data/models_peers.txt");
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

fn relative(a: &[f64], b: &[f64]) -> f64 {
    let scale = b.iter().fold(1e-3_f64, |m, x| m.max(x.abs()));
    a.iter()
        .zip(b)
        .fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()))
        / scale
}

/// Every state of the fixture to 1e-12 relative (of the quantity's largest entry); returns the
/// worst difference.
fn check<const N: usize, A: Dynamics<N>>(arm: &A, names: [&str; N], name: &str) -> f64 {
    let (joints, lines) = self::arm(name);
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
        let damping = v("damping", 6);
        let bias = v("bias", 4) + damping.component_mul(&qd);
        let pairs = [
            (
                "M",
                arm.mass_matrix(&q).as_slice().to_vec(),
                m.as_slice().to_vec(),
            ),
            (
                "bias",
                arm.bias(&q, &qd).as_slice().to_vec(),
                bias.as_slice().to_vec(),
            ),
            (
                "gravity",
                arm.gravity(&q).as_slice().to_vec(),
                v("gravity_torque", 5).as_slice().to_vec(),
            ),
            (
                "tau",
                arm.inverse_dynamics(&q, &qd, &qdd).as_slice().to_vec(),
                v("tau", 7).as_slice().to_vec(),
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
        check(&Acrobot, ["shoulder", "elbow"], "acrobot"),
        check(&CartPole, ["slider", "hinge_1"], "cartpole"),
        check(&Pendulum, ["hinge"], "pendulum"),
        check(&Reacher, ["shoulder", "wrist"], "reacher"),
        check(
            &Hopper,
            ["rootx", "rootz", "rooty", "waist", "hip", "knee", "ankle"],
            "hopper",
        ),
        check(
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
    let ur5 = check(&Ur5, Ur5::JOINT_NAMES, "ur5");
    let panda = check(&Panda, Panda::JOINT_NAMES, "panda");
    eprintln!("worst relative difference to Pinocchio: ur5 {ur5:e}, panda {panda:e}");
}
