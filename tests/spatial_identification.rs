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
