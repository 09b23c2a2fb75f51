//! The engine's spatial programs (what `#[derive(SpatialArm)]` renders as Rust), in both forms
//! it chooses between (the product of the joints' transformations and the expanded exact
//! formulas), against the numeric reference (`reference::spatial`, a product of 4x4 matrices
//! built at run time), for random arms of 1 to 7 joints in each convention: random slides,
//! lengths, twists and offsets that are multiples of pi/12 or any number of radians, URDF
//! origins and integer axes, centres of mass, gravity, a tool frame, and a length read at run
//! time.

use std::collections::HashMap;

use planar_arm::nalgebra::{
    Isometry3, Matrix3, Rotation3, SVector, Translation3, UnitQuaternion, Vector3,
};
use planar_arm::reference::spatial as reference;
use planar_arm::spatial::{JointGeometry, SpatialJoint, SpatialLink, SpatialModel};
use planar_arm::symbolic::methods::Method;
use planar_arm::symbolic::ring::{ratio, to_f64, Rational};
use planar_arm::symbolic::slp::{Input, Program};
use planar_arm::symbolic::spatial::{
    unit_axis, FixedAngle, SpatialArmSpec, SpatialBody, SpatialDerived, SpatialForm,
    SpatialGeometry, SpatialJointSpec,
};
use planar_arm::symbolic::{JointKind, Param, Poly};
use planar_arm::Joint;
use proptest::prelude::*;

/// An angle as drawn: `k pi / 12` or `k / 10` radians.
#[derive(Clone, Debug)]
enum Drawn {
    Pi(i64),
    Radians(i64),
}

impl Drawn {
    fn exact(&self) -> FixedAngle {
        match self {
            Self::Pi(k) => FixedAngle::pi(ratio(*k, 12)),
            Self::Radians(k) => FixedAngle {
                radians: ratio(*k, 10),
                pi_multiple: ratio(0, 1),
            },
        }
    }
    fn value(&self) -> f64 {
        self.exact().value()
    }
}

fn angle() -> impl Strategy<Value = Drawn> {
    prop_oneof![
        (-12i64..=12).prop_map(Drawn::Pi),
        (-31i64..=31).prop_map(Drawn::Radians)
    ]
}

/// A length `k / 8` metres.
fn length() -> impl Strategy<Value = i64> {
    -8i64..=8
}

#[derive(Clone, Debug)]
struct JointDraw {
    prismatic: bool,
    lengths: [i64; 3],
    angles: [Drawn; 3],
    axis: [i64; 3],
    mass: i64,
    com: [i64; 3],
    /// xx, yy, zz (hundredths, 1 to 8), then xy, xz, yz (hundredths, -2 to 2).
    inertia: [i64; 6],
    /// Armature, damping and frictionloss, in tenths.
    joint_terms: [i64; 3],
}

fn joint() -> impl Strategy<Value = JointDraw> {
    (
        proptest::bool::weighted(0.3),
        [length(), length(), length()],
        [angle(), angle(), angle()],
        [-2i64..=2, -2i64..=2, -2i64..=2],
        0i64..=8,
        [-4i64..=4, -4i64..=4, -4i64..=4],
        [
            1i64..=8,
            1i64..=8,
            1i64..=8,
            -2i64..=2,
            -2i64..=2,
            -2i64..=2,
        ],
        [0i64..=3, 0i64..=3, 0i64..=3],
    )
        .prop_filter("a non-zero axis", |j| j.3 != [0, 0, 0])
        .prop_map(
            |(prismatic, lengths, angles, axis, mass, com, inertia, joint_terms)| JointDraw {
                prismatic,
                lengths,
                angles,
                axis,
                mass,
                com,
                inertia,
                joint_terms,
            },
        )
}

#[derive(Clone, Debug)]
struct ArmDraw {
    convention: u8,
    joints: Vec<JointDraw>,
    gravity: [i64; 3],
    tool: ([i64; 3], [Drawn; 3]),
    /// The first joint's first length, read at run time (eighths of a metre).
    reach: i64,
    q: Vec<f64>,
    /// Seven joint rates, then seven accelerations.
    rates: Vec<f64>,
    /// A payload at the tool: its mass, centre and tensor as a joint's are drawn.
    payload: Option<JointDraw>,
}

fn arm() -> impl Strategy<Value = ArmDraw> {
    (
        0u8..3,
        proptest::collection::vec(joint(), 1..=7),
        [-10i64..=10, -10i64..=10, -10i64..=10],
        ([length(), length(), length()], [angle(), angle(), angle()]),
        -8i64..=8,
        proptest::collection::vec(-3.2f64..3.2, 7),
        proptest::collection::vec(-4.0f64..4.0, 14),
        proptest::option::weighted(0.5, joint()),
    )
        .prop_map(
            |(convention, joints, gravity, tool, reach, q, rates, payload)| ArmDraw {
                convention,
                joints,
                gravity,
                tool,
                reach,
                q,
                rates,
                payload,
            },
        )
}

fn eighths(k: i64) -> Rational {
    ratio(k, 8)
}

fn value(r: &Rational) -> f64 {
    to_f64(r).expect("a small rational")
}

fn spec(d: &ArmDraw) -> SpatialArmSpec {
    let constant = |k: i64| Poly::constant(eighths(k));
    let joints = d
        .joints
        .iter()
        .enumerate()
        .map(|(i, j)| {
            let [l0, l1, l2] = j.lengths;
            let first = if i == 0 {
                Poly::param(Param::new("reach"))
            } else {
                constant(l0)
            };
            let [a0, a1, a2] = j.angles.clone();
            let geometry = match d.convention {
                0 => SpatialGeometry::Dh {
                    a: first,
                    alpha: a0.exact(),
                    d: constant(l1),
                    theta: a1.exact(),
                },
                1 => SpatialGeometry::Mdh {
                    a: first,
                    alpha: a0.exact(),
                    d: constant(l1),
                    theta: a1.exact(),
                },
                _ => SpatialGeometry::Urdf {
                    xyz: [first, constant(l1), constant(l2)],
                    rpy: [a0.exact(), a1.exact(), a2.exact()],
                    axis: unit_axis(&j.axis.map(|k| ratio(k, 1))),
                },
            };
            SpatialJointSpec {
                geometry,
                kind: if j.prismatic {
                    JointKind::Prismatic
                } else {
                    JointKind::Revolute
                },
                mass: Poly::constant(ratio(j.mass, 4)),
                com: j.com.map(|k| Poly::constant(ratio(k, 10))),
                inertia: j.inertia.map(|k| Poly::constant(ratio(k, 100))),
                range: None,
                armature: Poly::constant(ratio(j.joint_terms[0], 10)),
                damping: Poly::constant(ratio(j.joint_terms[1], 10)),
                frictionloss: Poly::constant(ratio(j.joint_terms[2], 10)),
                // A spring wherever there is damping, relaxed off zero.
                stiffness: Poly::constant(ratio(j.joint_terms[1], 2)),
                springref: Poly::constant(ratio(j.joint_terms[0] - 1, 4)),
            }
        })
        .collect();
    SpatialArmSpec {
        joints,
        gravity: d.gravity.map(|k| Poly::constant(ratio(k, 1))),
        tool_xyz: d.tool.0.map(|k| Poly::constant(eighths(k))),
        tool_rpy: d.tool.1.clone().map(|a| a.exact()),
        payload: d.payload.as_ref().map(|p| SpatialBody {
            mass: Poly::constant(ratio(p.mass, 4)),
            com: p.com.map(|k| Poly::constant(ratio(k, 10))),
            inertia: p.inertia.map(|k| Poly::constant(ratio(k, 100))),
        }),
    }
}

fn model<const N: usize>(d: &ArmDraw) -> SpatialModel<N> {
    let joints = core::array::from_fn(|i| {
        let j = &d.joints[i];
        let len = |k: i64| value(&eighths(k));
        let first = len(if i == 0 { d.reach } else { j.lengths[0] });
        let [a0, a1, a2] = [
            j.angles[0].value(),
            j.angles[1].value(),
            j.angles[2].value(),
        ];
        let geometry = match d.convention {
            0 => JointGeometry::Dh {
                a: first,
                alpha: a0,
                d: len(j.lengths[1]),
                theta: a1,
            },
            1 => JointGeometry::Mdh {
                a: first,
                alpha: a0,
                d: len(j.lengths[1]),
                theta: a1,
            },
            _ => JointGeometry::Urdf {
                xyz: Vector3::new(first, len(j.lengths[1]), len(j.lengths[2])),
                rpy: Vector3::new(a0, a1, a2),
                axis: Vector3::from(j.axis.map(|k| k as f64)),
            },
        };
        let kind = if j.prismatic {
            Joint::Prismatic
        } else {
            Joint::Revolute
        };
        let [armature, damping, frictionloss] = j.joint_terms.map(|k| k as f64 / 10.0);
        SpatialJoint {
            armature,
            damping,
            frictionloss,
            stiffness: j.joint_terms[1] as f64 / 2.0,
            springref: (j.joint_terms[0] - 1) as f64 / 4.0,
            ..SpatialJoint::new(geometry, kind)
        }
    });
    let links = core::array::from_fn(|i| link(&d.joints[i]));
    let [r, p, y] = [
        d.tool.1[0].value(),
        d.tool.1[1].value(),
        d.tool.1[2].value(),
    ];
    SpatialModel {
        joints,
        links,
        gravity: Vector3::from(d.gravity.map(|k| k as f64)),
        tool: Isometry3::from_parts(
            Translation3::from(Vector3::from(d.tool.0.map(|k| k as f64 / 8.0))),
            UnitQuaternion::from_euler_angles(r, p, y),
        ),
        payload: d.payload.as_ref().map(link),
    }
}

/// A drawn body's mass properties.
fn link(j: &JointDraw) -> SpatialLink {
    SpatialLink {
        mass: j.mass as f64 / 4.0,
        com: Vector3::from(j.com.map(|k| k as f64 / 10.0)),
        inertia: {
            let [xx, yy, zz, xy, xz, yz] = j.inertia.map(|k| k as f64 / 100.0);
            Matrix3::new(xx, xy, xz, xy, yy, yz, xz, yz, zz)
        },
    }
}

/// A method's outputs by name, at `q`, with the run-time length set.
fn outputs(m: &Method, q: &[f64], reach: f64) -> HashMap<String, f64> {
    outputs_at(m, q, &[], &[], reach)
}

/// A method's outputs by name, at `(q, qd, qdd)`, with the run-time length set.
fn outputs_at(m: &Method, q: &[f64], qd: &[f64], qdd: &[f64], reach: f64) -> HashMap<String, f64> {
    let params = m.program.params().to_vec();
    let input = |i: Input| match i {
        Input::Q(k) => q[k],
        Input::Qd(k) => qd[k],
        Input::Qdd(k) => qdd[k],
        Input::Param(k) => {
            assert_eq!(params[k].name(), "reach");
            reach
        }
        other => panic!("a kinematic program reads {other:?}"),
    };
    let values = m.eval(&input);
    m.outputs
        .iter()
        .map(|(name, _)| name.clone())
        .zip(values)
        .collect()
}

fn frame(out: &HashMap<String, f64>, prefix: &str) -> Isometry3<f64> {
    let at = |name: String| out[&format!("{prefix}{name}")];
    let r = Matrix3::from_fn(|i, j| at(format!("r{}{}", i + 1, j + 1)));
    let p = Vector3::from_fn(|i, _| at(format!("p{}", i + 1)));
    let rotation = Rotation3::from_matrix_unchecked(r);
    // A rotation matrix the program got wrong would not be orthonormal: check before
    // comparing as isometries.
    assert!(
        (r * r.transpose() - Matrix3::identity()).amax() < 1e-12,
        "{r}"
    );
    Isometry3::from_parts(
        Translation3::from(p),
        UnitQuaternion::from_rotation_matrix(&rotation),
    )
}

fn gap(a: &Isometry3<f64>, b: &Isometry3<f64>) -> f64 {
    let d = a.inverse() * b;
    d.translation.vector.norm().max(d.rotation.angle())
}

fn compare<const N: usize>(d: &ArmDraw, derived: &SpatialDerived) -> Result<(), TestCaseError> {
    let model: SpatialModel<N> = model(d);
    let q = SVector::<f64, N>::from_fn(|i, _| d.q[i]);
    let reach = value(&eighths(d.reach));
    let qs = q.as_slice();
    let tip = frame(&outputs(&derived.tip_pose, qs, reach), "");
    let expected = reference::tip_pose(&model, &q);
    prop_assert!(gap(&tip, &expected) < 1e-12, "tip {tip} vs {expected}");
    let links = outputs(&derived.link_poses, qs, reach);
    for (i, expected) in reference::link_poses(&model, &q).iter().enumerate() {
        let pose = frame(&links, &format!("l{}", i + 1));
        prop_assert!(
            gap(&pose, expected) < 1e-12,
            "link {i}: {pose} vs {expected}"
        );
    }
    let j = outputs(&derived.jacobian, qs, reach);
    let expected = reference::jacobian(&model, &q);
    for r in 0..6 {
        for c in 0..N {
            let got = j[&format!("j{}{}", r + 1, c + 1)];
            prop_assert!(
                (got - expected[(r, c)]).abs() < 1e-12,
                "J{r}{c}: {got} vs {expected}"
            );
        }
    }
    let g = outputs(&derived.gravity, qs, reach);
    let expected = reference::gravity(&model, &q);
    let scale = 1.0 + expected.amax();
    for i in 0..N {
        let got = g[&format!("g{}", i + 1)];
        prop_assert!(
            (got - expected[i]).abs() < 1e-12 * scale,
            "g{i}: {got} vs {expected}"
        );
    }
    let v = outputs(&derived.potential_energy, qs, reach)["v"];
    let expected = reference::potential_energy(&model, &q);
    prop_assert!(
        (v - expected).abs() < 1e-12 * (1.0 + expected.abs()),
        "V {v} vs {expected}"
    );
    let qd = SVector::<f64, N>::from_fn(|i, _| d.rates[i]);
    let qdd = SVector::<f64, N>::from_fn(|i, _| d.rates[7 + i]);
    let tau = outputs_at(
        &derived.inverse_dynamics,
        qs,
        qd.as_slice(),
        qdd.as_slice(),
        reach,
    );
    let expected = reference::inverse_dynamics(&model, &q, &qd, &qdd);
    let scale = 1.0 + expected.amax();
    for i in 0..N {
        let got = tau[&format!("t{}", i + 1)];
        prop_assert!(
            (got - expected[i]).abs() < 1e-12 * scale,
            "tau{i}: {got} vs {expected}"
        );
    }
    derivatives(derived, &model, (&q, &qd, &qdd), reach)?;
    let m = outputs(&derived.mass_matrix, qs, reach);
    let expected = reference::mass_matrix(&model, &q);
    let scale = 1.0 + expected.amax();
    for i in 0..N {
        for j in 0..N {
            let got = m[&format!("m{}{}", i + 1, j + 1)];
            prop_assert!(
                (got - expected[(i, j)]).abs() < 1e-12 * scale,
                "M{i}{j}: {got} vs {expected}"
            );
        }
    }
    // M and c multiplied out from the Lagrangian, where the engine expands them.
    if let Some(dynamics) = &derived.dynamics {
        let mut p = Program::new();
        let mut rows = Vec::new();
        for i in 0..N {
            for j in 0..N {
                rows.push((
                    format!("m{}{}", i + 1, j + 1),
                    p.expr(&dynamics.mass_matrix[i][j]),
                ));
            }
            rows.push((format!("c{}", i + 1), p.expr(&dynamics.coriolis[i])));
        }
        let method = Method {
            program: p,
            outputs: rows,
            evaluation: String::new(),
            packed: None,
        };
        let got = outputs_at(&method, qs, qd.as_slice(), &[], reach);
        let m = reference::mass_matrix(&model, &q);
        let c = reference::coriolis(&model, &q, &qd);
        let (scale_m, scale_c) = (1.0 + m.amax(), 1.0 + c.amax());
        for i in 0..N {
            for j in 0..N {
                let x = got[&format!("m{}{}", i + 1, j + 1)];
                prop_assert!(
                    (x - m[(i, j)]).abs() < 1e-12 * scale_m,
                    "expanded M{i}{j}: {x} vs {m}"
                );
            }
            let x = got[&format!("c{}", i + 1)];
            prop_assert!(
                (x - c[i]).abs() < 1e-12 * scale_c,
                "expanded c{i}: {x} vs {c}"
            );
        }
    }
    // C qd is c, and Mdot - 2C is skew (Mdot along qd by central differences of the
    // reference's M).
    let c = outputs_at(&derived.coriolis_matrix, qs, qd.as_slice(), &[], reach);
    let c = planar_arm::nalgebra::SMatrix::<f64, N, N>::from_fn(|i, j| {
        c[&format!("c{}{}", i + 1, j + 1)]
    });
    let expected = reference::coriolis(&model, &q, &qd);
    let scale = 1.0 + expected.amax();
    prop_assert!(
        (c * qd - expected).amax() < 1e-12 * scale,
        "C qd {} vs {expected}",
        c * qd
    );
    let h = 1e-6;
    let m_dot = (reference::mass_matrix(&model, &(q + qd * h))
        - reference::mass_matrix(&model, &(q - qd * h)))
        / (2.0 * h);
    let skew = m_dot - c * 2.0;
    let scale = 1.0 + m_dot.amax();
    prop_assert!(
        (skew + skew.transpose()).amax() < 1e-6 * scale,
        "Mdot - 2C not skew: {skew}"
    );
    Ok(())
}

/// `inverse_dynamics_derivatives`, one direction at a time and packed four directions at a
/// time, against central differences of the reference's inverse dynamics, and the two
/// programs against each other.
fn derivatives<const N: usize>(
    derived: &SpatialDerived,
    model: &SpatialModel<N>,
    (q, qd, qdd): (&SVector<f64, N>, &SVector<f64, N>, &SVector<f64, N>),
    reach: f64,
) -> Result<(), TestCaseError> {
    let Some(method) = &derived.inverse_dynamics_derivatives else {
        return Ok(());
    };
    let scalar = outputs_at(method, q.as_slice(), qd.as_slice(), qdd.as_slice(), reach);
    let packed = method.packed.as_ref().map(|pk| {
        let input = |i: Input| match i {
            Input::Q(k) => q[k],
            Input::Qd(k) => qd[k],
            Input::Qdd(k) => qdd[k],
            Input::Param(_) => reach,
            other => panic!("the derivatives read {other:?}"),
        };
        pk.eval(&input)
    });
    let h = 1e-6;
    let central = |dq: bool, j: usize| {
        let shifted = |delta: f64| {
            let (mut a, mut b) = (*q, *qd);
            if dq {
                a[j] += delta;
            } else {
                b[j] += delta;
            }
            reference::inverse_dynamics(model, &a, &b, qdd)
        };
        (shifted(h) - shifted(-h)) / (2.0 * h)
    };
    let scale = 1.0 + reference::inverse_dynamics(model, q, qd, qdd).amax();
    for (block, wrt) in ["q", "qd"].into_iter().enumerate() {
        for j in 0..N {
            let expected = central(block == 0, j);
            for i in 0..N {
                let name = format!("dtau{}_d{wrt}{}", i + 1, j + 1);
                let got = scalar[&name];
                prop_assert!(
                    (got - expected[i]).abs() < 1e-6 * scale,
                    "{name}: {got} vs central difference {}",
                    expected[i]
                );
                if let Some(packed) = &packed {
                    let k = block * N * N + i * N + j;
                    prop_assert!(
                        (packed[k] - got).abs() < 1e-12 * scale,
                        "{name}: packed {} vs {got}",
                        packed[k]
                    );
                }
            }
        }
    }
    Ok(())
}

fn check(d: &ArmDraw, derived: &SpatialDerived) -> Result<(), TestCaseError> {
    match d.joints.len() {
        1 => compare::<1>(d, derived),
        2 => compare::<2>(d, derived),
        3 => compare::<3>(d, derived),
        4 => compare::<4>(d, derived),
        5 => compare::<5>(d, derived),
        6 => compare::<6>(d, derived),
        7 => compare::<7>(d, derived),
        n => panic!("{n} joints"),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn both_forms_match_the_reference(d in arm()) {
        let s = spec(&d);
        check(&d, &SpatialDerived::in_form(&s, SpatialForm::Product))?;
        check(&d, &SpatialDerived::in_form(&s, SpatialForm::Expanded))?;
    }
}
