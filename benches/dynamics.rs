//! Run-time cost of the generated dynamics against our numeric reference (RNEA, CRBA, ABA),
//! against the bare cost of one `sin_cos` per joint, and (with `--features bench-dynibo`)
//! against the `dynibo` crate loading the same arm from a URDF.
//!
//! Not run in CI. The table in docs/performance.md comes from one run of
//!
//! ```text
//! CARGO_TARGET_DIR=/tmp/target_bench cargo bench --bench dynamics --features bench-dynibo
//! python3 bench/table.py /tmp/target_bench/criterion
//! ```
//!
//! Before timing, every arm is checked: generated inverse dynamics, mass matrix and forward
//! dynamics against the reference and (with the feature) against dynibo, at random states.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion};
use planar_arm::nalgebra::{SMatrix, SVector};
use planar_arm::prelude::*;
use planar_arm::reference;

// dynibo fixes gravity at 9.80665 m/s^2 along its -z, so every benchmarked arm uses that value.

// The paper's equal links: uniform unit rods (inertia m l^2 / 12 about the centre).
macro_rules! equal_arm {
    ($name:ident, $($field:ident),+) => {
        #[derive(PlanarArm, Default, Debug)]
        #[arm(gravity = 9.80665)]
        struct $name {
            $(
                #[arm(length = 1, mass = 1)]
                $field: Revolute,
            )+
        }
    };
}

equal_arm!(Equal1, a);
equal_arm!(Equal2, a, b);
equal_arm!(Equal3, a, b, c);
equal_arm!(Equal4, a, b, c, d);
equal_arm!(Equal6, a, b, c, d, e, f);
equal_arm!(Equal8, a, b, c, d, e, f, g, h);

#[path = "support/random_arms.rs"]
mod random_arms;
use random_arms::{Random1, Random2, Random3, Random4, Random6, Random8};

/// A deterministic pseudo-random vector in `[-range, range]` (xorshift).
fn state<const N: usize>(seed: u64, range: f64) -> SVector<f64, N> {
    let mut s = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15).wrapping_add(1);
    SVector::from_fn(|_, _| {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        #[allow(clippy::cast_precision_loss)]
        let u = (s >> 11) as f64 / (1u64 << 53) as f64;
        (2.0 * u - 1.0) * range
    })
}

/// Largest entry-wise difference relative to the larger operand's max-norm (at least 1).
fn rel_err<const R: usize, const C: usize>(a: &SMatrix<f64, R, C>, b: &SMatrix<f64, R, C>) -> f64 {
    (a - b).amax() / a.amax().max(b.amax()).max(1.0)
}

/// The same arm loaded into dynibo from a URDF written for it.
#[cfg(feature = "bench-dynibo")]
mod dyn_arm {
    use planar_arm::Link;

    /// URDF of a planar arm: `continuous` joints about z, each link along its frame's x with
    /// the next joint at `(length, 0, 0)` and the centre of mass at `(com.x, com.y, 0)`. `ixx`
    /// and `iyy` only need to make a valid tensor; rotation about z sees `izz` alone.
    pub fn urdf(name: &str, links: &[Link]) -> String {
        let mut s =
            format!("<?xml version=\"1.0\"?>\n<robot name=\"{name}\">\n  <link name=\"base\"/>\n");
        for (i, l) in links.iter().enumerate() {
            let parent = if i == 0 {
                "base".to_string()
            } else {
                format!("link{i}")
            };
            let offset = if i == 0 { 0.0 } else { links[i - 1].length };
            let inertia = l.inertia.max(1e-9);
            s.push_str(&format!(
                "  <link name=\"link{k}\">\n    <inertial>\n      <origin xyz=\"{com_x:e} {com_y:e} 0\" rpy=\"0 0 0\"/>\n      \
                 <mass value=\"{mass:e}\"/>\n      <inertia ixx=\"{inertia:e}\" ixy=\"0\" ixz=\"0\" iyy=\"{inertia:e}\" iyz=\"0\" izz=\"{izz:e}\"/>\n    \
                 </inertial>\n  </link>\n  <joint name=\"joint{k}\" type=\"continuous\">\n    <parent link=\"{parent}\"/>\n    \
                 <child link=\"link{k}\"/>\n    <origin xyz=\"{offset:e} 0 0\" rpy=\"0 0 0\"/>\n    <axis xyz=\"0 0 1\"/>\n  </joint>\n",
                k = i + 1,
                com_x = l.com.x,
                com_y = l.com.y,
                mass = l.mass,
                izz = l.inertia,
            ));
        }
        s.push_str("</robot>\n");
        s
    }

    /// The robot, with its base turned so that dynibo's gravity (-z) is the arm's -y.
    pub fn robot(name: &str, links: &[Link]) -> dynibo::Robot {
        let path = std::env::temp_dir().join(format!("planar_arm_bench_{name}.urdf"));
        std::fs::write(&path, urdf(name, links)).expect("write URDF");
        let mut robot = dynibo::Robot::from_urdf(&path).expect("dynibo loads the URDF");
        assert_eq!(robot.generalized_count(), links.len());
        // Rotate +90 degrees about x: base y -> world z, so world gravity -z is base -y.
        let rotation = planar_arm::nalgebra::UnitQuaternion::from_axis_angle(
            &planar_arm::nalgebra::Vector3::x_axis(),
            std::f64::consts::FRAC_PI_2,
        );
        robot
            .set_base_frame(dynibo::Frame::from_parts(
                planar_arm::nalgebra::Translation3::identity(),
                rotation,
            ))
            .expect("valid base frame");
        robot
    }
}

/// Checks the generated code against the reference (and dynibo) at random states; returns the
/// largest relative differences `(vs reference, vs dynibo)` over inverse dynamics, mass matrix
/// and forward dynamics.
fn agreement<A: PlanarArm<N> + Default, const N: usize>(name: &str) -> (f64, f64) {
    let arm = A::default();
    let model = arm.model();
    let mut vs_ref = 0.0_f64;
    #[cfg(not(feature = "bench-dynibo"))]
    let vs_dyn = f64::NAN;
    #[cfg(feature = "bench-dynibo")]
    let (mut robot, mut vs_dyn) = {
        assert!(
            (model.gravity - 9.80665).abs() < 1e-15,
            "{name}: dynibo's gravity is fixed"
        );
        (dyn_arm::robot(name, &model.links), 0.0_f64)
    };
    for k in 0..100 {
        let q = state::<N>(3 * k + 1, 3.0);
        let qd = state::<N>(3 * k + 2, 2.0);
        let qdd = state::<N>(3 * k + 3, 2.0);
        let tau = arm.inverse_dynamics(&q, &qd, &qdd);
        let m = arm.mass_matrix(&q);
        let fd = arm.forward_dynamics(&q, &qd, &tau);
        vs_ref = vs_ref
            .max(rel_err(
                &tau,
                &reference::inverse_dynamics(&model, &q, &qd, &qdd),
            ))
            .max(rel_err(&m, &reference::mass_matrix(&model, &q)))
            .max(rel_err(
                &fd,
                &reference::forward_dynamics(&model, &q, &qd, &tau),
            ));
        #[cfg(feature = "bench-dynibo")]
        {
            let mut t = [0.0; N];
            robot
                .inverse_dynamics(q.as_slice(), qd.as_slice(), qdd.as_slice(), &[], &mut t)
                .expect("dynibo inverse dynamics");
            let mut mm = vec![0.0; N * N];
            robot
                .mass_matrix(q.as_slice(), &mut mm)
                .expect("dynibo mass matrix");
            let mut a = [0.0; N];
            robot
                .forward_dynamics(q.as_slice(), qd.as_slice(), tau.as_slice(), &[], &mut a)
                .expect("dynibo forward dynamics");
            vs_dyn = vs_dyn
                .max(rel_err(&tau, &SVector::from(t)))
                .max(rel_err(&m, &SMatrix::from_column_slice(&mm)))
                .max(rel_err(&fd, &SVector::from(a)));
        }
    }
    assert!(vs_ref < 1e-9, "{name}: generated vs reference {vs_ref:e}");
    assert!(
        vs_dyn.is_nan() || vs_dyn < 1e-9,
        "{name}: generated vs dynibo {vs_dyn:e}"
    );
    (vs_ref, vs_dyn)
}

/// One benchmark group per arm: the generated methods and what they are compared with.
fn bench_arm<A: PlanarArm<N> + Default, const N: usize>(c: &mut Criterion, set: &str) {
    let name = format!("{set}{N}");
    let (vs_ref, vs_dyn) = agreement::<A, N>(&name);
    eprintln!("agreement {name}: max relative difference vs reference {vs_ref:.1e}, vs dynibo {vs_dyn:.1e}");

    let arm = A::default();
    let model = arm.model();
    let q = state::<N>(101, 3.0);
    let qd = state::<N>(102, 2.0);
    let qdd = state::<N>(103, 2.0);
    let tau = arm.inverse_dynamics(&q, &qd, &qdd);

    let mut group = c.benchmark_group(format!("{set}/N{N}"));
    group.bench_function("generated/inverse_dynamics", |b| {
        b.iter(|| arm.inverse_dynamics(black_box(&q), black_box(&qd), black_box(&qdd)));
    });
    group.bench_function("generated/mass_matrix", |b| {
        b.iter(|| arm.mass_matrix(black_box(&q)));
    });
    group.bench_function("generated/coriolis+gravity", |b| {
        b.iter(|| {
            let q = black_box(&q);
            (arm.coriolis(q, black_box(&qd)), arm.gravity(q))
        });
    });
    group.bench_function("generated/forward_dynamics", |b| {
        b.iter(|| arm.forward_dynamics(black_box(&q), black_box(&qd), black_box(&tau)));
    });
    // The reference reads its parameters at run time, as a user's numeric code would.
    group.bench_function("reference/rnea", |b| {
        b.iter(|| {
            reference::inverse_dynamics(
                black_box(&model),
                black_box(&q),
                black_box(&qd),
                black_box(&qdd),
            )
        });
    });
    // The same recursion with the generated code's trigonometry: what the arithmetic gains.
    group.bench_function("reference/rnea_batched_trig", |b| {
        b.iter(|| {
            reference::inverse_dynamics_batched_trig(
                black_box(&model),
                black_box(&q),
                black_box(&qd),
                black_box(&qdd),
            )
        });
    });
    group.bench_function("reference/crba", |b| {
        b.iter(|| reference::mass_matrix(black_box(&model), black_box(&q)));
    });
    group.bench_function("reference/aba", |b| {
        b.iter(|| {
            reference::forward_dynamics(
                black_box(&model),
                black_box(&q),
                black_box(&qd),
                black_box(&tau),
            )
        });
    });
    // The floor: one sin_cos per joint, every result used.
    group.bench_function("floor/sin_cos", |b| {
        b.iter(|| {
            let q = black_box(&q);
            let out: [(f64, f64); N] = core::array::from_fn(|j| q[j].sin_cos());
            out
        });
    });
    // The same N pairs from the kernel the generated code calls, all angles in one call.
    group.bench_function("floor/trig_kernel", |b| {
        b.iter(|| planar_arm::trig::sin_cos(black_box(&q).data.0[0]));
    });
    #[cfg(feature = "bench-dynibo")]
    {
        // Storage reused across calls, as dynibo's docs advise.
        let mut robot = dyn_arm::robot(&name, &model.links);
        let mut out = vec![0.0; N];
        let mut mass = vec![0.0; N * N];
        let (q, qd, qdd, tau) = (
            q.as_slice().to_vec(),
            qd.as_slice().to_vec(),
            qdd.as_slice().to_vec(),
            tau.as_slice().to_vec(),
        );
        group.bench_function("dynibo/inverse_dynamics", |b| {
            b.iter(|| {
                robot
                    .inverse_dynamics(
                        black_box(&q),
                        black_box(&qd),
                        black_box(&qdd),
                        &[],
                        black_box(&mut out),
                    )
                    .expect("dynibo");
            });
        });
        group.bench_function("dynibo/mass_matrix", |b| {
            b.iter(|| {
                robot
                    .mass_matrix(black_box(&q), black_box(&mut mass))
                    .expect("dynibo");
            });
        });
        group.bench_function("dynibo/forward_dynamics", |b| {
            b.iter(|| {
                robot
                    .forward_dynamics(
                        black_box(&q),
                        black_box(&qd),
                        black_box(&tau),
                        &[],
                        black_box(&mut out),
                    )
                    .expect("dynibo");
            });
        });
    }
    group.finish();
}

fn dynamics(c: &mut Criterion) {
    bench_arm::<Equal1, 1>(c, "equal");
    bench_arm::<Equal2, 2>(c, "equal");
    bench_arm::<Equal3, 3>(c, "equal");
    bench_arm::<Equal4, 4>(c, "equal");
    bench_arm::<Equal6, 6>(c, "equal");
    bench_arm::<Equal8, 8>(c, "equal");
    bench_arm::<Random1, 1>(c, "random");
    bench_arm::<Random2, 2>(c, "random");
    bench_arm::<Random3, 3>(c, "random");
    bench_arm::<Random4, 4>(c, "random");
    bench_arm::<Random6, 6>(c, "random");
    bench_arm::<Random8, 8>(c, "random");
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_millis(1500))
        .sample_size(40);
    targets = dynamics
}
criterion_main!(benches);
