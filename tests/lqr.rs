//! `lqr` and `dlqr` against hand solutions and their own equations written out here, on
//! random pairs, and on pairs they must refuse (`tests/lqr_arm.rs` has the arm).

mod common;

use common::riccati::{care_residual, dare_residual};
use common::Rng;
use planar_arm::nalgebra::Const;
use planar_arm::nalgebra::{
    Complex, Matrix1, Matrix2, Matrix3, Matrix4, SMatrix, Vector2, Vector3, Vector4,
};
use planar_arm::prelude::*;
use planar_arm::{dlqr, lqr, EigenSize};

/// `|a - b|` over the larger of `|b|` and 1, entrywise largest.
fn off<const R: usize, const C: usize>(a: &SMatrix<f64, R, C>, b: &SMatrix<f64, R, C>) -> f64 {
    (a - b).amax() / b.amax().max(1.0)
}

/// Sorted by real part, then imaginary, for comparison with a hand list; real parts within
/// 1e-9 count as equal, so that a conjugate pair sorts by its imaginary parts.
fn sorted(z: impl IntoIterator<Item = Complex<f64>>) -> Vec<Complex<f64>> {
    let mut z: Vec<_> = z.into_iter().collect();
    let key = |x: &Complex<f64>| (x.re * 1e9).round();
    z.sort_by(|a, b| key(a).total_cmp(&key(b)).then(a.im.total_cmp(&b.im)));
    z
}

#[test]
fn double_integrator_matches_the_textbook() {
    // xd = (v, u), cost x^2 + v^2 + u^2: by hand, the CARE's three scalar equations
    // 1 - p12^2 = 0, p11 - p12 p22 = 0, 2 p12 + 1 - p22^2 = 0 give p12 = 1, p22 = sqrt 3,
    // p11 = sqrt 3; K = B^T P = (1, sqrt 3), poles (-sqrt 3 +- i) / 2.
    let s3 = 3f64.sqrt();
    let a = Matrix2::new(0.0, 1.0, 0.0, 0.0);
    let b = Vector2::new(0.0, 1.0);
    let lqr = lqr(&a, &b, &Matrix2::identity(), &Matrix1::new(1.0)).unwrap();
    assert!(
        off(&lqr.cost_to_go, &Matrix2::new(s3, 1.0, 1.0, s3)) < 1e-14,
        "{}",
        lqr.cost_to_go
    );
    assert!(
        off(&lqr.gain, &SMatrix::<f64, 1, 2>::new(1.0, s3)) < 1e-14,
        "{}",
        lqr.gain
    );
    let poles = sorted(lqr.closed_loop_eigenvalues.iter().copied());
    let hand = [Complex::new(-s3 / 2.0, -0.5), Complex::new(-s3 / 2.0, 0.5)];
    for (z, h) in poles.iter().zip(hand) {
        assert!((z - h).norm() < 1e-14, "{z} vs {h}");
    }
    assert!(lqr.residual < 1e-15, "{}", lqr.residual);
    println!(
        "double integrator: {} doublings, residual {:.1e}",
        lqr.iterations, lqr.residual
    );
}

#[test]
fn scalar_equations_match_their_closed_forms() {
    // CARE 2 a p - b^2 p^2 / r + q = 0: p = r (a + sqrt(a^2 + b^2 q / r)) / b^2.
    // DARE p = q + a^2 p r / (r + b^2 p): b^2 p^2 + (r - q b^2 - a^2 r) p - q r = 0.
    for (a, b, q, r) in [
        (1.0_f64, 1.0_f64, 1.0_f64, 1.0_f64),
        (-2.0, 0.5, 3.0, 0.1),
        (0.3, 4.0, 0.0, 2.0),
        (5.0, 1e-2, 1e-3, 1e2),
        (-3.0, 1.0, 2.0, 1.0),
        (2.0, 1.0, 1.0, 1.0),
    ] {
        let m = |x: f64| Matrix1::new(x);
        if q > 0.0 || a < 0.0 {
            let p = r * (a + (a * a + b * b * q / r).sqrt()) / (b * b);
            let c = lqr(&m(a), &m(b), &m(q), &m(r)).unwrap();
            assert!(
                (c.cost_to_go[0] - p).abs() <= 1e-13 * p.max(1.0),
                "CARE {a} {b} {q} {r}: {} vs {p}",
                c.cost_to_go[0]
            );
            assert!((c.gain[0] - b * p / r).abs() <= 1e-13 * (b * p / r).max(1.0));
            let pole = -(a * a + b * b * q / r).sqrt();
            assert!((c.closed_loop_eigenvalues[0].re - pole).abs() <= 1e-13 * pole.abs());
        }
        if q > 0.0 || a.abs() < 1.0 {
            let linear = r - q * b * b - a * a * r;
            let p = (-linear + (linear * linear + 4.0 * b * b * q * r).sqrt()) / (2.0 * b * b);
            let d = dlqr(&m(a), &m(b), &m(q), &m(r)).unwrap();
            assert!(
                (d.cost_to_go[0] - p).abs() <= 1e-12 * p.max(1.0),
                "DARE {a} {b} {q} {r}: {} vs {p}",
                d.cost_to_go[0]
            );
            let k = a * b * p / (r + b * b * p);
            assert!((d.gain[0] - k).abs() <= 1e-12 * k.abs().max(1.0));
            assert!((d.closed_loop_eigenvalues[0].re - (a - b * k)).abs() < 1e-12);
        }
    }
}

#[test]
fn a_stable_mode_the_input_cannot_move_is_left_alone() {
    // Decoupled: the first state is stable and unreachable, so its cost is the geometric (or
    // exponential) sum of q x^2 along its own decay; the second is the scalar case.
    let one = Matrix1::new(1.0);
    let b = Vector2::new(0.0, 1.0);
    let d = dlqr(
        &Matrix2::new(0.5, 0.0, 0.0, 2.0),
        &b,
        &Matrix2::identity(),
        &one,
    )
    .unwrap();
    // sum 0.25^k = 4/3; x+ = 2x + u, unit weights: 2 + sqrt 5.
    let hand = Matrix2::new(4.0 / 3.0, 0.0, 0.0, 2.0 + 5f64.sqrt());
    assert!(off(&d.cost_to_go, &hand) < 1e-14, "{}", d.cost_to_go);
    let poles = sorted(d.closed_loop_eigenvalues.iter().copied());
    assert!((poles[0].re - (3.0 - 5f64.sqrt()) / 2.0).abs() < 1e-14);
    assert!((poles[1].re - 0.5).abs() < 1e-14);

    let c = lqr(
        &Matrix2::new(-1.0, 0.0, 0.0, 1.0),
        &b,
        &Matrix2::identity(),
        &one,
    )
    .unwrap();
    // integral e^{-2t} = 1/2; xd = x + u, unit weights: 1 + sqrt 2.
    let hand = Matrix2::new(0.5, 0.0, 0.0, 1.0 + 2f64.sqrt());
    assert!(off(&c.cost_to_go, &hand) < 1e-14, "{}", c.cost_to_go);
    let poles = sorted(c.closed_loop_eigenvalues.iter().copied());
    assert!((poles[0].re + 2f64.sqrt()).abs() < 1e-14 && (poles[1].re + 1.0).abs() < 1e-14);
}

/// A random pair of `S` states and `M` inputs, entries of size `scale`, and positive definite
/// weights.
#[allow(clippy::type_complexity)]
fn random<const S: usize, const M: usize>(
    rng: &mut Rng,
    scale: f64,
) -> (
    SMatrix<f64, S, S>,
    SMatrix<f64, S, M>,
    SMatrix<f64, S, S>,
    SMatrix<f64, M, M>,
) {
    let a = SMatrix::<f64, S, S>::from_fn(|_, _| rng.range(-scale, scale));
    let b = SMatrix::<f64, S, M>::from_fn(|_, _| rng.range(-1.0, 1.0));
    let c = SMatrix::<f64, S, S>::from_fn(|_, _| rng.range(-1.0, 1.0));
    let d = SMatrix::<f64, M, M>::from_fn(|_, _| rng.range(-1.0, 1.0));
    let q = c.transpose() * c + SMatrix::identity() * 0.1;
    let r = d.transpose() * d + SMatrix::identity() * 0.5;
    (a, b, q, r)
}

/// The residuals (as `care_residual`, `dare_residual` measure them) of the designs on random
/// pairs, each with `|P| / |Q|` (large for a nearly uncontrollable mode), and the most
/// doublings taken.
#[derive(Default)]
struct Seen {
    care: Vec<(f64, f64)>,
    dare: Vec<(f64, f64)>,
    most: usize,
}

/// Checks one continuous and one discrete design on each of `runs` random pairs against the
/// equations written out here.
fn check_random<const S: usize, const M: usize>(rng: &mut Rng, runs: usize, seen: &mut Seen)
where
    Const<S>: EigenSize<S>,
{
    for _ in 0..runs {
        // Up to a few unstable modes in either sense.
        let (a, b, q, r) = random::<S, M>(rng, 1.5);
        let c = lqr(&a, &b, &q, &r).unwrap();
        let p = c.cost_to_go;
        let res = care_residual(&a, &b, &q, &r, &p);
        assert!(res < 1e-9, "CARE residual {res:e}");
        // K = R^-1 B^T P to rounding in the product's terms (B^T P cancels when P is large).
        let r_inverse = r.try_inverse().unwrap();
        let k = r_inverse * b.transpose() * p;
        let terms = r_inverse.abs() * b.transpose().abs() * p.abs();
        assert!((c.gain - k).amax() < 1e-13 * terms.amax());
        // Re s < 0 exactly when the Cayley transform has |z| < 1.
        let ac = a - b * c.gain;
        let identity = SMatrix::<f64, S, S>::identity();
        let cayley = (identity - ac).try_inverse().unwrap() * (identity + ac);
        assert!(schur_stable(&cayley), "{ac}");
        assert!(p.cholesky().is_some(), "P is not positive definite");
        seen.care.push((res, p.amax() / q.amax()));

        let a = a * 0.8;
        let d = dlqr(&a, &b, &q, &r).unwrap();
        let p = d.cost_to_go;
        let res = dare_residual(&a, &b, &q, &r, &p);
        assert!(res < 1e-9, "DARE residual {res:e}");
        let inner = (r + b.transpose() * p * b).try_inverse().unwrap();
        let k = inner * b.transpose() * p * a;
        let terms = inner.abs() * b.transpose().abs() * p.abs() * a.abs();
        assert!((d.gain - k).amax() < 1e-13 * terms.amax());
        assert!(schur_stable(&(a - b * d.gain)));
        assert!(p.cholesky().is_some(), "P is not positive definite");
        seen.dare.push((res, p.amax() / q.amax()));
        seen.most = seen.most.max(c.iterations).max(d.iterations);
    }
}

/// Whether the powers of `m` die out (spectral radius below 1), by squaring it 16 times with
/// the scale kept apart, so that `m^65536` neither overflows nor underflows: written apart
/// from the eigenvalue solvers `lqr` and `dlqr` use.
fn schur_stable<const S: usize>(m: &SMatrix<f64, S, S>) -> bool {
    let mut power = *m;
    let mut log_scale = 0.0;
    for _ in 0..16 {
        let size = power.amax();
        power /= size;
        log_scale = 2.0 * (log_scale + size.ln());
        power = power * power;
    }
    // log |m^65536|, whose 65536-th root is within a few percent of the spectral radius.
    let log_norm = log_scale + power.amax().ln();
    log_norm.is_finite() && log_norm < 0.0
}

#[test]
fn random_pairs_satisfy_their_riccati_equations() {
    let mut rng = Rng(0x5eed_1a2b);
    let mut seen = Seen::default();
    check_random::<2, 1>(&mut rng, 200, &mut seen);
    check_random::<4, 2>(&mut rng, 200, &mut seen);
    check_random::<6, 1>(&mut rng, 100, &mut seen);
    check_random::<8, 3>(&mut rng, 100, &mut seen);
    check_random::<3, 4>(&mut rng, 100, &mut seen);
    for (name, all) in [("CARE", &mut seen.care), ("DARE", &mut seen.dare)] {
        all.sort_by(|x, y| x.0.total_cmp(&y.0));
        let (median, worst) = (all[all.len() / 2], all[all.len() - 1]);
        let conditioned = all
            .iter()
            .filter(|x| x.1 < 100.0)
            .fold(0.0_f64, |m, x| m.max(x.0));
        println!(
            "{name}: {} pairs, median residual {:.1e}, largest {:.1e} (|P| / |Q| = {:.0e} there), \
             largest where |P| / |Q| < 100: {conditioned:.1e}",
            all.len(),
            median.0,
            worst.0,
            worst.1
        );
        assert!(median.0 < 1e-14 && conditioned < 1e-12);
    }
    println!("at most {} doublings", seen.most);
    assert!(seen.most <= 20);
}

#[test]
fn an_unstable_mode_no_input_moves_is_an_error() {
    let one = Matrix1::new(1.0);
    let b = Vector2::new(0.0, 1.0);
    let unmoved = |e: ArmError, eigenvalue: [f64; 2], discrete: bool| match e {
        ArmError::NotStabilizable {
            eigenvalue: z,
            discrete: d,
            missed_by: "B",
            measure,
        } => {
            assert!((z[0] - eigenvalue[0]).abs() < 1e-12 && (z[1] - eigenvalue[1]).abs() < 1e-12);
            assert!(d == discrete && measure < 1e-12, "{measure:e}");
        }
        e => panic!("{e:?}"),
    };
    // Decoupled: the first state grows (z = 2, s = 1) and the input reaches only the second.
    let e = dlqr(
        &Matrix2::new(2.0, 0.0, 0.0, 0.5),
        &b,
        &Matrix2::identity(),
        &one,
    )
    .unwrap_err();
    unmoved(e.clone(), [2.0, 0.0], true);
    assert_eq!(
        e.to_string(),
        "no stabilising LQR gain: the mode at eigenvalue 2 (|z| = 2 >= 1) is not moved by any \
         input, so (A, B) is not stabilisable (PBH measure 0)"
    );
    let e = lqr(
        &Matrix2::new(1.0, 0.0, 0.0, -1.0),
        &b,
        &Matrix2::identity(),
        &one,
    )
    .unwrap_err();
    unmoved(e, [1.0, 0.0], false);
    // On the boundary: an integrator (z = 1, s = 0) the input does not reach.
    let e = dlqr(
        &Matrix2::new(1.0, 0.0, 0.0, 0.5),
        &b,
        &Matrix2::identity(),
        &one,
    )
    .unwrap_err();
    unmoved(e, [1.0, 0.0], true);
    let e = lqr(
        &Matrix2::new(0.0, 0.0, 0.0, -1.0),
        &b,
        &Matrix2::identity(),
        &one,
    )
    .unwrap_err();
    unmoved(e, [0.0, 0.0], false);

    // Disguised by a change of coordinates T (A' = T A T^-1, B' = T B): a growing rotation
    // (s = 0.5 +- 2i) that the input, which drives only a third, stable state, cannot reach.
    let a = Matrix3::new(0.5, 2.0, 0.0, -2.0, 0.5, 0.0, 0.0, 0.0, -3.0);
    let b = Vector3::new(0.0, 0.0, 1.0);
    let t = Matrix3::new(1.0, 0.3, -0.2, 0.5, 2.0, 0.1, -0.4, 0.6, 1.5);
    let t_inverse = t.try_inverse().unwrap();
    let e = lqr(&(t * a * t_inverse), &(t * b), &Matrix3::identity(), &one).unwrap_err();
    let ArmError::NotStabilizable {
        eigenvalue: [re, im],
        missed_by: "B",
        measure,
        ..
    } = e
    else {
        panic!("{e:?}")
    };
    assert!((re - 0.5).abs() < 1e-12 && (im.abs() - 2.0).abs() < 1e-12 && measure < 1e-12);
    assert!(
        e.to_string()
            .contains("eigenvalue 0.5 +- 2i (Re s = 0.5 >= 0)"),
        "{e}"
    );
    // The same rotation shrinking (s = -0.5 +- 2i) needs no input: it is fine.
    let a = Matrix3::new(-0.5, 2.0, 0.0, -2.0, -0.5, 0.0, 0.0, 0.0, 3.0);
    let ok = lqr(&(t * a * t_inverse), &(t * b), &Matrix3::identity(), &one).unwrap();
    let mut poles = sorted(ok.closed_loop_eigenvalues.iter().copied());
    poles.retain(|s| s.im != 0.0);
    assert!(poles
        .iter()
        .all(|s| (s.re + 0.5).abs() < 1e-12 && (s.im.abs() - 2.0).abs() < 1e-12));
}

#[test]
fn an_unstable_mode_the_cost_does_not_see_is_an_error() {
    // Both modes reachable, but Q weighs only the stable one: the optimal control would leave
    // the growing one (z = 2, s = 1) alone, and there is no stabilising solution to find.
    let b = Vector2::new(1.0, 1.0);
    let q = Matrix2::new(1.0, 0.0, 0.0, 0.0);
    let one = Matrix1::new(1.0);
    for (e, discrete, z) in [
        (
            dlqr(&Matrix2::new(0.5, 0.0, 0.0, 2.0), &b, &q, &one).unwrap_err(),
            true,
            2.0,
        ),
        (
            lqr(&Matrix2::new(-1.0, 0.0, 0.0, 1.0), &b, &q, &one).unwrap_err(),
            false,
            1.0,
        ),
    ] {
        let ArmError::NotStabilizable {
            eigenvalue,
            discrete: d,
            missed_by: "Q",
            measure,
        } = e
        else {
            panic!("{e:?}")
        };
        assert!(
            eigenvalue == [z, 0.0] && d == discrete && measure < 1e-12,
            "{e:?}"
        );
        assert!(e
            .to_string()
            .contains("is not weighed by Q, so (Q, A) is not detectable"));
    }
    // Weighing it through a cross term is enough.
    let q = Matrix2::new(1.0, 0.5, 0.5, 0.5);
    assert!(dlqr(&Matrix2::new(0.5, 0.0, 0.0, 2.0), &b, &q, &one).is_ok());
}

#[test]
fn bad_weights_and_nan_give_errors_not_panics() {
    // Two falling links and their torques, about the shape of a linearisation upright.
    #[rustfmt::skip]
    let a = Matrix4::new(
        0.0, 0.0, 1.0, 0.0,
        0.0, 0.0, 0.0, 1.0,
        20.0, -6.0, 0.0, 0.0,
        -25.0, 40.0, 0.0, 0.0,
    );
    let b = SMatrix::<f64, 4, 2>::new(0.0, 0.0, 0.0, 0.0, 1.2, -3.0, -3.0, 9.6);
    let q = Matrix4::identity();
    let r = Matrix2::identity();
    let mut nan = a;
    nan[(2, 1)] = f64::NAN;
    assert_eq!(
        lqr(&nan, &b, &q, &r),
        Err(ArmError::NonFinite { argument: "a" })
    );
    assert_eq!(
        dlqr(&a, &(b * f64::INFINITY), &q, &r),
        Err(ArmError::NonFinite { argument: "b" })
    );
    assert_eq!(
        lqr(&a, &b, &(q * f64::NAN), &r),
        Err(ArmError::NonFinite { argument: "q" })
    );
    assert_eq!(
        dlqr(&a, &b, &q, &(r * f64::NAN)),
        Err(ArmError::NonFinite { argument: "r" })
    );

    // R with eigenvalues 3 and -1; Q with eigenvalue -0.5; an asymmetric Q.
    let indefinite = Matrix2::new(1.0, 2.0, 2.0, 1.0);
    match lqr(&a, &b, &q, &indefinite) {
        Err(ArmError::OutOfRange { what, value, .. }) => {
            assert!(
                what.contains("of R") && (value + 1.0).abs() < 1e-12,
                "{what} {value}"
            );
        }
        other => panic!("{other:?}"),
    }
    let q_bad = Matrix4::from_diagonal(&Vector4::new(1.0, -0.5, 1.0, 1.0));
    match dlqr(&a, &b, &q_bad, &r) {
        Err(ArmError::OutOfRange { what, value, .. }) => {
            assert!(
                what.contains("of Q") && (value + 0.5).abs() < 1e-12,
                "{what} {value}"
            );
        }
        other => panic!("{other:?}"),
    }
    let mut skew = q;
    skew[(0, 1)] = 0.5;
    assert!(matches!(
        lqr(&a, &b, &skew, &r),
        Err(ArmError::OutOfRange { what, .. }) if what.contains("asymmetry")
    ));
    // R = 0: no cost on the input, no optimum.
    assert!(matches!(
        dlqr(&a, &b, &q, &Matrix2::zeros()),
        Err(ArmError::OutOfRange { value, .. }) if value == 0.0
    ));

    // Huge and tiny finite input: a result or an error, never a panic or a NaN in an Ok.
    for scale in [1e-300, 1e-150, 1e150, 1e300] {
        let results = [
            lqr(&(a * scale), &b, &q, &r),
            dlqr(&(a * scale), &b, &q, &r),
            lqr(&a, &(b * scale), &q, &(r * scale)),
            dlqr(&a, &b, &(q * scale), &r),
        ];
        let outcomes: Vec<String> = results
            .iter()
            .map(|result| match result {
                Ok(l) => format!("Ok (residual {:.0e})", l.residual),
                Err(e) => format!("Err({e})"),
            })
            .collect();
        println!("scale {scale:e}: {outcomes:?}");
        for l in results.into_iter().flatten() {
            let all = l.gain.iter().chain(l.cost_to_go.iter());
            assert!(all.copied().all(f64::is_finite) && l.residual < 1.5e-8);
        }
    }
}
