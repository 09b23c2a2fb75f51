//! The spatial regressor and base parameters (`Identification` of `#[derive(SpatialArm)]`)
//! against things derived without them: the reference's inverse dynamics and regressor
//! (`reference::spatial`, numeric, in base coordinates), the numeric rank of the regressor
//! stacked over random states, and the null space of that stack.

use planar_arm::nalgebra::{DMatrix, DVector, SMatrix, SVector};
use planar_arm::prelude::*;
use planar_arm::reference::spatial as reference;
use planar_arm::spatial::{SpatialArm, SpatialModel};

/// PUMA 560 (Corke's parameters) with armature, damping and Coulomb friction on the first
/// three joints and a payload at a tool frame 0.1 m out along the last axis.
#[derive(SpatialArm, Default)]
#[arm(gravity = (0, 0, -9.81), tool(xyz = (0, 0, 0.1)), payload = 1.5,
      payload_com = (0.01, 0.02, 0.05), payload_inertia(xx = 4e-3, yy = 5e-3, zz = 2e-3, xy = 1e-4))]
struct Puma {
    #[arm(dh(a = 0, alpha = pi/2, d = 0), inertia(yy = 0.35), armature = 0.2, damping = 0.5, frictionloss = 0.2)]
    waist: Revolute,
    #[arm(dh(a = 0.4318, alpha = 0, d = 0), mass = 17.4, com = (-0.3638, 0.006, 0.2275),
          inertia(xx = 0.13, yy = 0.524, zz = 0.539), armature = 0.2, damping = 0.5)]
    shoulder: Revolute,
    #[arm(dh(a = 0.0203, alpha = -pi/2, d = 0.15005), mass = 4.8, com = (-0.0203, -0.0141, 0.07),
          inertia(xx = 0.066, yy = 0.086, zz = 0.0125), armature = 0.1, frictionloss = 0.3)]
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
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        lo + (hi - lo) * ((self.0 >> 11) as f64 / (1u64 << 53) as f64)
    }
    fn vector<const N: usize>(&mut self, scale: f64) -> SVector<f64, N> {
        SVector::from_fn(|_, _| self.uniform(-scale, scale))
    }
}

/// The largest entry's magnitude, at least 1: relative errors of torques near zero.
fn size<const R: usize, const C: usize>(m: &SMatrix<f64, R, C>) -> f64 {
    m.amax().max(1.0)
}

#[test]
fn the_puma_regressors_give_its_inverse_dynamics() {
    let arm = Puma::default();
    let model = arm.model();
    let theta = arm.standard_parameters();
    let base = arm.base_parameters();
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let (mut y_gap, mut yb_gap, mut block_gap, mut payload_gap) =
        (0.0_f64, 0.0_f64, 0.0_f64, 0.0_f64);
    let without = SpatialModel {
        payload: None,
        ..model
    };
    for _ in 0..50 {
        let (q, qd, qdd) = (
            rng.vector::<6>(3.0),
            rng.vector::<6>(2.0),
            rng.vector::<6>(4.0),
        );
        let tau = reference::inverse_dynamics(&model, &q, &qd, &qdd);
        let y = arm.regressor(&q, &qd, &qdd);
        y_gap = y_gap.max((y * theta - tau).amax() / size(&tau));
        let yb = arm.base_regressor(&q, &qd, &qdd);
        yb_gap = yb_gap.max((yb * base - tau).amax() / size(&tau));
        // Each link's ten columns against the reference's regressor, built in base
        // coordinates from its own recursion.
        let blocks = reference::regressor(&model, &q, &qd, &qdd);
        for (i, block) in blocks.iter().enumerate() {
            let ours = y.fixed_columns::<10>(10 * i);
            block_gap = block_gap.max((ours - block).amax() / size(block));
        }
        // The payload's ten columns carry what the payload adds.
        let p = Puma::parameter_names().len();
        let carried = y.fixed_columns::<10>(p - 10) * theta.fixed_rows::<10>(p - 10);
        let added = tau - reference::inverse_dynamics(&without, &q, &qd, &qdd);
        payload_gap = payload_gap.max((carried - added).amax() / size(&added));
    }
    assert!(y_gap < 1e-12, "Y theta: {y_gap:e}");
    assert!(yb_gap < 1e-12, "Y_b theta_b: {yb_gap:e}");
    assert!(block_gap < 1e-12, "link blocks: {block_gap:e}");
    assert!(payload_gap < 1e-12, "payload columns: {payload_gap:e}");
    // The links' standard parameters are the reference's.
    let expected = reference::standard_parameters(&without);
    for (i, e) in expected.iter().enumerate() {
        let ours = theta.fixed_rows::<10>(10 * i);
        assert!((ours - e).amax() < 1e-12 * e.amax().max(1.0), "link {i}");
    }
}

/// The regressor stacked over `states` random states, and its singular values.
fn stacked<A: Identification<N, P, B>, const N: usize, const P: usize, const B: usize>(
    arm: &A,
    states: usize,
) -> DMatrix<f64> {
    let mut rng = Rng(0x2545_f491_4f6c_dd1d);
    let mut rows = DMatrix::<f64>::zeros(N * states, P);
    for s in 0..states {
        let (q, qd, qdd) = (
            rng.vector::<N>(3.0),
            rng.vector::<N>(2.0),
            rng.vector::<N>(4.0),
        );
        rows.view_mut((N * s, 0), (N, P))
            .copy_from(&arm.regressor(&q, &qd, &qdd));
    }
    rows
}

/// The numeric rank: singular values above `1e-9` of the largest.
fn rank(m: &DMatrix<f64>) -> usize {
    let sv = m.clone().svd(false, false).singular_values;
    let top = sv.max();
    sv.iter().filter(|s| **s > 1e-9 * top).count()
}

#[test]
fn the_puma_has_as_many_base_parameters_as_its_regressor_has_rank() {
    let arm = Puma::default();
    let names = Puma::base_parameter_names();
    let y = stacked(&arm, 40);
    assert_eq!(names.len(), rank(&y), "{names:#?}");
    println!(
        "{} standard, {} base parameters",
        Puma::parameter_names().len(),
        names.len()
    );
    for b in names {
        println!("  {b}");
    }
}

/// The groupings as a matrix `G` (`theta_b = G theta`), read from the formulas the derive
/// documents: `xx3 - 3001/10000 my3 + ia1`.
fn groupings(names: &[&str], formulas: &[&str]) -> DMatrix<f64> {
    let mut g = DMatrix::<f64>::zeros(formulas.len(), names.len());
    for (b, formula) in formulas.iter().enumerate() {
        let spaced = formula.replace(" - ", " + -");
        for term in spaced.split(" + ") {
            let (sign, term) = match term.strip_prefix('-') {
                Some(rest) => (-1.0, rest),
                None => (1.0, term),
            };
            let (coefficient, name) = match term.split_once(' ') {
                Some((c, name)) => {
                    let value = match c.split_once('/') {
                        Some((p, q)) => p.parse::<f64>().unwrap() / q.parse::<f64>().unwrap(),
                        None => c.parse::<f64>().unwrap(),
                    };
                    (value, name)
                }
                None => (1.0, term),
            };
            let k = names.iter().position(|n| *n == name).expect(name);
            g[(b, k)] += sign * coefficient;
        }
    }
    g
}

#[test]
fn a_change_in_the_null_space_leaves_every_base_parameter_unchanged() {
    let arm = Puma::default();
    let names = Puma::parameter_names();
    let g = groupings(names, Puma::base_parameter_names());
    // The derive's values are the documented combinations of the standard ones.
    let theta = DVector::from_column_slice(arm.standard_parameters().as_slice());
    let base = DVector::from_column_slice(arm.base_parameters().as_slice());
    assert!(
        (&g * &theta - &base).amax() < 1e-13,
        "{}",
        (&g * &theta - &base).amax()
    );
    // The null space of the stacked regressor, from its SVD: every direction in it changes
    // no torque, and (the groupings being exact) no base parameter.
    let y = stacked(&arm, 40);
    let svd = y.clone().svd(false, true);
    let v_t = svd.v_t.expect("V^T");
    let top = svd.singular_values.max();
    let mut directions = 0;
    let mut worst: f64 = 0.0;
    for (k, s) in svd.singular_values.iter().enumerate() {
        if *s > 1e-9 * top {
            continue;
        }
        let delta = v_t.row(k).transpose();
        assert!((&y * &delta).amax() < 1e-9 * top);
        worst = worst.max((&g * &delta).amax());
        directions += 1;
    }
    assert_eq!(directions + g.nrows(), names.len());
    assert!(
        worst < 1e-9,
        "a null direction moves a base parameter by {worst:e}"
    );
    // And the other way: the base regressor times G is the regressor.
    let mut rng = Rng(7);
    for _ in 0..10 {
        let (q, qd, qdd) = (
            rng.vector::<6>(3.0),
            rng.vector::<6>(2.0),
            rng.vector::<6>(4.0),
        );
        let yb =
            DMatrix::from_column_slice(6, g.nrows(), arm.base_regressor(&q, &qd, &qdd).as_slice());
        let full =
            DMatrix::from_column_slice(6, names.len(), arm.regressor(&q, &qd, &qdd).as_slice());
        assert!((yb * &g - &full).amax() < 1e-11 * full.amax().max(1.0));
    }
}

mod random_arms {
    //! The engine's identification on random arms of exact geometry (1 to 6 joints in each
    //! convention, slides, twists and URDF rotations by multiples of pi/2, axes of rational
    //! length, a payload at a turned tool frame, armature and friction on some joints): the
    //! number of base parameters is the numeric rank of the regressor stacked over random
    //! states, and `Y theta` and `Y_b theta_b` are the engine's inverse dynamics (which
    //! `spatial_engine_vs_reference.rs` checks against the reference). The regressors' packed
    //! programs, four joints per lane, give the same entries.

    use planar_arm::nalgebra::DMatrix;
    use planar_arm::symbolic::ring::{ratio, to_f64};
    use planar_arm::symbolic::slp::Input;
    use planar_arm::symbolic::spatial::{
        identification, packed_regressor, regressor, standard_values, unit_axis, FixedAngle,
        SpatialArmSpec, SpatialBody, SpatialDerived, SpatialGeometry, SpatialJointSpec,
    };
    use planar_arm::symbolic::{JointKind, Poly};
    use proptest::prelude::*;

    #[derive(Clone, Debug)]
    struct JointDraw {
        prismatic: bool,
        lengths: [i64; 3],
        turns: [i64; 3],
        axis: usize,
        mass: [i64; 10],
        terms: [bool; 3],
    }

    /// Axes whose length is rational.
    const AXES: [[i64; 3]; 6] = [
        [0, 0, 1],
        [1, 0, 0],
        [0, -1, 0],
        [1, 2, 2],
        [2, -3, 6],
        [0, 3, 4],
    ];

    fn joint() -> impl Strategy<Value = JointDraw> {
        (
            proptest::bool::weighted(0.3),
            [-8i64..=8, -8i64..=8, -8i64..=8],
            [0i64..4, 0i64..4, 0i64..4],
            0usize..6,
            [
                1i64..=9,
                -5i64..=5,
                -5i64..=5,
                -5i64..=5,
                1i64..=9,
                1i64..=9,
                1i64..=9,
                -2i64..=2,
                -2i64..=2,
                -2i64..=2,
            ],
            [any::<bool>(), any::<bool>(), any::<bool>()],
        )
            .prop_map(|(prismatic, lengths, turns, axis, mass, terms)| JointDraw {
                prismatic,
                lengths,
                turns,
                axis,
                mass,
                terms,
            })
    }

    fn turn(k: i64) -> FixedAngle {
        FixedAngle::pi(ratio(k, 2))
    }

    fn body(m: &[i64; 10]) -> SpatialBody {
        SpatialBody {
            mass: Poly::constant(ratio(m[0], 4)),
            com: [1, 2, 3].map(|k| Poly::constant(ratio(m[k], 10))),
            inertia: [4, 5, 6, 7, 8, 9].map(|k| Poly::constant(ratio(m[k], 100))),
        }
    }

    fn spec(
        convention: u8,
        joints: &[JointDraw],
        payload: Option<&JointDraw>,
        tool: ([i64; 3], [i64; 3]),
        gravity: [i64; 3],
    ) -> SpatialArmSpec {
        let eighths = |k: i64| Poly::constant(ratio(k, 8));
        let joints = joints
            .iter()
            .map(|j| {
                let [l0, l1, l2] = j.lengths;
                let [t0, t1, t2] = j.turns;
                let geometry = match convention {
                    0 => SpatialGeometry::Dh {
                        a: eighths(l0),
                        alpha: turn(t0),
                        d: eighths(l1),
                        theta: turn(t1),
                    },
                    1 => SpatialGeometry::Mdh {
                        a: eighths(l0),
                        alpha: turn(t0),
                        d: eighths(l1),
                        theta: turn(t1),
                    },
                    _ => SpatialGeometry::Urdf {
                        xyz: [eighths(l0), eighths(l1), eighths(l2)],
                        rpy: [turn(t0), turn(t1), turn(t2)],
                        axis: unit_axis(&AXES[j.axis].map(|k| ratio(k, 1))),
                    },
                };
                let b = body(&j.mass);
                let term = |on: bool, k: i64| Poly::constant(ratio(if on { k } else { 0 }, 10));
                SpatialJointSpec {
                    geometry,
                    kind: if j.prismatic {
                        JointKind::Prismatic
                    } else {
                        JointKind::Revolute
                    },
                    mass: b.mass,
                    com: b.com,
                    inertia: b.inertia,
                    range: None,
                    armature: term(j.terms[0], 3),
                    damping: term(j.terms[1], 5),
                    frictionloss: term(j.terms[2], 7),
                    // A spring's torque is linear in the angle itself: arms with springs get
                    // no Identification.
                    stiffness: Poly::default(),
                    springref: Poly::default(),
                }
            })
            .collect();
        SpatialArmSpec {
            joints,
            gravity: gravity.map(|k| Poly::constant(ratio(k, 1))),
            tool_xyz: tool.0.map(eighths),
            tool_rpy: tool.1.map(turn),
            payload: payload.map(|p| body(&p.mass)),
        }
    }

    fn value(p: &Poly) -> f64 {
        to_f64(&p.as_rational().expect("a number")).expect("small")
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]
        #[test]
        fn base_parameters_match_the_numeric_rank_and_reproduce_the_torques(
            convention in 0u8..3,
            joints in proptest::collection::vec(joint(), 1..=6),
            payload in proptest::option::weighted(0.5, joint()),
            tool in ([-4i64..=4, -4i64..=4, -4i64..=4], [0i64..4, 0i64..4, 0i64..4]),
            gravity in [-10i64..=10, -10i64..=10, -10i64..=10],
            states in proptest::collection::vec(-3.0f64..3.0, 30 * 18),
        ) {
            let arm = spec(convention, &joints, payload.as_ref(), tool, gravity);
            let n = arm.joints.len();
            let id = identification(&arm).expect("exact geometry");
            let p = id.parameters.len();
            let all: Vec<usize> = (0..p).collect();
            let y_method = regressor(&arm, &id.parameters, &all);
            let yb_method = regressor(&arm, &id.parameters, &id.base.columns);
            let y_packed = packed_regressor(&arm, &id.parameters, &all).expect("packed");
            let yb_packed =
                packed_regressor(&arm, &id.parameters, &id.base.columns).expect("packed");
            let tau_method = SpatialDerived::new(&arm).inverse_dynamics;
            let theta: Vec<f64> = standard_values(&arm, &id.parameters).iter().map(value).collect();
            let base: Vec<f64> = id
                .base
                .grouping
                .iter()
                .map(|g| g.iter().map(|(k, c)| theta[*k] * to_f64(c).unwrap()).sum())
                .collect();
            let b = base.len();
            let mut stacked = DMatrix::<f64>::zeros(30 * n, p);
            let mut worst: f64 = 0.0;
            for (s, x) in states.chunks(18).enumerate() {
                let input = |i: Input| match i {
                    Input::Q(j) => x[j],
                    Input::Qd(j) => x[6 + j],
                    Input::Qdd(j) => x[12 + j],
                    _ => f64::NAN,
                };
                let y = y_method.eval(&input);
                let yb = yb_method.eval(&input);
                let tau = tau_method.eval(&input);
                let scale = tau.iter().fold(1.0_f64, |m, t| m.max(t.abs()));
                // The packed programs (four joints per lane, what the AVX2 copy runs) give the
                // same entries to rounding.
                for (packed, values) in [(&y_packed, &y), (&yb_packed, &yb)] {
                    let packed = packed.eval(&input);
                    prop_assert_eq!(packed.len(), values.len());
                    for (k, (a, b)) in packed.iter().zip(values).enumerate() {
                        prop_assert!(
                            (a - b).abs() <= 1e-12 * (1.0 + b.abs()),
                            "entry {} (row-major): packed {} against {}", k, a, b
                        );
                    }
                }
                for i in 0..n {
                    let full: f64 = (0..p).map(|k| y[i * p + k] * theta[k]).sum();
                    let reduced: f64 = (0..b).map(|k| yb[i * b + k] * base[k]).sum();
                    worst = worst.max((full - tau[i]).abs() / scale).max((reduced - tau[i]).abs() / scale);
                    for k in 0..p {
                        stacked[(s * n + i, k)] = y[i * p + k];
                    }
                }
            }
            prop_assert!(worst < 1e-11, "Y theta or Y_b theta_b off by {worst:e}");
            let sv = stacked.svd(false, false).singular_values;
            let top = sv.max();
            let rank = sv.iter().filter(|s| **s > 1e-9 * top).count();
            prop_assert_eq!(b, rank);
        }
    }
}
