//! The engine's straight-line programs (what the derive renders as Rust) against the numeric
//! reference (recursive Newton-Euler, composite rigid body, articulated body), for arms of 1
//! to 8 links with random rational parameters, random joint kinds (about a third prismatic),
//! joint offsets (quarter turns, and angles with rational cosine and sine), reversed joints
//! and joint springs, gravity in any direction, and random states.

use planar_arm::nalgebra::{SVector, Vector2};
use planar_arm::reference;
use planar_arm::symbolic::frozen::freeze;
use planar_arm::symbolic::methods::{Derived, Method};
use planar_arm::symbolic::ring::{ratio, to_f64, Rational};
use planar_arm::symbolic::slp::{Emit, Input};
use planar_arm::symbolic::spatial::FixedAngle;
use planar_arm::symbolic::{ArmSpec, JointKind, LinkSpec, Offset, PayloadSpec, Poly};
use planar_arm::{Link, Model, Payload};
use proptest::prelude::*;

/// A random rational `p / q` in a range, as the exact value.
fn rational(lo: i64, hi: i64, den: i64) -> impl Strategy<Value = (i64, i64)> {
    (lo * den..=hi * den, Just(den)).prop_map(|(p, q)| (p, q))
}

fn link() -> impl Strategy<Value = LinkSpec> {
    (
        rational(1, 3, 8),  // length 1/8 .. 3
        rational(1, 5, 4),  // mass 1/4 .. 5
        rational(0, 1, 16), // inertia 0 .. 1
        (-2i64..=12, 1i64..=10, -3i64..=3),
        (0i64..=4, 0i64..=4, 0i64..=4), // armature, damping, frictionloss in tenths
        proptest::bool::weighted(0.35),
        (0usize..12, proptest::bool::weighted(0.3)),
        (-6i64..=6, -10i64..=10), // spring stiffness (none below 1), springref in tenths
    )
        .prop_filter("positive length and mass", |(l, m, _, _, _, _, _, _)| {
            l.0 > 0 && m.0 > 0
        })
        .prop_map(
            |(l, m, i, (c, cd, cy), (a, b, f), prismatic, (turn, reversed), (k, r))| {
                let length = ratio(l.0, l.1);
                LinkSpec {
                    // com may lie past either end of the link (a counterweight), and off its axis
                    com: (&length * ratio(c, cd * 10), ratio(cy, 10)),
                    length,
                    mass: ratio(m.0, m.1),
                    // keep the mass matrix positive definite even when com = 0
                    inertia: ratio(i.0 + 1, i.1),
                    armature: ratio(a, 10),
                    damping: ratio(b, 10),
                    frictionloss: ratio(f, 10),
                    stiffness: ratio(k.max(0), 1),
                    springref: ratio(r, 10),
                    joint: if prismatic {
                        JointKind::Prismatic
                    } else {
                        JointKind::Revolute
                    },
                    range: None,
                    offset: offset(turn),
                    reversed,
                }
            },
        )
}

/// No offset half the time, else a quarter turn or an angle whose cosine and sine are
/// rational (Pythagorean triples), either way round.
fn offset(k: usize) -> Option<Offset> {
    let (c, s, d): (i32, i32, i64) = match k {
        0..=5 => return None,
        6 => (0, 1, 1),
        7 => (-1, 0, 1),
        8 => (0, -1, 1),
        9 => (3, 4, 5),
        10 => (12, -5, 13),
        _ => (-8, 15, 17),
    };
    let radians = f64::from(s).atan2(f64::from(c));
    Some(Offset {
        angle: FixedAngle {
            radians: Rational::from_float(radians).expect("finite"),
            pi_multiple: ratio(0, 1),
        },
        cos: ratio(c.into(), d),
        sin: ratio(s.into(), d),
    })
}

fn arm(max_links: usize) -> impl Strategy<Value = ArmSpec> {
    (
        proptest::collection::vec(link(), 1..=max_links),
        (0i64..=2000, -500i64..=500),
        proptest::option::of((0i64..=20, 0i64..=5, -3i64..=3, -3i64..=3)),
    )
        .prop_map(|(links, (g, across), payload)| ArmSpec {
            links,
            gravity: (ratio(across, 100), ratio(-g, 100)),
            payload: payload.map(|(m, i, x, y)| PayloadSpec {
                mass: ratio(m, 10),
                inertia: ratio(i, 100),
                com: (ratio(x, 10), ratio(y, 10)),
            }),
        })
}

fn numeric<const N: usize>(spec: &ArmSpec) -> Model<N> {
    let f = |r: &Rational| to_f64(r).expect("finite");
    let pair = |c: &(Rational, Rational)| Vector2::new(f(&c.0), f(&c.1));
    let links = std::array::from_fn(|i| {
        let l = &spec.links[i];
        Link {
            length: f(&l.length),
            mass: f(&l.mass),
            inertia: f(&l.inertia),
            com: pair(&l.com),
            armature: f(&l.armature),
            damping: f(&l.damping),
            stiffness: f(&l.stiffness),
            springref: f(&l.springref),
            frictionloss: f(&l.frictionloss),
            joint: match l.joint {
                JointKind::Revolute => planar_arm::Joint::Revolute,
                JointKind::Prismatic => planar_arm::Joint::Prismatic,
            },
            range: None,
            offset: l.offset.as_ref().map_or(0.0, |o| o.angle.value()),
            reversed: l.reversed,
        }
    });
    let payload = spec.payload.as_ref().map_or(Payload::NONE, |p| Payload {
        mass: f(&p.mass),
        inertia: f(&p.inertia),
        com: pair(&p.com),
    });
    Model::new(links, 0.0)
        .with_gravity(pair(&spec.gravity))
        .with_payload(payload)
}

/// The same arm with every value a run-time parameter `v0, v1, ...`, and their values: the
/// programs then read parameters instead of folding constants.
fn parameterised(arm: &ArmSpec) -> (ArmSpec<Poly>, Vec<f64>) {
    let (spec, values) = arm.parameterised();
    (
        spec,
        values
            .iter()
            .map(|(_, r)| to_f64(r).expect("finite"))
            .collect(),
    )
}

struct State<const N: usize> {
    q: SVector<f64, N>,
    qd: SVector<f64, N>,
    qdd: SVector<f64, N>,
}

fn run(m: &Method, s: &[Vec<f64>; 4], params: &[f64]) -> Vec<f64> {
    run_frozen(m, s, params, &[])
}

/// As [`run`], with a frozen block's values for [`Input::Frozen`].
fn run_frozen(m: &Method, s: &[Vec<f64>; 4], params: &[f64], block: &[f64]) -> Vec<f64> {
    let names = m.program.params().to_vec();
    m.eval(&|i| match i {
        Input::Frozen(k) => block[k],
        Input::Q(j) => s[0][j],
        Input::Qd(j) => s[1][j],
        Input::Qdd(j) => s[2][j],
        Input::Tau(j) => s[3][j],
        Input::Force(_) | Input::TipTorque | Input::Virtual(_) => f64::NAN,
        Input::Param(k) => names[k].name()[1..]
            .parse::<usize>()
            .map_or(f64::NAN, |v| params[v]),
    })
}

fn close(a: f64, b: f64, scale: f64) -> bool {
    (a - b).abs() <= 1e-9 * scale.max(1.0)
}

fn check<const N: usize, C: Emit>(
    spec: &ArmSpec,
    d: &Derived<C>,
    params: &[f64],
    raw: &[f64],
) -> Result<(), TestCaseError> {
    let model = numeric::<N>(spec);
    let run = |m: &Method, s: &[Vec<f64>; 4]| run(m, s, params);
    let st = State::<N> {
        q: SVector::from_fn(|i, _| raw[i]),
        qd: SVector::from_fn(|i, _| raw[N + i]),
        qdd: SVector::from_fn(|i, _| raw[2 * N + i]),
    };
    let tau_ref = reference::inverse_dynamics(&model, &st.q, &st.qd, &st.qdd);
    let state = [
        st.q.iter().copied().collect(),
        st.qd.iter().copied().collect(),
        st.qdd.iter().copied().collect(),
        tau_ref.iter().copied().collect(),
    ];
    let scale = tau_ref.amax() + reference::mass_matrix(&model, &st.q).amax();

    let tau = run(&d.inverse_dynamics_method(), &state);
    let m = run(&d.mass_matrix_method(), &state);
    let c = run(&d.coriolis_method(), &state);
    let gv = run(&d.gravity_method(), &state);
    let qdd = run(&d.forward_dynamics_method(), &state);
    let m_ref = reference::mass_matrix(&model, &st.q);
    let c_ref = reference::coriolis(&model, &st.q, &st.qd);
    let g_ref = reference::gravity_torques(&model, &st.q);
    let tau_batched = reference::inverse_dynamics_batched_trig(&model, &st.q, &st.qd, &st.qdd);
    for i in 0..N {
        prop_assert!(
            close(tau_batched[i], tau_ref[i], scale),
            "batched-trig RNEA tau[{i}]: {} vs {}",
            tau_batched[i],
            tau_ref[i]
        );
        prop_assert!(
            close(tau[i], tau_ref[i], scale),
            "tau[{i}]: {} vs {}",
            tau[i],
            tau_ref[i]
        );
        prop_assert!(
            close(c[i], c_ref[i], scale),
            "c[{i}]: {} vs {}",
            c[i],
            c_ref[i]
        );
        prop_assert!(
            close(gv[i], g_ref[i], scale),
            "g[{i}]: {} vs {}",
            gv[i],
            g_ref[i]
        );
        // forward dynamics is conditioned by M: compare through the reference ABA
        let fd_ref = reference::forward_dynamics(&model, &st.q, &st.qd, &tau_ref);
        prop_assert!(
            close(qdd[i], fd_ref[i], st.qdd.amax() * 1e3),
            "qdd[{i}]: {} vs {} (expected {})",
            qdd[i],
            fd_ref[i],
            st.qdd[i]
        );
        for j in 0..N {
            prop_assert!(close(m[i * N + j], m_ref[(i, j)], scale), "M[{i}][{j}]");
        }
    }
    // Friction, the bias and M with the bias in one program.
    let f = run(&d.friction_method(), &state);
    let f_ref = reference::friction(&model, &st.qd);
    let h = run(&d.bias_method(), &state);
    let h_ref = reference::bias_forces(&model, &st.q, &st.qd);
    let mh = run(&d.mass_matrix_and_bias_method(), &state);
    for i in 0..N {
        prop_assert!(
            close(f[i], f_ref[i], scale),
            "f[{i}]: {} vs {}",
            f[i],
            f_ref[i]
        );
        prop_assert!(
            close(h[i], h_ref[i], scale),
            "h[{i}]: {} vs {}",
            h[i],
            h_ref[i]
        );
        prop_assert!(close(mh[N * N + i], h_ref[i], scale), "(M, h).h[{i}]");
        for j in 0..N {
            prop_assert!(
                close(mh[i * N + j], m_ref[(i, j)], scale),
                "(M, h).M[{i}][{j}]"
            );
        }
    }
    // Split at the parameter-only frontier, the hot methods still give the reference's numbers.
    let hot = [
        (d.mass_matrix_method(), m.clone()),
        (d.inverse_dynamics_method(), tau.clone()),
        (d.mass_matrix_and_bias_method(), mh.clone()),
        (d.bias_method(), h.clone()),
    ];
    let methods: Vec<Method> = hot.iter().map(|(m, _)| m.clone()).collect();
    if let Some(split) = freeze(&methods) {
        let block = run(&split.block, &state);
        for (s, (_, whole)) in split.methods.iter().zip(&hot) {
            let got = run_frozen(s, &state, params, &block);
            for (a, b) in got.iter().zip(whole) {
                prop_assert!(close(*a, *b, scale), "frozen {a} vs {b}");
            }
        }
    } else {
        prop_assert!(
            params.is_empty(),
            "a parameterised arm has parameter-only work"
        );
    }
    let t = run(&d.kinetic_energy_method(), &state)[0];
    let v = run(&d.potential_energy_method(), &state)[0];
    let t_ref = reference::kinetic_energy(&model, &st.q, &st.qd);
    let v_ref = reference::potential_energy(&model, &st.q);
    prop_assert!(close(t, t_ref, t_ref.abs()), "T: {t} vs {t_ref}");
    prop_assert!(close(v, v_ref, v_ref.abs()), "V: {v} vs {v_ref}");

    let jac = run(&d.jacobian_method(), &state);
    let j_ref = reference::jacobian(&model, &st.q);
    let tip = run(&d.tip_pose_method(), &state);
    let tip_ref = reference::tip_position(&model, &st.q);
    prop_assert!(close(tip[0], tip_ref.x, 10.0) && close(tip[1], tip_ref.y, 10.0));
    for r in 0..3 {
        for j in 0..N {
            prop_assert!(close(jac[r * N + j], j_ref[(r, j)], 10.0), "J[{r}][{j}]");
        }
    }
    Ok(())
}

fn dispatch<C: Emit>(
    spec: &ArmSpec,
    d: &Derived<C>,
    params: &[f64],
    raw: &[f64],
) -> Result<(), TestCaseError> {
    match spec.links.len() {
        1 => check::<1, C>(spec, d, params, raw),
        2 => check::<2, C>(spec, d, params, raw),
        3 => check::<3, C>(spec, d, params, raw),
        4 => check::<4, C>(spec, d, params, raw),
        5 => check::<5, C>(spec, d, params, raw),
        6 => check::<6, C>(spec, d, params, raw),
        7 => check::<7, C>(spec, d, params, raw),
        8 => check::<8, C>(spec, d, params, raw),
        n => unreachable!("{n} links"),
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    /// Literal arms: the derivation over the rationals, constants folded into the programs.
    #[test]
    fn programs_match_newton_euler(spec in arm(8), raw in proptest::collection::vec(-3.0f64..3.0, 24)) {
        dispatch(&spec, &Derived::new(&spec), &[], &raw)?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// The same arms with every value a run-time parameter: the derivation over polynomials
    /// in the parameters, the programs reading their values.
    #[test]
    fn parameterised_programs_match_newton_euler(spec in arm(8), raw in proptest::collection::vec(-3.0f64..3.0, 24)) {
        let (symbolic, values) = parameterised(&spec);
        dispatch(&spec, &Derived::new(&symbolic), &values, &raw)?;
    }
}
