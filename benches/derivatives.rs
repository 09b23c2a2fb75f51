//! `inverse_dynamics_derivatives` and `forward_dynamics_derivatives` against central
//! differences of the generated inverse and forward dynamics (what a user without them would
//! write: two calls per column), for the random arms of the dynamics bench.
//!
//! Not run in CI. One run prints the table of docs/performance.md:
//!
//! ```text
//! CARGO_TARGET_DIR=/tmp/target_bench cargo bench --bench derivatives
//! ```
//!
//! Each speed-up is the median over 101 rounds of the two timed back to back
//! (`support/interleaved.rs`).

use std::hint::black_box;

use planar_arm::nalgebra::{SMatrix, SVector};
use planar_arm::prelude::*;

#[path = "support/interleaved.rs"]
mod interleaved;
use interleaved::interleaved;

#[path = "support/random_arms.rs"]
#[allow(dead_code)] // the one- and eight-link arms are the dynamics bench's
mod random_arms;
use random_arms::{Random2, Random3, Random4, Random6};

/// Central differences of `f` along each unit direction.
fn central<const N: usize>(
    f: impl Fn(&SVector<f64, N>) -> SVector<f64, N>,
    x: &SVector<f64, N>,
) -> SMatrix<f64, N, N> {
    let h = 1e-6;
    SMatrix::from_columns(&core::array::from_fn::<_, N, _>(|j| {
        let mut e = SVector::<f64, N>::zeros();
        e[j] = h;
        (f(&(x + e)) - f(&(x - e))) / (2.0 * h)
    }))
}

/// `(dtau/dq, dtau/dqd)`.
type Derivatives<const N: usize> = (SMatrix<f64, N, N>, SMatrix<f64, N, N>);

/// The forward dynamics' derivatives from the inverse dynamics' ones at `qdd = FD(q, qd, tau)`:
/// `-M^-1 dtau/dq`, `-M^-1 dtau/dqd` and `M^-1`, as the trait's default computes them (M and h
/// once, one fixed-size `L D L^T` factor for `qdd` and `M^-1`; `None` if that fails).
#[allow(clippy::type_complexity)]
fn through_inverse<A: PlanarArm<N>, const N: usize>(
    arm: &A,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    tau: &SVector<f64, N>,
    inverse: impl Fn(&A, &SVector<f64, N>, &SVector<f64, N>, &SVector<f64, N>) -> Derivatives<N>,
) -> Option<(SMatrix<f64, N, N>, SMatrix<f64, N, N>, SMatrix<f64, N, N>)> {
    let (m, h) = arm.mass_matrix_and_bias(black_box(q), black_box(qd));
    let factor = planar_arm::__private::Factor::new(&m)?;
    let qdd = factor.solve(&(black_box(tau) - h));
    let (dq, dqd) = inverse(arm, q, qd, &qdd);
    Some(factor.inverse_products(&dq, &dqd))
}

#[allow(clippy::cast_precision_loss)]
fn row<A: PlanarArm<N> + Default, const N: usize>() {
    let arm = A::default();
    let state = |phase: f64| {
        SVector::<f64, N>::from_fn(|j, _| ((j + 1) as f64).mul_add(0.37, phase).sin() * 2.0)
    };
    let (q, qd, qdd) = (state(0.1), state(1.3), state(2.9));
    let tau = arm.inverse_dynamics(&q, &qd, &qdd);
    let (id, id_ns) = interleaved(
        || {
            black_box(arm.inverse_dynamics_derivatives(
                black_box(&q),
                black_box(&qd),
                black_box(&qdd),
            ));
        },
        || {
            black_box(central(
                |x| arm.inverse_dynamics(x, &qd, &qdd),
                black_box(&q),
            ));
            black_box(central(
                |x| arm.inverse_dynamics(&q, x, &qdd),
                black_box(&qd),
            ));
        },
    );
    let (fd, fd_ns) = interleaved(
        || {
            black_box(arm.forward_dynamics_derivatives(
                black_box(&q),
                black_box(&qd),
                black_box(&tau),
            ));
        },
        || {
            black_box(central(
                |x| arm.forward_dynamics(x, &qd, &tau),
                black_box(&q),
            ));
            black_box(central(
                |x| arm.forward_dynamics(&q, x, &tau),
                black_box(&qd),
            ));
            black_box(central(
                |x| arm.forward_dynamics(&q, &qd, x),
                black_box(&tau),
            ));
        },
    );
    // The run-time route the emitted code replaced (and larger arms still take): the generated
    // inverse dynamics evaluated in jets, M^-1 by Cholesky.
    let (id_jet, _) = interleaved(
        || {
            black_box(arm.inverse_dynamics_derivatives(
                black_box(&q),
                black_box(&qd),
                black_box(&qdd),
            ));
        },
        || {
            black_box(planar_arm::Jet::inverse_dynamics_derivatives(
                &arm,
                black_box(&q),
                black_box(&qd),
                black_box(&qdd),
            ));
        },
    );
    let emitted = || {
        black_box(arm.forward_dynamics_derivatives(black_box(&q), black_box(&qd), black_box(&tau)));
    };
    let (fd_jet, _) = interleaved(emitted, || {
        black_box(through_inverse(&arm, &q, &qd, &tau, |a, q, qd, qdd| {
            planar_arm::Jet::inverse_dynamics_derivatives(a, q, qd, qdd)
        }));
    });
    // The trait's default, which arms without an emitted `forward_dynamics_derivatives` take:
    // the emitted inverse dynamics' derivatives at `qdd`.
    let (fd_default, _) = interleaved(emitted, || {
        black_box(through_inverse(&arm, &q, &qd, &tau, |a, q, qd, qdd| {
            a.inverse_dynamics_derivatives(q, qd, qdd)
        }));
    });
    println!(
        "| {N} | {id_ns:.0} | {:.0} | {id:.2}x | {id_jet:.2}x | {fd_ns:.0} | {:.0} | {fd:.2}x | {fd_jet:.2}x | {fd_default:.2}x |",
        id * id_ns,
        fd * fd_ns
    );
}

fn main() {
    println!("| N | ID derivatives ns | central differences ns | speed-up | over jets | FD derivatives ns | central differences ns | speed-up | over jets | over the default |");
    println!("|---|---|---|---|---|---|---|---|---|---|");
    row::<Random2, 2>();
    row::<Random3, 3>();
    row::<Random4, 4>();
    row::<Random6, 6>();
}
