//! The engine's straight-line programs (what the derive renders as Rust) against the numeric
//! reference (recursive Newton-Euler, composite rigid body, articulated body), for arms of 1
//! to 8 links with random rational parameters and random states.

use planar_arm::nalgebra::SVector;
use planar_arm::reference;
use planar_arm::symbolic::methods::{Derived, Method};
use planar_arm::symbolic::ring::{ratio, to_f64};
use planar_arm::symbolic::slp::Input;
use planar_arm::symbolic::{ArmSpec, LinkSpec};
use planar_arm::Link;
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
        (-2i64..=12, 1i64..=10),
    )
        .prop_filter("positive length and mass", |(l, m, _, _)| {
            l.0 > 0 && m.0 > 0
        })
        .prop_map(|(l, m, i, (c, cd))| {
            let length = ratio(l.0, l.1);
            LinkSpec {
                // com may lie past either end of the link (a counterweight)
                com: &length * ratio(c, cd * 10),
                length,
                mass: ratio(m.0, m.1),
                // keep the mass matrix positive definite even when com = 0
                inertia: ratio(i.0 + 1, i.1),
            }
        })
}

fn arm(max_links: usize) -> impl Strategy<Value = ArmSpec> {
    (
        proptest::collection::vec(link(), 1..=max_links),
        0i64..=2000,
    )
        .prop_map(|(links, g)| ArmSpec {
            links,
            gravity: ratio(g, 100),
        })
}

fn numeric<const N: usize>(spec: &ArmSpec) -> ([Link; N], f64) {
    let f = |r| to_f64(r).expect("finite");
    let links = std::array::from_fn(|i| {
        let l = &spec.links[i];
        Link {
            length: f(&l.length),
            mass: f(&l.mass),
            inertia: f(&l.inertia),
            com: f(&l.com),
        }
    });
    (links, f(&spec.gravity))
}

struct State<const N: usize> {
    q: SVector<f64, N>,
    qd: SVector<f64, N>,
    qdd: SVector<f64, N>,
}

fn run(m: &Method, s: &[Vec<f64>; 4]) -> Vec<f64> {
    m.eval(&|i| match i {
        Input::Q(j) => s[0][j],
        Input::Qd(j) => s[1][j],
        Input::Qdd(j) => s[2][j],
        Input::Tau(j) => s[3][j],
        Input::Force(_) | Input::TipTorque => f64::NAN,
    })
}

fn close(a: f64, b: f64, scale: f64) -> bool {
    (a - b).abs() <= 1e-9 * scale.max(1.0)
}

fn check<const N: usize>(spec: &ArmSpec, raw: &[f64]) -> Result<(), TestCaseError> {
    let (links, g) = numeric::<N>(spec);
    let st = State::<N> {
        q: SVector::from_fn(|i, _| raw[i]),
        qd: SVector::from_fn(|i, _| raw[N + i]),
        qdd: SVector::from_fn(|i, _| raw[2 * N + i]),
    };
    let tau_ref = reference::inverse_dynamics(&links, g, &st.q, &st.qd, &st.qdd);
    let state = [
        st.q.iter().copied().collect(),
        st.qd.iter().copied().collect(),
        st.qdd.iter().copied().collect(),
        tau_ref.iter().copied().collect(),
    ];
    let d = Derived::new(spec);
    let scale = tau_ref.amax() + reference::mass_matrix(&links, &st.q).amax();

    let tau = run(&d.inverse_dynamics_method(), &state);
    let m = run(&d.mass_matrix_method(), &state);
    let c = run(&d.coriolis_method(), &state);
    let gv = run(&d.gravity_method(), &state);
    let qdd = run(&d.forward_dynamics_method(), &state);
    let m_ref = reference::mass_matrix(&links, &st.q);
    let c_ref = reference::coriolis(&links, &st.q, &st.qd);
    let g_ref = reference::gravity_torques(&links, g, &st.q);
    let tau_batched = reference::inverse_dynamics_batched_trig(&links, g, &st.q, &st.qd, &st.qdd);
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
        let fd_ref = reference::forward_dynamics(&links, g, &st.q, &st.qd, &tau_ref);
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
    let t = run(&d.kinetic_energy_method(), &state)[0];
    let v = run(&d.potential_energy_method(), &state)[0];
    let t_ref = reference::kinetic_energy(&links, &st.q, &st.qd);
    let v_ref = reference::potential_energy(&links, g, &st.q);
    prop_assert!(close(t, t_ref, t_ref.abs()), "T: {t} vs {t_ref}");
    prop_assert!(close(v, v_ref, v_ref.abs()), "V: {v} vs {v_ref}");

    let jac = run(&d.jacobian_method(), &state);
    let j_ref = reference::jacobian(&links, &st.q);
    let tip = run(&d.tip_pose_method(), &state);
    let tip_ref = reference::tip_position(&links, &st.q);
    prop_assert!(close(tip[0], tip_ref.x, 10.0) && close(tip[1], tip_ref.y, 10.0));
    for r in 0..3 {
        for j in 0..N {
            prop_assert!(close(jac[r * N + j], j_ref[(r, j)], 10.0), "J[{r}][{j}]");
        }
    }
    Ok(())
}

fn dispatch(spec: &ArmSpec, raw: &[f64]) -> Result<(), TestCaseError> {
    match spec.links.len() {
        1 => check::<1>(spec, raw),
        2 => check::<2>(spec, raw),
        3 => check::<3>(spec, raw),
        4 => check::<4>(spec, raw),
        5 => check::<5>(spec, raw),
        6 => check::<6>(spec, raw),
        7 => check::<7>(spec, raw),
        8 => check::<8>(spec, raw),
        n => unreachable!("{n} links"),
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    #[test]
    fn programs_match_newton_euler(spec in arm(8), raw in proptest::collection::vec(-3.0f64..3.0, 24)) {
        dispatch(&spec, &raw)?;
    }
}
