//! The methods run through `__private::dispatch` (the derivatives of the dynamics, a spatial
//! arm's base regressor) give, bit for bit, what their bodies give called directly; and those
//! bodies are the right functions (the inverse dynamics' derivatives, one direction at a time and packed
//! four directions at a time, against the inverse dynamics in run-time jets, the forward
//! dynamics' `dqdd/dtau` against the mass matrix, the base regressor times the base parameters
//! against the inverse dynamics).
//!
//! In a `dev` build the dispatched method runs the one-direction body, so the bit-for-bit
//! comparison means something only in an optimised build on a processor with AVX2 and FMA,
//! where the public method runs the copy compiled for them, with the packed body in AVX2
//! registers and its multiply-adds fused (a spatial arm's forward derivatives: its reverse-mode
//! program, in the AVX-512 copy where the processor has AVX-512), and the test calls the packed
//! body in portable lanes, whose `mul_add` rounds once too: CI runs this file with `--release`.
//! The products by `-M^-1` of the reverse-mode program (spatial arms) and of the trait's default
//! (planar arms) are checked against the kernel's in value.

mod common;

#[path = "../examples/support/puma_arm.rs"]
mod puma_arm;

use common::Rng;
use planar_arm::nalgebra::{SMatrix, SVector};
use planar_arm::prelude::*;
use planar_arm::Jet;
use puma_arm::Puma560;

/// Three planar links: small enough that the derive emits the forward dynamics' derivatives
/// too.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct Three {
    #[arm(length = 0.5, mass = 1.5, com = (0.2, 0.03), armature = 0.05)]
    a: Revolute,
    #[arm(length = 0.4, mass = 1.1, damping = 0.15)]
    b: Revolute,
    #[arm(length = 0.3, mass = 0.6)]
    c: Revolute,
}

/// Seven joints (two groups of four lanes in the packed base regressor, one group of eight in
/// the forward derivatives' reverse-mode program), the Panda's modified DH frames with the fourth joint a
/// slide, full inertia tensors, armature, damping and friction on some joints and a payload:
/// the generated packed programs on what the PUMA does not have.
#[derive(SpatialArm, Default)]
#[arm(gravity = (0, 0, -9.81), tool(xyz = (0, 0, 0.107)), payload = 0.8,
      payload_com = (0.01, -0.02, 0.04), payload_inertia(xx = 3e-3, yy = 4e-3, zz = 2e-3, xz = 2e-4))]
struct SevenWithSlide {
    #[arm(mdh(d = 0.333), mass = 4.97, com = (0.0039, 0.0021, -0.0476),
          inertia(xx = 0.7, yy = 0.7, zz = 0.009, xy = -1e-4, yz = 0.02), armature = 0.1,
          damping = 0.3, frictionloss = 0.2)]
    j1: Revolute,
    #[arm(mdh(alpha = -pi/2), mass = 0.646, com = (-0.0031, -0.0287, 0.0034),
          inertia(xx = 0.008, yy = 0.028, zz = 0.025, xz = -0.004), damping = 0.2)]
    j2: Revolute,
    #[arm(mdh(alpha = pi/2, d = 0.316), mass = 3.228, com = (0.0275, 0.0392, -0.0665))]
    j3: Revolute,
    #[arm(mdh(a = 0.0825, alpha = pi/2), mass = 3.587, com = (-0.0532, 0.1044, 0.0274),
          armature = 0.3, frictionloss = 0.4)]
    j4: Prismatic,
    #[arm(mdh(a = -0.0825, alpha = -pi/2, d = 0.384), mass = 1.226, com = (-0.0118, 0.0414, -0.0384),
          inertia(xx = 0.036, yy = 0.037, zz = 0.002, xy = -0.001, xz = 0.002, yz = -0.001))]
    j5: Revolute,
    #[arm(mdh(alpha = pi/2), mass = 1.666, com = (0.0601, -0.0141, -0.0105))]
    j6: Revolute,
    #[arm(mdh(a = 0.088, alpha = pi/2), mass = 0.735, com = (0.0105, 0.0043, 0.0617),
          damping = 0.05)]
    j7: Revolute,
}

/// Whether the dispatched methods run the AVX2 copy, with the packed programs: an optimised
/// build on a processor with AVX2 and FMA (or a build for both).
fn avx2_copy() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        (cfg!(target_feature = "avx2") && cfg!(target_feature = "fma"))
            || (!cfg!(debug_assertions)
                && std::is_x86_feature_detected!("avx2")
                && std::is_x86_feature_detected!("fma"))
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

fn same_bits<const R: usize, const C: usize>(a: &SMatrix<f64, R, C>, b: &SMatrix<f64, R, C>) {
    for (x, y) in a.iter().zip(b.iter()) {
        assert_eq!(x.to_bits(), y.to_bits(), "{x} against {y}");
    }
}

fn close<const R: usize, const C: usize>(a: &SMatrix<f64, R, C>, b: &SMatrix<f64, R, C>) {
    let scale = 1.0 + b.amax();
    assert!((a - b).amax() <= 1e-12 * scale, "{a} against {b}");
}

/// The dispatched derivatives against their bodies (bits) and against jets and the mass matrix
/// (values).
fn check<A: Dynamics<N>, const N: usize>(arm: &A, rng: &mut Rng) {
    for _ in 0..20 {
        let (q, qd, qdd): (SVector<f64, N>, SVector<f64, N>, SVector<f64, N>) =
            (rng.vector(3.0), rng.vector(2.0), rng.vector(2.0));
        let (dq, dqd) = arm.inverse_dynamics_derivatives(&q, &qd, &qdd);
        // The body that runs one direction at a time, and the packed one in portable lanes.
        let (kq, kqd) = arm.__inverse_dynamics_derivatives_kernel(&q, &qd, &qdd);
        let (pq, pqd) = arm.__inverse_dynamics_derivatives_packed(
            planar_arm::__private::Portable,
            &q,
            &qd,
            &qdd,
        );
        if avx2_copy() {
            same_bits(&dq, &pq);
            same_bits(&dqd, &pqd);
        } else {
            same_bits(&dq, &kq);
            same_bits(&dqd, &kqd);
        }
        let (jq, jqd) = Jet::inverse_dynamics_derivatives(arm, &q, &qd, &qdd);
        for (a, b) in [(&kq, &jq), (&kqd, &jqd), (&pq, &jq), (&pqd, &jqd)] {
            close(a, b);
        }

        let tau = arm.inverse_dynamics(&q, &qd, &qdd);
        let fd = arm.forward_dynamics_derivatives(&q, &qd, &tau);
        // The body that multiplies the inverse derivatives by -M^-1, and the AVX2 copy's in
        // portable lanes (a spatial arm's: the inverse dynamics run backward from the rows of
        // -M^-1), which agree in value.
        let kfd = arm.__forward_dynamics_derivatives_kernel(&q, &qd, &tau);
        let pfd = arm.__forward_dynamics_derivatives_packed(
            planar_arm::__private::Portable,
            &q,
            &qd,
            &tau,
        );
        let bits = if avx2_copy() { &pfd } else { &kfd };
        same_bits(&fd.0, &bits.0);
        same_bits(&fd.1, &bits.1);
        same_bits(&fd.2, &bits.2);
        for (a, b) in [(&pfd.0, &kfd.0), (&pfd.1, &kfd.1), (&pfd.2, &kfd.2)] {
            close(a, b);
        }
        // `-M^-1` times the inverse derivatives at the accelerations that gave `tau`.
        let (aq, aqd) = arm.__forward_dynamics_derivatives_adjoint(
            planar_arm::__private::Portable,
            &q,
            &qd,
            &qdd,
            &kfd.2,
        );
        close(&aq, &kfd.0);
        close(&aqd, &kfd.1);
        // dqdd/dtau is M^-1.
        close(&(arm.mass_matrix(&q) * fd.2), &SMatrix::identity());
    }
}

/// The dispatched base regressor against its bodies (bits), the packed body against the
/// one-joint-at-a-time body (values), and both times the base parameters against the inverse
/// dynamics.
fn check_base_regressor<A, const N: usize, const P: usize, const B: usize>(arm: &A, rng: &mut Rng)
where
    A: Identification<N, P, B>,
{
    let base = arm.base_parameters();
    for _ in 0..20 {
        let (q, qd, qdd): (SVector<f64, N>, SVector<f64, N>, SVector<f64, N>) =
            (rng.vector(3.0), rng.vector(2.0), rng.vector(2.0));
        let tau = arm.inverse_dynamics(&q, &qd, &qdd);
        let yb = arm.base_regressor(&q, &qd, &qdd);
        let kernel = arm.__base_regressor_kernel(&q, &qd, &qdd);
        let packed = arm.__base_regressor_packed(planar_arm::__private::Portable, &q, &qd, &qdd);
        if avx2_copy() {
            same_bits(&yb, &packed);
        } else {
            same_bits(&yb, &kernel);
        }
        close(&packed, &kernel);
        close(&(kernel * base), &tau);
        close(&(packed * base), &tau);
    }
}

#[test]
fn puma_dispatched_methods_match_their_bodies() {
    check(&Puma560::default(), &mut Rng(11));
    check_base_regressor(&Puma560::default(), &mut Rng(13));
}

#[test]
fn seven_joints_with_a_slide_dispatched_methods_match_their_bodies() {
    check(&SevenWithSlide::default(), &mut Rng(15));
    check_base_regressor(&SevenWithSlide::default(), &mut Rng(14));
}

#[test]
fn planar_dispatched_methods_match_their_bodies() {
    check(&Three::default(), &mut Rng(12));
}
