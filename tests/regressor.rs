//! The engine's regressor and exact base parameters against independent numerics: the
//! number of base parameters is the numerical rank of the regressor stacked over many random
//! states (an SVD, not the elimination), and moving the standard parameters along the
//! numerical null space leaves every base parameter unchanged.

mod common;

use common::Rng;

use planar_arm::nalgebra::DMatrix;
use planar_arm::symbolic::regressor::{base_parameters, regressor};
use planar_arm::symbolic::ring::{ratio, to_f64};
use planar_arm::symbolic::{ArmSpec, JointKind, LinkSpec, PayloadSpec, Poly};

fn random_arm(rng: &mut Rng, n: usize, gravity: bool, extras: bool) -> ArmSpec<Poly> {
    #[allow(clippy::cast_possible_truncation)]
    let mut r = |lo: f64, hi: f64| {
        let k = (rng.range(lo, hi) * 20.0).round() as i64;
        Poly::constant(ratio(k.max(1), 20))
    };
    let zero = || Poly::constant(ratio(0, 1));
    let links = (0..n)
        .map(|_| LinkSpec {
            length: r(0.2, 1.5),
            mass: r(0.2, 3.0),
            inertia: r(0.05, 0.5),
            com: (r(0.05, 1.0), r(0.05, 0.3)),
            armature: if extras { r(0.05, 0.2) } else { zero() },
            damping: if extras { r(0.05, 1.0) } else { zero() },
            frictionloss: zero(),
            stiffness: Default::default(),
            springref: Default::default(),
            joint: JointKind::Revolute,
            range: None,
            offset: None,
            reversed: false,
        })
        .collect();
    ArmSpec {
        links,
        // Gravity tilted off -y: nothing may assume its direction.
        gravity: if gravity {
            (
                Poly::constant(ratio(3, 2)),
                Poly::constant(ratio(-981, 100)),
            )
        } else {
            (zero(), zero())
        },
        payload: extras.then(|| PayloadSpec {
            mass: r(0.1, 1.0),
            inertia: r(0.05, 0.1),
            com: (r(0.05, 0.2), r(0.05, 0.2)),
        }),
    }
}

fn singular_values(m: &DMatrix<f64>) -> Vec<f64> {
    m.clone()
        .svd(false, false)
        .singular_values
        .iter()
        .copied()
        .collect()
}

#[test]
fn base_parameter_count_is_the_numerical_rank() {
    let mut rng = Rng(0x5eed_1d3e);
    for n in 1..=8 {
        for (gravity, extras) in [(true, false), (false, false), (true, true)] {
            if n > 5 && extras {
                continue; // the symbolic columns of long arms with a payload take long unoptimised
            }
            let arm = random_arm(&mut rng, n, gravity, extras);
            let reg = regressor(&arm);
            let base = base_parameters(&reg).expect("rational columns");
            let columns = reg.rational_columns().expect("rational columns");
            let p = columns.len();
            let states = 4 * p / n + 8;
            let mut y = DMatrix::<f64>::zeros(states * n, p);
            for s in 0..states {
                let (q, qd, qdd) = (
                    rng.vector::<8>(3.0),
                    rng.vector::<8>(3.0),
                    rng.vector::<8>(3.0),
                );
                for (k, column) in columns.iter().enumerate() {
                    for (i, e) in column.iter().enumerate() {
                        y[(s * n + i, k)] = e.eval(q.as_slice(), qd.as_slice(), qdd.as_slice());
                    }
                }
            }
            // Column scaling keeps the rank decision about dependence, not units.
            let mut scales = vec![1.0; p];
            for (k, scale) in scales.iter_mut().enumerate() {
                let norm = y.column(k).norm();
                if norm > 0.0 {
                    y.column_mut(k).scale_mut(1.0 / norm);
                    *scale = norm;
                }
            }
            let sv = singular_values(&y);
            let top = sv.iter().copied().fold(0.0, f64::max);
            let rank = sv.iter().filter(|&&s| s > 1e-9 * top).count();
            assert_eq!(
                base.columns.len(),
                rank,
                "n = {n}, gravity {gravity}, extras {extras}: singular values {sv:?}"
            );
            // Null space of the scaled regressor Y D (D = diag(1 / column norms)): the
            // directions D v in standard parameters that change no torque. Each must change
            // no base parameter.
            let svd = y.clone().svd(false, true);
            let vt = svd.v_t.expect("V^T");
            let mut null = 0;
            for (row, &s) in vt.row_iter().zip(svd.singular_values.iter()) {
                if s > 1e-9 * top {
                    continue;
                }
                null += 1;
                for group in &base.grouping {
                    let change: f64 = group
                        .iter()
                        .map(|(k, c)| {
                            to_f64(c).unwrap_or(f64::NAN) * row[*k] / scales[*k].max(1e-300)
                        })
                        .sum();
                    assert!(
                        change.abs() < 1e-6,
                        "n = {n}: base parameter moved by {change}"
                    );
                }
            }
            // Every link's mass is grouped away, so there is always a null space to check.
            assert_eq!(null, p - rank);
            assert!(null >= n);
        }
    }
}
