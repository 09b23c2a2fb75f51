//! The generated regressor and base parameters: `Y theta` and `Y_b theta_b` are the generated
//! inverse dynamics (itself checked against the numeric reference elsewhere) at random states,
//! for arms with run-time parameters, armature, damping, Coulomb friction and a payload; and a
//! change of the standard parameters that leaves every base parameter unchanged leaves the
//! torques unchanged.

mod common;

#[path = "common/arms.rs"]
mod arms;

use arms::Scara;
use common::Rng;

use planar_arm::nalgebra::{DMatrix, DVector, SVector};
use planar_arm::prelude::*;
use planar_arm::reference;

#[derive(PlanarArm, Default)]
#[arm(gravity = 0)]
struct Flat {
    #[arm(length = 3/4, mass = 3/2, inertia = 1/7, com = (1/5, 1/9))]
    a: Revolute,
    #[arm(length = 1, mass = 5/2, inertia = 1/8, com = (2/5, 0))]
    b: Revolute,
    #[arm(length = 5/4, mass = 7/2, inertia = 1/9, com = (3/5, -1/9), armature = 1/10)]
    c: Revolute,
}

#[derive(PlanarArm, Default)]
#[arm(gravity = 9.80665)]
struct Six {
    #[arm(length = 1/2, mass = 2)]
    a: Revolute,
    #[arm(length = 3/4, mass = 3/2, damping = 1/5)]
    b: Revolute,
    #[arm(length = 1, mass = 1, com = (1/3, 1/20))]
    c: Revolute,
    #[arm(length = 1/2, mass = 3/4, frictionloss = 1/4)]
    d: Revolute,
    #[arm(length = 3/4, mass = 1/2, armature = 1/50)]
    e: Revolute,
    #[arm(length = 1/2, mass = 1/4)]
    f: Revolute,
}

/// The longest arm that gets the impl (`identification::MAX_LINKS`): a 30-link chain.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct Thirty {
    #[arm(length = 2/4, mass = 1/2, inertia = 1/5, com = (1/5, -2/50))]
    l0: Revolute,
    #[arm(length = 3/4, mass = 2/2, inertia = 1/6, com = (2/5, -1/50))]
    l1: Revolute,
    #[arm(length = 4/4, mass = 3/2, inertia = 1/7, com = (3/5, 0/50))]
    l2: Revolute,
    #[arm(length = 2/4, mass = 4/2, inertia = 1/8, com = (1/5, 1/50))]
    l3: Revolute,
    #[arm(length = 3/4, mass = 1/2, inertia = 1/9, com = (2/5, 2/50))]
    l4: Revolute,
    #[arm(length = 4/4, mass = 2/2, inertia = 1/10, com = (3/5, -2/50))]
    l5: Revolute,
    #[arm(length = 2/4, mass = 3/2, inertia = 1/11, com = (1/5, -1/50))]
    l6: Revolute,
    #[arm(length = 3/4, mass = 4/2, inertia = 1/12, com = (2/5, 0/50))]
    l7: Revolute,
    #[arm(length = 4/4, mass = 1/2, inertia = 1/13, com = (3/5, 1/50))]
    l8: Revolute,
    #[arm(length = 2/4, mass = 2/2, inertia = 1/14, com = (1/5, 2/50))]
    l9: Revolute,
    #[arm(length = 3/4, mass = 3/2, inertia = 1/15, com = (2/5, -2/50))]
    l10: Revolute,
    #[arm(length = 4/4, mass = 4/2, inertia = 1/16, com = (3/5, -1/50))]
    l11: Revolute,
    #[arm(length = 2/4, mass = 1/2, inertia = 1/17, com = (1/5, 0/50))]
    l12: Revolute,
    #[arm(length = 3/4, mass = 2/2, inertia = 1/18, com = (2/5, 1/50))]
    l13: Revolute,
    #[arm(length = 4/4, mass = 3/2, inertia = 1/19, com = (3/5, 2/50))]
    l14: Revolute,
    #[arm(length = 2/4, mass = 4/2, inertia = 1/20, com = (1/5, -2/50))]
    l15: Revolute,
    #[arm(length = 3/4, mass = 1/2, inertia = 1/21, com = (2/5, -1/50))]
    l16: Revolute,
    #[arm(length = 4/4, mass = 2/2, inertia = 1/22, com = (3/5, 0/50))]
    l17: Revolute,
    #[arm(length = 2/4, mass = 3/2, inertia = 1/23, com = (1/5, 1/50))]
    l18: Revolute,
    #[arm(length = 3/4, mass = 4/2, inertia = 1/24, com = (2/5, 2/50))]
    l19: Revolute,
    #[arm(length = 4/4, mass = 1/2, inertia = 1/25, com = (3/5, -2/50))]
    l20: Revolute,
    #[arm(length = 2/4, mass = 2/2, inertia = 1/26, com = (1/5, -1/50))]
    l21: Revolute,
    #[arm(length = 3/4, mass = 3/2, inertia = 1/27, com = (2/5, 0/50))]
    l22: Revolute,
    #[arm(length = 4/4, mass = 4/2, inertia = 1/28, com = (3/5, 1/50))]
    l23: Revolute,
    #[arm(length = 2/4, mass = 1/2, inertia = 1/29, com = (1/5, 2/50))]
    l24: Revolute,
    #[arm(length = 3/4, mass = 2/2, inertia = 1/30, com = (2/5, -2/50))]
    l25: Revolute,
    #[arm(length = 4/4, mass = 3/2, inertia = 1/31, com = (3/5, -1/50))]
    l26: Revolute,
    #[arm(length = 2/4, mass = 4/2, inertia = 1/32, com = (1/5, 0/50))]
    l27: Revolute,
    #[arm(length = 3/4, mass = 1/2, inertia = 1/33, com = (2/5, 1/50))]
    l28: Revolute,
    #[arm(length = 4/4, mass = 2/2, inertia = 1/34, com = (3/5, 2/50))]
    l29: Revolute,
}

/// Run-time lengths: the groupings are polynomials in them.
#[derive(PlanarArm, Clone)]
#[arm(gravity = 9.81)]
struct Stretch {
    #[arm(length = self.l1, mass = 2, com = self.c1)]
    a: Revolute,
    #[arm(length = self.l2, mass = self.m2, armature = 0.01)]
    b: Revolute,
    #[arm(length = 0.3, mass = 0.5, damping = 0.05)]
    c: Revolute,
    l1: f64,
    l2: f64,
    c1: f64,
    m2: f64,
}

fn check<A, const N: usize, const P: usize, const B: usize>(arm: &A, rng: &mut Rng)
where
    A: Identification<N, P, B> + PlanarArm<N>,
{
    let (theta, base) = (arm.standard_parameters(), arm.base_parameters());
    for _ in 0..50 {
        let (q, qd, qdd) = (
            rng.vector::<N>(3.0),
            rng.vector::<N>(3.0),
            rng.vector::<N>(5.0),
        );
        let tau = arm.inverse_dynamics(&q, &qd, &qdd);
        let scale = 1.0 + tau.amax();
        let y = arm.regressor(&q, &qd, &qdd);
        assert!((y * theta - tau).amax() <= 1e-12 * scale, "Y theta");
        let yb = arm.base_regressor(&q, &qd, &qdd);
        assert!((yb * base - tau).amax() <= 1e-12 * scale, "Y_b theta_b");
        // Column by column against the numeric Newton-Euler regressor, which shares no code
        // with the derive.
        let numeric = reference::regressor(&arm.model(), &q, &qd, &qdd);
        for (k, name) in A::PARAMETERS.iter().enumerate() {
            let col = numeric.column(name).expect("a standard parameter's name");
            let d = (y.column(k) - col).amax();
            assert!(d <= 1e-12 * (1.0 + col.amax()), "column {name}: {d:e}");
        }
    }
    // The standard parameters' values, by name, from the numeric model.
    let model = arm.model();
    for (k, name) in A::PARAMETERS.iter().enumerate() {
        let (kind, index) =
            name.split_at(name.find(|c: char| c.is_ascii_digit() || c == 'p').unwrap());
        let value = match (kind, index) {
            (_, "p") => standard_block(&reference::payload_parameters(&model), kind),
            ("ia" | "fv" | "fc", _) => {
                let link = model.links[index.parse::<usize>().unwrap() - 1];
                match kind {
                    "ia" => link.armature,
                    "fv" => link.damping,
                    _ => link.frictionloss,
                }
            }
            _ => standard_block(
                &reference::link_parameters(&model.links[index.parse::<usize>().unwrap() - 1]),
                kind,
            ),
        };
        assert!(
            (theta[k] - value).abs() <= 1e-14 * (1.0 + value.abs()),
            "{name}"
        );
    }
    assert!(B <= P);
}

fn standard_block(block: &planar_arm::nalgebra::Vector4<f64>, kind: &str) -> f64 {
    block[["zz", "mx", "my", "m"]
        .iter()
        .position(|k| *k == kind)
        .expect("kind")]
}

#[test]
fn regressor_and_base_regressor_give_the_inverse_dynamics() {
    let mut rng = Rng(0x1d_e471_f1ca);
    for _ in 0..10 {
        let arm = Scara::random(&mut rng);
        check(&arm, &mut rng);
    }
    check(&Flat::default(), &mut rng);
    check(&Six::default(), &mut rng);
    check(&Thirty::default(), &mut rng);
    for _ in 0..5 {
        let arm = Stretch {
            a: Revolute,
            b: Revolute,
            c: Revolute,
            l1: rng.range(0.2, 1.0),
            l2: rng.range(0.2, 1.0),
            c1: rng.range(0.05, 0.3),
            m2: rng.range(0.5, 3.0),
        };
        check(&arm, &mut rng);
    }
}

/// The 30-link methods of the most `let`s compile in a `dev` build (the kinetic energy has
/// 6,600, the regressor 4,200; beyond about 3,000 in one block rustc overflowed its stack)
/// and agree: `T = 1/2 qd^T M qd` between the expanded energy and the recursion's M.
#[test]
fn thirty_links_compile_and_agree() {
    let arm = Thirty::default();
    let mut rng = Rng(0x0301_14e5);
    for _ in 0..10 {
        let (q, qd) = (rng.vector::<30>(3.0), rng.vector::<30>(2.0));
        let t = arm.kinetic_energy(&q, &qd);
        let quadratic = 0.5 * qd.dot(&(arm.mass_matrix(&q) * qd));
        assert!(
            (t - quadratic).abs() <= 1e-12 * quadratic.abs(),
            "{t} vs {quadratic}"
        );
    }
}

#[test]
fn run_time_lengths_group_as_polynomials() {
    // Gautier and Khalil's grouping with the lengths as symbols; link 3's literal length 0.3
    // groups nothing (no link beyond it), the armature of joint 2 and damping stand alone.
    assert_eq!(
        <Stretch as Identification<3, 14, 11>>::BASE_PARAMETERS,
        [
            "zz1 + l1^2 m2 + l1^2 m3",
            "mx1 + l1 m2 + l1 m3",
            "my1",
            "zz2 + l2^2 m3",
            "mx2 + l2 m3",
            "my2",
            "zz3",
            "mx3",
            "my3",
            "ia2",
            "fv3"
        ]
    );
    // The base parameters follow the lengths at run time: zz1 + l1^2 (m2 + m3), where link 1's
    // default inertia m l1^2 / 12 moves with l1 too.
    let mut arm = Stretch {
        a: Revolute,
        b: Revolute,
        c: Revolute,
        l1: 0.5,
        l2: 0.4,
        c1: 0.2,
        m2: 1.5,
    };
    let before = arm.base_parameters()[0];
    arm.l1 = 0.6;
    let after = arm.base_parameters()[0];
    assert!((after - before - (0.36 - 0.25) * (2.0 / 12.0 + 1.5 + 0.5)).abs() < 1e-12);
}

#[test]
fn parameter_lists_and_counts() {
    // Two links with payload, armature on joint 1, damping on 1, friction on 2:
    // 3 x 2 + 3 (payload) + 3 masses + ia1 + fv1 + fc2 = 15 standard parameters; base: zz, mx,
    // my per link (the payload and masses grouped, ia1 into zz1) plus fv1 and fc2 = 8.
    assert_eq!(
        <Scara as Identification<2, 15, 8>>::PARAMETERS,
        [
            "zz1", "mx1", "my1", "zz2", "mx2", "my2", "zzp", "mxp", "myp", "m1", "m2", "mp", "ia1",
            "fv1", "fc2"
        ]
    );
    // zz1 gathers l1^2 = 0.35^2 = 49/400 of each mass beyond link 1 and the armature.
    assert_eq!(
        <Scara as Identification<2, 15, 8>>::BASE_PARAMETERS[0],
        "zz1 + 49/400 m2 + 49/400 mp + ia1"
    );
    // No gravity: mx1 and my1 are not identifiable, ia1 joins zz1; ia3 is its own.
    assert_eq!(<Flat as Identification<3, 13, 8>>::BASE_PARAMETERS.len(), 8);
    // Six links with gravity: 18 + fv2 + fc4 + ia5 = 21.
    assert_eq!(
        <Six as Identification<6, 27, 21>>::BASE_PARAMETERS.len(),
        21
    );
}

#[test]
fn moving_along_a_grouping_leaves_the_torques_unchanged() {
    // m2 enters the base parameters only through zz1 + l1^2 m2 + ... and mx1 + l1 m2 + ...:
    // adding dm to m2 and subtracting l1^2 dm from zz1 and l1 dm from mx1 changes no base
    // parameter, so no torque. In standard parameters: theta + d.
    let arm = Six::default();
    let mut rng = Rng(5);
    let theta = arm.standard_parameters();
    let names = <Six as Identification<6, 27, 21>>::PARAMETERS;
    let at = |name: &str| names.iter().position(|n| *n == name).expect("name");
    let mut d = SVector::<f64, 27>::zeros();
    let (dm, l1) = (0.3, 0.5);
    d[at("m2")] = dm;
    d[at("zz1")] = -l1 * l1 * dm;
    d[at("mx1")] = -l1 * dm;
    for _ in 0..20 {
        let (q, qd, qdd) = (
            rng.vector::<6>(3.0),
            rng.vector::<6>(3.0),
            rng.vector::<6>(5.0),
        );
        let y = arm.regressor(&q, &qd, &qdd);
        let (a, b) = (y * theta, y * (theta + d));
        assert!((a - b).amax() <= 1e-12 * (1.0 + a.amax()));
        // And a change that moves a base parameter changes the torques.
        let mut e = SVector::<f64, 27>::zeros();
        e[at("zz1")] = 0.3;
        let c = y * (theta + e);
        assert!((a - c).amax() > 1e-6 || qdd[0].abs() < 1e-3);
    }
}

/// A model with random lengths, inertial parameters, 2-D centres of mass, armature, friction,
/// payload and gravity.
fn random_model<const N: usize>(rng: &mut Rng) -> planar_arm::Model<N> {
    let links = core::array::from_fn(|_| Link {
        length: rng.range(0.2, 1.5),
        mass: rng.range(0.1, 5.0),
        inertia: rng.range(0.0, 0.5),
        com: planar_arm::nalgebra::Vector2::new(rng.range(-0.5, 1.0), rng.range(-0.2, 0.2)),
        armature: rng.range(0.0, 0.1),
        damping: rng.range(0.0, 0.5),
        frictionloss: rng.range(0.0, 0.5),
        stiffness: 0.0,
        springref: 0.0,
        joint: planar_arm::Joint::Revolute,
        range: None,
        offset: 0.0,
        reversed: false,
    });
    let payload = Payload::point(rng.range(0.0, 2.0))
        .with_com(rng.range(-0.2, 0.2), rng.range(-0.2, 0.2))
        .with_inertia(rng.range(0.0, 0.05));
    planar_arm::Model {
        links,
        // Any direction: the regressor's gravity columns must not assume -y.
        gravity: planar_arm::nalgebra::Vector2::new(rng.range(-5.0, 5.0), rng.range(-10.0, 5.0)),
        payload,
    }
}

fn reference_regressor_matches<const N: usize>(rng: &mut Rng) {
    for _ in 0..20 {
        let model = random_model::<N>(rng);
        let (q, qd, qdd) = (
            rng.vector::<N>(3.0),
            rng.vector::<N>(3.0),
            rng.vector::<N>(5.0),
        );
        let tau = reference::inverse_dynamics(&model, &q, &qd, &qdd);
        let y = reference::regressor(&model, &q, &qd, &qdd);
        let d = (y.torques(&model) - tau).amax();
        assert!(d <= 1e-12 * (1.0 + tau.amax()), "N = {N}: {d:e}");
        // Pinocchio's algorithm (local frames, joint by joint) gives the same columns.
        let local = reference::regressor_local(&model, &q, &qd, &qdd);
        let blocks = |r: &reference::Regressor<N>| {
            r.links
                .iter()
                .chain([&r.payload])
                .map(|b| b.amax())
                .fold(0.0, f64::max)
        };
        let scale = 1.0 + blocks(&y);
        for (a, b) in y
            .links
            .iter()
            .chain([&y.payload])
            .zip(local.links.iter().chain([&local.payload]))
        {
            assert!((a - b).amax() <= 1e-12 * scale, "N = {N}: local frames");
        }
        assert_eq!(
            (y.armature, y.damping, y.coulomb),
            (local.armature, local.damping, local.coulomb)
        );
    }
}

#[test]
fn numeric_regressor_times_parameters_is_the_newton_euler_torque() {
    // The numeric regressor against the reference's own recursion (one pass that sums
    // wrenches inwards, the other per body and per joint), and against the same columns by
    // Pinocchio's algorithm, 1 to 8 links.
    let mut rng = Rng(0x5eed);
    reference_regressor_matches::<1>(&mut rng);
    reference_regressor_matches::<2>(&mut rng);
    reference_regressor_matches::<3>(&mut rng);
    reference_regressor_matches::<5>(&mut rng);
    reference_regressor_matches::<8>(&mut rng);
}

#[test]
fn column_names_outside_the_arm_are_none() {
    let model = random_model::<2>(&mut Rng(1));
    let z = SVector::<f64, 2>::zeros();
    let y = reference::regressor(&model, &z, &z, &z);
    for name in ["zz0", "zz3", "m01", "q1", "iap", "zz", "", "mz1"] {
        assert!(y.column(name).is_none(), "{name}");
    }
    assert!(y.column("myp").is_some() && y.column("fc2").is_some());
}

/// A standard normal deviate (Box-Muller).
fn normal(rng: &mut Rng) -> f64 {
    let (u, v) = (1.0 - rng.next(), rng.next());
    (-2.0 * u.ln()).sqrt() * (core::f64::consts::TAU * v).cos()
}

/// Least squares on `states` noisy torque samples (noise `sigma`) measured on `truth`, with the
/// base regressor of `model`: the estimate, its standard deviations from `sigma^2 (W^T W)^-1`,
/// and the stacked regressor's condition number.
fn identify<A, const N: usize, const P: usize, const B: usize>(
    model: &A,
    truth: &planar_arm::Model<N>,
    sigma: f64,
    states: usize,
    rng: &mut Rng,
) -> (DVector<f64>, DVector<f64>, f64)
where
    A: Identification<N, P, B> + PlanarArm<N>,
{
    let mut w = DMatrix::<f64>::zeros(states * N, B);
    let mut t = DVector::<f64>::zeros(states * N);
    for s in 0..states {
        let (q, qd, qdd) = (
            rng.vector::<N>(3.0),
            rng.vector::<N>(3.0),
            rng.vector::<N>(5.0),
        );
        let tau = reference::inverse_dynamics(truth, &q, &qd, &qdd);
        w.view_mut((s * N, 0), (N, B))
            .copy_from(&model.base_regressor(&q, &qd, &qdd));
        for i in 0..N {
            t[s * N + i] = tau[i] + sigma * normal(rng);
        }
    }
    let svd = w.clone().svd(true, true);
    let cond = svd.singular_values.max() / svd.singular_values.min();
    let estimate = svd.solve(&t, 0.0).expect("full column rank");
    let cov = (w.transpose() * &w)
        .try_inverse()
        .expect("full column rank")
        * (sigma * sigma);
    let std = cov.diagonal().map(f64::sqrt);
    (estimate, std, cond)
}

#[test]
fn noisy_torques_identify_the_base_parameters_within_the_noise() {
    // 400 random states of the six-link arm (21 base parameters, 2400 torque samples), torques
    // from the numeric reference plus Gaussian noise of 0.02 N m. Bound: every base parameter
    // within 4.5 of its standard deviations (a false alarm has probability about 21 x 7e-6 per
    // seed; the seed is fixed), and the mean squared normalised error near 1 (a chi-square with
    // 21 degrees of freedom divided by 21 lies in 0.3 ..= 2.2 with probability 0.998).
    let arm = Six::default();
    let mut rng = Rng(0x0001_de47);
    let sigma = 0.02;
    let truth = arm.base_parameters();
    let (estimate, std, cond) = identify(&arm, &arm.model(), sigma, 400, &mut rng);
    assert!(cond.is_finite() && cond > 1.0);
    let z: Vec<f64> = (0..21).map(|k| (estimate[k] - truth[k]) / std[k]).collect();
    for (k, zk) in z.iter().enumerate() {
        assert!(
            zk.abs() <= 4.5,
            "{}: {zk:.2} standard deviations",
            <Six as Identification<6, 27, 21>>::BASE_PARAMETERS[k]
        );
    }
    let chi2 = z.iter().map(|zk| zk * zk).sum::<f64>() / 21.0;
    assert!((0.3..=2.2).contains(&chi2), "chi2 / dof = {chi2}");
    // Noise-free, the same least squares recovers them to rounding.
    let (exact, _, _) = identify(&arm, &arm.model(), 0.0, 60, &mut rng);
    let d = (exact - DVector::from_column_slice(truth.as_slice())).amax();
    assert!(d <= 1e-9, "{d:e}");

    // Negative control: an unknown 50 g at the tip is seen, far outside the noise, in the last
    // link's base parameters.
    let mut loaded = arm.model();
    loaded.payload = Payload::point(0.05);
    let (estimate, std, _) = identify(&arm, &loaded, sigma, 400, &mut rng);
    let worst = (0..21)
        .map(|k| ((estimate[k] - truth[k]) / std[k]).abs())
        .fold(0.0, f64::max);
    assert!(worst > 20.0, "{worst}");
}
